#ifndef RODNET_TESTS_COMMON_DIAGONAL_TANGENT_H
#define RODNET_TESTS_COMMON_DIAGONAL_TANGENT_H

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

namespace rodnet::testing
{
  /// @p tangent made an n x n matrix with the diagonal pattern, on one
  /// process: the Jacobian of a separable test problem.
  inline void
  diagonal_tangent(const unsigned int                      n,
                   dealii::TrilinosWrappers::SparseMatrix &tangent)
  {
    dealii::IndexSet all(n);
    all.add_range(0, n);
    dealii::TrilinosWrappers::SparsityPattern pattern(all, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      pattern.add(i, i);
    pattern.compress();
    tangent.reinit(pattern);
  }
} // namespace rodnet::testing

#endif
