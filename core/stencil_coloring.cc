#include <core/stencil_coloring.h>

#include <algorithm>
#include <cstdint>

namespace rodnet
{
  StencilBlocks
  color_stencil_blocks(const ElementFamily   &family,
                       const global_dof_index n_dofs,
                       const unsigned int     block_size)
  {
    // Per DoF, a bit for every color that already touches it.
    std::vector<std::uint64_t>    used(n_dofs, 0);
    StencilBlocks                 blocks;
    std::vector<global_dof_index> dofs, stencil_dofs;
    const unsigned int            n_stencils = family.n_stencils();
    for (unsigned int begin = 0; begin < n_stencils; begin += block_size)
      {
        const unsigned int end = std::min(n_stencils, begin + block_size);
        dofs.clear();
        for (unsigned int s = begin; s < end; ++s)
          {
            family.get_dofs(s, stencil_dofs);
            dofs.insert(dofs.end(), stencil_dofs.begin(), stencil_dofs.end());
          }
        std::uint64_t taken = 0;
        for (const global_dof_index d : dofs)
          taken |= used[d];
        if (~taken == 0)
          return {};
        unsigned int color = 0;
        while (taken & (std::uint64_t(1) << color))
          ++color;
        for (const global_dof_index d : dofs)
          used[d] |= std::uint64_t(1) << color;
        if (color >= blocks.colors.size())
          blocks.colors.resize(color + 1);
        blocks.colors[color].push_back(blocks.first.size());
        blocks.first.push_back(begin);
      }
    blocks.first.push_back(n_stencils);
    return blocks;
  }


  unsigned int
  default_block_size(const unsigned int n_stencils)
  {
    return std::max(8u, n_stencils / 64);
  }
} // namespace rodnet
