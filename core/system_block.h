#ifndef RODNET_CORE_SYSTEM_BLOCK_H
#define RODNET_CORE_SYSTEM_BLOCK_H

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace rodnet
{
  /**
   * Where a model's DoFs sit in a caller's linear system: model DoF i is
   * row and column index(i) there. A user who couples a rod model with
   * other deal.II models places its DoFs as a block of the coupled system
   * (at_offset()) or anywhere else (one index per DoF), and the model
   * assembles its sparsity, residual and tangent into those rows and
   * columns (RodModel::add_sparsity_pattern(), RodModel::assemble_into()).
   */
  class SystemBlock
  {
  public:
    using size_type = dealii::types::global_dof_index;

    /// Model DoF i at row @p offset + i, for a model of @p n_model_dofs
    /// DoFs (offset 0: the model's own numbering).
    static SystemBlock
    at_offset(size_type n_model_dofs, size_type offset);

    /// Model DoF i at row @p rows[i]; throws std::invalid_argument if two
    /// DoFs share a row.
    explicit SystemBlock(std::vector<size_type> rows);

    /// Number of model DoFs placed.
    size_type
    size() const
    {
      return rows.size();
    }

    /// Row (and column) of model DoF @p i.
    size_type
    index(const size_type i) const
    {
      return rows[i];
    }

    /// Renames model DoFs @p dofs to their rows in place.
    void
    map(std::vector<size_type> &dofs) const;

    /// @p constraints of model DoFs as constraints of the rows.
    dealii::AffineConstraints<double>
    map(const dealii::AffineConstraints<double> &constraints) const;

  private:
    std::vector<size_type> rows;
  };
} // namespace rodnet

#endif
