// Fuzz target of the branched Gmsh reader read_gmsh_network().
#include <io/gmsh_network.h>

#include "graph_reader.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  rodnet::fuzz::fuzz_graph_reader(data,
                                  size,
                                  ".msh",
                                  [](const std::string &path) {
                                    return rodnet::read_gmsh_network(path);
                                  });
  return 0;
}
