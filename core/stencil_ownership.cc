#include <core/stencil_ownership.h>

#include <algorithm>

namespace rodnet
{
  std::vector<OwnedStencils>
  stencils_coupling(const std::vector<std::unique_ptr<ElementFamily>> &families,
                    const dealii::IndexSet &owned_dofs)
  {
    std::vector<OwnedStencils>    result(families.size());
    std::vector<global_dof_index> dofs;
    for (unsigned int f = 0; f < families.size(); ++f)
      for (unsigned int s = 0; s < families[f]->n_stencils(); ++s)
        {
          families[f]->get_dofs(s, dofs);
          if (dofs.empty())
            continue;
          const bool couples_owned =
            std::any_of(dofs.begin(), dofs.end(), [&](const auto d) {
              return owned_dofs.is_element(d);
            });
          if (!couples_owned)
            continue;
          result[f].stencils.push_back(s);
          result[f].counts_energy.push_back(owned_dofs.is_element(dofs[0]));
        }
    return result;
  }


  dealii::IndexSet
  dofs_read_by(const std::vector<std::unique_ptr<ElementFamily>> &families,
               const std::vector<OwnedStencils>                  &stencils,
               const dealii::IndexSet                            &owned_dofs)
  {
    std::vector<global_dof_index> read;
    std::vector<global_dof_index> dofs;
    for (unsigned int f = 0; f < families.size(); ++f)
      for (const unsigned int s : stencils[f].stencils)
        {
          families[f]->get_dofs(s, dofs);
          read.insert(read.end(), dofs.begin(), dofs.end());
        }
    std::sort(read.begin(), read.end());
    read.erase(std::unique(read.begin(), read.end()), read.end());
    dealii::IndexSet result = owned_dofs;
    result.add_indices(read.begin(), read.end());
    result.compress();
    return result;
  }


  dealii::IndexSet
  contiguous_share(const dealii::types::global_dof_index n_dofs,
                   const unsigned int                    n_processes,
                   const unsigned int                    rank)
  {
    const auto start = [&](const unsigned int r) {
      return n_dofs * r / n_processes;
    };
    dealii::IndexSet result(n_dofs);
    result.add_range(start(rank), start(rank + 1));
    return result;
  }
} // namespace rodnet
