#ifndef RODNET_IO_VERTEX_SELECTOR_H
#define RODNET_IO_VERTEX_SELECTOR_H

#include <core/rod_network.h>

#include <string>

namespace rodnet
{
  /**
   * Resolves a vertex named in a scene to a triangulation vertex. Syntax:
   * `[rod:]where`, where `rod` is a rod index (default 0) and `where` is
   * `start`, `end`, `mid` (the middle vertex), or a vertex index along the
   * rod, negative counting from the end (-1 = last); or `@name`, a vertex
   * the network named (junctions, network nodes). Throws
   * std::invalid_argument naming @p entry and the text for anything else.
   */
  unsigned int
  select_vertex(const RodNetwork  &network,
                const std::string &text,
                const std::string &entry);

  /// As select_vertex(), returning the rod index and whether @p text names
  /// its start (true) or end (false); anything else throws.
  std::pair<unsigned int, bool>
  select_rod_end(const RodNetwork  &network,
                 const std::string &text,
                 const std::string &entry);
} // namespace rodnet

#endif
