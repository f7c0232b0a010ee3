#include <solvers/newton/saddle_point_order.h>

#include <algorithm>
#include <amd.h>
#include <stdexcept>
#include <utility>

namespace rodnet
{
  namespace
  {
    /**
     * The compressed rows of the pattern of K_xx + |G|^T |G|: the rows of
     * @p kept (the rows with a nonzero diagonal), numbered by @p index,
     * each with its own columns among them and the columns of the
     * zero-diagonal rows it couples. Unsorted, with duplicates: AMD
     * accepts both.
     */
    std::pair<std::vector<int>, std::vector<int>>
    condensed_pattern(const std::vector<int>  &offsets,
                      const std::vector<int>  &columns,
                      const std::vector<bool> &zero_diagonal,
                      const std::vector<int>  &kept,
                      const std::vector<int>  &index)
    {
      std::vector<int> condensed_offsets(1, 0), condensed_columns;
      const auto       add_row = [&](const int row) {
        for (int k = offsets[row]; k < offsets[row + 1]; ++k)
          if (!zero_diagonal[columns[k]])
            condensed_columns.push_back(index[columns[k]]);
      };
      for (const int row : kept)
        {
          add_row(row);
          for (int k = offsets[row]; k < offsets[row + 1]; ++k)
            if (zero_diagonal[columns[k]])
              add_row(columns[k]);
          condensed_offsets.push_back(condensed_columns.size());
        }
      return {std::move(condensed_offsets), std::move(condensed_columns)};
    }
  } // namespace


  std::vector<int>
  saddle_point_order(const std::vector<int>  &offsets,
                     const std::vector<int>  &columns,
                     const std::vector<bool> &zero_diagonal)
  {
    const int        n = offsets.size() - 1;
    std::vector<int> kept, index(n, -1);
    for (int row = 0; row < n; ++row)
      if (!zero_diagonal[row])
        {
          index[row] = kept.size();
          kept.push_back(row);
        }
    const auto [condensed_offsets, condensed_columns] =
      condensed_pattern(offsets, columns, zero_diagonal, kept, index);
    std::vector<int> amd(kept.size());
    double           control[AMD_CONTROL], info[AMD_INFO];
    amd_defaults(control);
    if (amd_order(kept.size(),
                  condensed_offsets.data(),
                  condensed_columns.data(),
                  amd.data(),
                  control,
                  info) < AMD_OK)
      throw std::runtime_error("AMD could not order the tangent");

    // Each row's place: a kept row's rank in AMD's order, twice; a
    // zero-diagonal row's, one more than that of the last row it couples
    // (after all others where it couples none).
    std::vector<int> place(n, 2 * n);
    for (std::size_t k = 0; k < amd.size(); ++k)
      place[kept[amd[k]]] = 2 * k;
    for (int row = 0; row < n; ++row)
      if (zero_diagonal[row])
        {
          int last = -1;
          for (int k = offsets[row]; k < offsets[row + 1]; ++k)
            if (!zero_diagonal[columns[k]])
              last = std::max(last, place[columns[k]]);
          if (last >= 0)
            place[row] = last + 1;
        }
    std::vector<int> order(n);
    for (int row = 0; row < n; ++row)
      order[row] = row;
    std::stable_sort(order.begin(), order.end(), [&](const int a, const int b) {
      return place[a] < place[b];
    });
    return order;
  }
} // namespace rodnet
