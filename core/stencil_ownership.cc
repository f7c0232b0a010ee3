#include <core/stencil_ownership.h>

#include <algorithm>

namespace rodnet
{
  std::vector<OwnedStencils>
  stencils_anchored(const std::vector<std::unique_ptr<ElementFamily>> &families,
                    const dealii::IndexSet &owned_dofs)
  {
    std::vector<OwnedStencils>    result(families.size());
    std::vector<global_dof_index> dofs;
    for (unsigned int f = 0; f < families.size(); ++f)
      for (unsigned int s = 0; s < families[f]->n_stencils(); ++s)
        {
          families[f]->get_dofs(s, dofs);
          if (!dofs.empty() && owned_dofs.is_element(dofs[0]))
            result[f].stencils.push_back(s);
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


  namespace
  {
    /// The anchor (first DoF) of every stencil of @p families with the
    /// stencil's cost (ElementFamily::relative_cost()), sorted by anchor.
    std::vector<std::pair<global_dof_index, double>>
    sorted_anchors(const std::vector<std::unique_ptr<ElementFamily>> &families)
    {
      std::vector<std::pair<global_dof_index, double>> anchors;
      std::vector<global_dof_index>                    dofs;
      for (const auto &family : families)
        for (unsigned int s = 0; s < family->n_stencils(); ++s)
          {
            family->get_dofs(s, dofs);
            if (!dofs.empty())
              anchors.emplace_back(dofs[0], family->relative_cost());
          }
      std::sort(anchors.begin(), anchors.end());
      return anchors;
    }
  } // namespace


  dealii::IndexSet
  balanced_share(const std::vector<std::unique_ptr<ElementFamily>> &families,
                 const dealii::types::global_dof_index              n_dofs,
                 const unsigned int                                 n_processes,
                 const unsigned int                                 rank)
  {
    const auto anchors = sorted_anchors(families);
    if (n_processes == 1 || anchors.empty() || n_dofs < n_processes)
      return contiguous_share(n_dofs, n_processes, rank);
    // Range p ends at the first anchor past (p + 1) / P of the total cost,
    // so that it anchors the stencils before it; each range one DoF long
    // at least, leaving one to each later range.
    double total = 0;
    for (const auto &anchor : anchors)
      total += anchor.second;
    std::vector<global_dof_index> ends(n_processes, n_dofs);
    global_dof_index              first  = 0;
    double                        summed = 0;
    std::size_t                   k      = 0;
    for (unsigned int p = 0; p + 1 < n_processes; ++p)
      {
        while (k < anchors.size() &&
               summed + anchors[k].second <= total * (p + 1) / n_processes)
          summed += anchors[k++].second;
        const global_dof_index cut =
          k < anchors.size() ? anchors[k].first : n_dofs;
        ends[p] = std::min<global_dof_index>(std::max(cut, first + 1),
                                             n_dofs - (n_processes - 1 - p));
        first   = ends[p];
      }
    dealii::IndexSet result(n_dofs);
    result.add_range(rank == 0 ? 0 : ends[rank - 1], ends[rank]);
    return result;
  }
} // namespace rodnet
