#ifndef RODNET_SOLVERS_STABILITY_H
#define RODNET_SOLVERS_STABILITY_H

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace rodnet
{
  /// Largest number of free DoFs for which lowest_eigenvalues() forms a
  /// dense matrix.
  constexpr unsigned int max_dense_eigenvalue_dofs = 6000;

  /**
   * The @p n lowest eigenvalues, in increasing order, of the tangent
   * restricted to the DoFs that @p constraints leave free (linearized
   * stability: the state is stable while the lowest is positive). Dense
   * symmetric eigensolver (Eigen); throws with a clear message beyond
   * max_dense_eigenvalue_dofs.
   */
  std::vector<double>
  lowest_eigenvalues(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                     const dealii::AffineConstraints<double>      &constraints,
                     unsigned int                                  n = 1);
  /**
   * The lowest eigenvalue of the constrained tangent and its eigenvector,
   * unit in the Euclidean norm, over all DoFs (zero at constrained ones).
   * Same limits as lowest_eigenvalues().
   */
  std::pair<double, std::vector<double>>
  lowest_eigenpair(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                   const dealii::AffineConstraints<double>      &constraints);
} // namespace rodnet

#endif
