#include <core/system_block.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace rodnet
{
  SystemBlock
  SystemBlock::at_offset(const size_type n_model_dofs, const size_type offset)
  {
    std::vector<size_type> rows(n_model_dofs);
    std::iota(rows.begin(), rows.end(), offset);
    return SystemBlock(std::move(rows));
  }

  SystemBlock::SystemBlock(std::vector<size_type> rows_)
      : rows(std::move(rows_))
  {
    std::vector<size_type> sorted = rows;
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end())
      throw std::invalid_argument("SystemBlock: row " + std::to_string(*twice) +
                                  " is given to two model DoFs");
  }

  void
  SystemBlock::map(std::vector<size_type> &dofs) const
  {
    for (size_type &dof : dofs)
      dof = rows[dof];
  }

  dealii::AffineConstraints<double>
  SystemBlock::map(const dealii::AffineConstraints<double> &constraints) const
  {
    dealii::AffineConstraints<double> mapped;
    for (const auto &line : constraints.get_lines())
      {
        mapped.add_line(rows[line.index]);
        for (const auto &[column, weight] : line.entries)
          mapped.add_entry(rows[line.index], rows[column], weight);
        mapped.set_inhomogeneity(rows[line.index], line.inhomogeneity);
      }
    mapped.close();
    return mapped;
  }
} // namespace rodnet
