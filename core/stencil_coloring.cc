#include <core/stencil_coloring.h>

#include <cstdint>

namespace rodnet
{
  std::vector<std::vector<unsigned int>>
  color_stencils(const ElementFamily &family, const global_dof_index n_dofs)
  {
    // Per DoF, a bit for every color that already touches it.
    std::vector<std::uint64_t>             used(n_dofs, 0);
    std::vector<std::vector<unsigned int>> colors;
    std::vector<global_dof_index>          dofs;
    for (unsigned int s = 0; s < family.n_stencils(); ++s)
      {
        dofs.clear();
        family.get_dofs(s, dofs);
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
        if (color >= colors.size())
          colors.resize(color + 1);
        colors[color].push_back(s);
      }
    return colors;
  }
} // namespace rodnet
