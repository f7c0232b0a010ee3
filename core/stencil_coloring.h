#ifndef RODNET_CORE_STENCIL_COLORING_H
#define RODNET_CORE_STENCIL_COLORING_H

#include <core/element_family.h>

#include <vector>

namespace rodnet
{
  /**
   * The stencils of @p family in colors: no two stencils of one color share
   * a DoF, so that their local contributions can be added into the global
   * matrix and vector at the same time, by different threads, without a
   * lock (deal.II's WorkStream over colored iterators). Greedy: each
   * stencil, in order, takes the lowest color that none of its DoFs has
   * yet; a chain of hinges needs 3 colors, a network a few more. Every
   * stencil is in exactly one color, in increasing order within it.
   * Returns no color at all (serial assembly only) if more than 64 would be
   * needed.
   */
  std::vector<std::vector<unsigned int>>
  color_stencils(const ElementFamily &family, global_dof_index n_dofs);
} // namespace rodnet

#endif
