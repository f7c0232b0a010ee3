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


  namespace
  {
    /// Where the DoFs of the stencils of @p families lie: how many
    /// stencils a range of DoFs evaluates.
    struct StencilSpans
    {
      /// The smallest and the largest DoF of every stencil, each sorted.
      std::vector<global_dof_index> first;
      std::vector<global_dof_index> last;
      /// The gaps (a, b) between two consecutive DoFs of a stencil wider
      /// than @p min_gap: a junction stencil's positions and its
      /// quaternion, numbered after all positions. A range inside a gap
      /// does not evaluate the stencil.
      std::vector<std::pair<global_dof_index, global_dof_index>> gaps;

      StencilSpans(const std::vector<std::unique_ptr<ElementFamily>> &families,
                   const global_dof_index                             min_gap)
      {
        std::vector<global_dof_index> dofs;
        for (const auto &family : families)
          for (unsigned int s = 0; s < family->n_stencils(); ++s)
            {
              family->get_dofs(s, dofs);
              if (dofs.empty())
                continue;
              std::sort(dofs.begin(), dofs.end());
              first.push_back(dofs.front());
              last.push_back(dofs.back());
              for (std::size_t k = 1; k < dofs.size(); ++k)
                if (dofs[k] - dofs[k - 1] > min_gap)
                  gaps.emplace_back(dofs[k - 1], dofs[k]);
            }
        std::sort(first.begin(), first.end());
        std::sort(last.begin(), last.end());
      }

      /// The stencils a process owning [lo, hi) evaluates: those with a
      /// DoF in it, exactly where the range is wider than the gaps left
      /// out.
      std::size_t
      evaluated(const global_dof_index lo, const global_dof_index hi) const
      {
        const auto below = [](const std::vector<global_dof_index> &list,
                              const global_dof_index               value) {
          return std::size_t(std::lower_bound(list.begin(), list.end(), value) -
                             list.begin());
        };
        const std::size_t around =
          std::count_if(gaps.begin(), gaps.end(), [&](const auto &gap) {
            return gap.first < lo && gap.second >= hi;
          });
        return below(first, hi) - below(last, lo) - around;
      }
    };

    /// The ends of the ranges of @p n_processes processes over @p n_dofs
    /// DoFs, each taken as long as it evaluates at most @p most stencils
    /// (and at least one DoF, leaving one to each later process), the last
    /// range the rest.
    std::vector<global_dof_index>
    greedy_ends(const StencilSpans    &spans,
                const global_dof_index n_dofs,
                const unsigned int     n_processes,
                const std::size_t      most)
    {
      std::vector<global_dof_index> ends;
      global_dof_index              start = 0;
      for (unsigned int p = 0; p + 1 < n_processes; ++p)
        {
          // The longest range from start within the bound, by bisection.
          global_dof_index low  = start + 1,
                           high = n_dofs - (n_processes - 1 - p);
          while (low < high)
            {
              const global_dof_index middle = low + (high - low + 1) / 2;
              if (spans.evaluated(start, middle) <= most)
                low = middle;
              else
                high = middle - 1;
            }
          ends.push_back(low);
          start = low;
        }
      ends.push_back(n_dofs);
      return ends;
    }
  } // namespace


  dealii::IndexSet
  balanced_share(const std::vector<std::unique_ptr<ElementFamily>> &families,
                 const dealii::types::global_dof_index              n_dofs,
                 const unsigned int                                 n_processes,
                 const unsigned int                                 rank)
  {
    // Ranges are rarely shorter than a sixteenth of an even share.
    const StencilSpans spans(families, n_dofs / (16 * n_processes) + 1);
    if (n_processes == 1 || spans.first.empty() || n_dofs < n_processes)
      return contiguous_share(n_dofs, n_processes, rank);
    // The least bound on the stencils of a range for which the greedy
    // ranges leave the last range within it too: bisection over the count.
    const auto last_within = [&](const std::size_t most) {
      const auto ends = greedy_ends(spans, n_dofs, n_processes, most);
      return spans.evaluated(ends[n_processes - 2], n_dofs) <= most;
    };
    std::size_t low = 0, high = spans.first.size();
    while (low < high)
      {
        const std::size_t middle = low + (high - low) / 2;
        if (last_within(middle))
          high = middle;
        else
          low = middle + 1;
      }
    const auto       ends = greedy_ends(spans, n_dofs, n_processes, low);
    dealii::IndexSet result(n_dofs);
    result.add_range(rank == 0 ? 0 : ends[rank - 1], ends[rank]);
    return result;
  }
} // namespace rodnet
