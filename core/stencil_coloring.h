#ifndef RODNET_CORE_STENCIL_COLORING_H
#define RODNET_CORE_STENCIL_COLORING_H

#include <core/element_family.h>

#include <vector>

namespace rodnet
{
  /**
   * The stencils of a family cut into blocks of consecutive stencils, and
   * the blocks in colors: no two blocks of one color share a DoF, so that
   * different threads can each take whole blocks of a color and add their
   * stencils' local contributions into the global matrix and vector at the
   * same time, without a lock. A thread works through a block in stencil
   * order, over neighbouring rows of the matrix, as the serial loop does:
   * coloring single stencils instead (every third hinge of a chain in one
   * color) made each color a pass over the whole matrix, and two threads
   * hardly faster than one on large rods (doc/performance.md).
   */
  struct StencilBlocks
  {
    /// Block b holds the stencils first[b], ..., first[b + 1] - 1.
    std::vector<unsigned int> first;
    /// The blocks of each color, in increasing order.
    std::vector<std::vector<unsigned int>> colors;

    /// Whether there are colors to run threads over.
    bool
    empty() const
    {
      return colors.empty();
    }
  };

  /**
   * Blocks of @p block_size consecutive stencils of @p family (the last
   * one shorter), colored greedily: each block, in order, takes the lowest
   * color that none of its DoFs has yet. A chain of hinges in blocks of
   * two or more stencils needs 2 colors, a network a few more. Returns no
   * color at all (serial assembly only) if more than 64 would be needed.
   */
  StencilBlocks
  color_stencil_blocks(const ElementFamily &family,
                       global_dof_index     n_dofs,
                       unsigned int         block_size);

  /// The block size for @p n_stencils stencils: 64 blocks, so that each
  /// thread gets several per color, of at least 8 stencils.
  unsigned int
  default_block_size(unsigned int n_stencils);
} // namespace rodnet

#endif
