#ifndef RODNET_SOLVERS_STABILITY_H
#define RODNET_SOLVERS_STABILITY_H

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <limits>
#include <vector>

namespace rodnet
{
  /// Signs of the eigenvalues of a constrained tangent (see
  /// tangent_inertia()).
  struct Inertia
  {
    unsigned int negative = 0;
    unsigned int zero     = 0;
    unsigned int positive = 0;
    /// The DoF whose pivot is smallest against its row's diagonal: where a
    /// zero pivot (a singular tangent) sits.
    unsigned int weakest_dof = 0;
    /// That pivot divided by the diagonal entry of its row.
    double weakest_ratio = std::numeric_limits<double>::infinity();
  };

  /**
   * Inertia of the tangent restricted to the DoFs that @p constraints leave
   * free, from the pivots D of its sparse factorization P K P^T = L D L^T
   * (Eigen's SimplicialLDLT, AMD ordering). K = (P^T L) D (P^T L)^T is a
   * congruence, so by Sylvester's law of inertia K has as many negative
   * (zero, positive) eigenvalues as D has negative (zero, positive)
   * entries: the state is stable when none is negative. It costs one
   * sparse factorization, like a Newton iteration, instead of a dense
   * eigen-decomposition. Where it can be wrong (doc/user_guide.md,
   * "Stability and strain range"): the factorization does not pivot, so a
   * pivot that rounding leaves near zero (a tangent within rounding of
   * singular, at a bifurcation) has an arbitrary sign. A pivot below
   * @p zero_ratio times its row's diagonal counts as zero.
   */
  Inertia
  tangent_inertia(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                  const dealii::AffineConstraints<double>      &constraints,
                  double zero_ratio = 1e-12);

  /**
   * K_ff^-1 b_f: the solution of the tangent restricted to the free DoFs
   * of @p constraints for the right-hand side @p rhs on them (one entry per
   * DoF; zero in the result at constrained DoFs), by the sparse LDL^T of
   * tangent_inertia(). Throws std::runtime_error for a singular tangent.
   */
  std::vector<double>
  solve_free_block(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                   const dealii::AffineConstraints<double>      &constraints,
                   const std::vector<double>                    &rhs);

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
