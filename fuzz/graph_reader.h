#ifndef RODNET_FUZZ_GRAPH_READER_H
#define RODNET_FUZZ_GRAPH_READER_H

#include <core/rod_network.h>
#include <geometry/rod_graph.h>

#include "fuzz_input.h"

namespace rodnet::fuzz
{
  /**
   * One input of a fuzz target of a network reader @p read (a path to a
   * RodGraph): the bytes as a file ending in @p extension, read, and for a
   * file that it accepts, build_rod_network(), which checks the graph's
   * geometry, as the scene does.
   */
  template <class Reader>
  void
  fuzz_graph_reader(const std::uint8_t *data,
                    const std::size_t   size,
                    const std::string  &extension,
                    const Reader       &read)
  {
    const InputFile file(data, size, extension);
    expect_accepted_or_refused([&] {
      const RodGraph graph = read(file.path());
      build_rod_network(graph, 2, "simple");
    });
  }
} // namespace rodnet::fuzz

#endif
