#ifndef RODNET_TESTS_GROUP_COUNTS_H
#define RODNET_TESTS_GROUP_COUNTS_H

#include <geometry/rod_graph.h>

#include <algorithm>
#include <string>

namespace rodnet::testing
{
  /// How many beams of @p graph are in group @p group.
  inline unsigned int
  count_in(const RodGraph &graph, const std::string &group)
  {
    unsigned int n = 0;
    for (const RodGraph::Beam &beam : graph.beams)
      n += std::count(beam.groups.begin(), beam.groups.end(), group);
    return n;
  }
} // namespace rodnet::testing

#endif
