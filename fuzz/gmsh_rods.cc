// Fuzz target of the Gmsh rod reader: read_gmsh_rods() (deal.II's GridIn
// underneath), and for a mesh it accepts, the rods' network, which checks
// their segments.
#include <core/rod_network.h>
#include <io/gmsh_rods.h>

#include "fuzz_input.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  const rodnet::fuzz::InputFile file(data, size, ".msh");
  rodnet::fuzz::expect_accepted_or_refused([&] {
    rodnet::RodNetwork network;
    for (const rodnet::RodChain &rod : rodnet::read_gmsh_rods(file.path()))
      network.add_rod(rod.points,
                      rod.closed,
                      rodnet::Vector3(0, 1, 0),
                      "simple");
    network.create_triangulation();
  });
  return 0;
}
