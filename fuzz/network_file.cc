// Fuzz target of the node/beam reader read_network_file().
#include <io/network_file.h>

#include "graph_reader.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  rodnet::fuzz::fuzz_graph_reader(data,
                                  size,
                                  ".net",
                                  rodnet::read_network_file);
  return 0;
}
