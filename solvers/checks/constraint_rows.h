#ifndef RODNET_SOLVERS_CHECKS_CONSTRAINT_ROWS_H
#define RODNET_SOLVERS_CHECKS_CONSTRAINT_ROWS_H

#include <core/solvable_model.h>
#include <solvers/checks/dof_roles.h>

#include <vector>

namespace rodnet
{
  /**
   * One constraint of a stencil: the row of its Hessian at a multiplier
   * DoF (the constraint's gradient times its scale), over the stencil's
   * DoFs. A rigid motion that changes the constraint is stopped by it, as
   * by a support (solvers/checks/free_motions.cc).
   */
  struct ConstraintRow
  {
    std::vector<global_dof_index> dofs;
    std::vector<double>           gradient;
  };

  /// The constraint rows of every stencil of @p model that has a DoF that
  /// @p roles calls a multiplier, at @p u and load factor 0.
  std::vector<ConstraintRow>
  constraint_rows(const SolvableModel &model,
                  const DofRoles      &roles,
                  const VectorType    &u);
} // namespace rodnet

#endif
