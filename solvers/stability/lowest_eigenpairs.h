#ifndef RODNET_SOLVERS_STABILITY_LOWEST_EIGENPAIRS_H
#define RODNET_SOLVERS_STABILITY_LOWEST_EIGENPAIRS_H

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rodnet
{
  /// The lowest eigenpairs of a constrained tangent (lowest_eigenpairs()).
  struct Eigenpairs
  {
    /// Eigenvalues in increasing order.
    std::vector<double> values;
    /// Eigenvectors over all DoFs (zero at constrained ones), unit in the
    /// Euclidean norm; vectors[i] belongs to values[i].
    std::vector<std::vector<double>> vectors;
    /// Sparse factorizations made (shifts tried, the check included).
    unsigned int factorizations = 0;
    /// Solves with a factorization (Lanczos vectors).
    unsigned int solves = 0;
  };

  /// Most free DoFs for which lowest_eigenpairs() takes the dense
  /// symmetric eigensolver (exact, O(n^3)) rather than the sparse one.
  constexpr unsigned int max_dense_eigenpair_dofs = 300;

  /**
   * The @p k lowest eigenpairs of the tangent restricted to the DoFs that
   * @p constraints leave free by the dense symmetric eigensolver (Eigen's
   * SelfAdjointEigenSolver): exact to rounding, O(n^2) memory and O(n^3)
   * time in the n free DoFs. With @p multipliers (the constraint rows G of
   * a KKT tangent, ConstrainedFactorization): the eigenpairs of the Hessian
   * H on the constraint manifold, Z^T H Z with Z an orthonormal basis of
   * the null space of G, the vectors Z y (zero at the multipliers).
   */
  Eigenpairs
  dense_eigenpairs(
    const dealii::TrilinosWrappers::SparseMatrix       &tangent,
    const dealii::AffineConstraints<double>            &constraints,
    unsigned int                                        k,
    const std::vector<dealii::types::global_dof_index> &multipliers = {});

  /**
   * The @p k lowest eigenpairs of the tangent restricted to the DoFs that
   * @p constraints leave free, at a cost linear in the DoFs for a rod
   * network's tangent (sparse LDL^T factorizations and solves).
   *
   * Up to max_dense_eigenpair_dofs free DoFs: the dense eigensolver.
   * Beyond: shift-invert block Lanczos (Ericsson & Ruhe, Math. Comp. 35,
   * 1980; Grimes, Lewis & Simon, SIAM J. Matrix Anal. Appl. 15, 1994) with
   * a shift sigma below the lowest eigenvalue, so that (K_ff - sigma I)^-1
   * is positive definite and the wanted eigenvalues lambda are its
   * largest, theta = 1 / (lambda - sigma):
   *  1. sigma = 0 if the LDL^T of K_ff has no negative or zero pivot;
   *     otherwise sigma = -2 |lambda_0| (lambda_0 the eigenvalue nearest
   *     zero, from a Lanczos run with K_ff^-1), made four times more
   *     negative until the inertia of K_ff - sigma I shows no eigenvalue
   *     below it (Sylvester's law of inertia);
   *  2. block Lanczos with full reorthogonalization, blocks of
   *     min(k, 6) vectors (at least 3), until the residual of each of the
   *     k largest Ritz pairs is below @p tolerance times its Ritz value;
   *  3. the result is checked by the inertia of K_ff - tau I, tau just
   *     above the k-th value: exactly k eigenvalues below tau, or an
   *     eigenvalue of a multiplicity above the block size was missed and
   *     the run is repeated with blocks twice as big.
   *
   * Throws std::invalid_argument if every DoF is constrained, and
   * SolverFailure with the reason where no shift can be factorized or
   * the iteration does not converge within 10 k + 100 Lanczos vectors
   * (memory: that many vectors of the free DoFs). The dense solver also
   * takes k of a quarter of the free DoFs or more.
   *
   * With @p multipliers: on the constraint manifold, as dense_eigenpairs();
   * the sparse path on the condensed operator of ConstrainedFactorization,
   * exact to a fraction 1e-2 (l / L)^2 of each eigenvalue.
   */
  Eigenpairs
  lowest_eigenpairs(
    const dealii::TrilinosWrappers::SparseMatrix       &tangent,
    const dealii::AffineConstraints<double>            &constraints,
    unsigned int                                        k,
    const std::vector<dealii::types::global_dof_index> &multipliers = {},
    double                                              tolerance   = 1e-9);

  /**
   * @p u moved along @p mode (one entry per DoF, as Eigenpairs::vectors)
   * so that its largest component moves by @p distance (its sign the
   * direction): a state pushed off an unstable equilibrium along its
   * buckling mode, or a mode drawn on the state.
   */
  template <class VectorType>
  VectorType
  moved_along_mode(const VectorType          &u,
                   const std::vector<double> &mode,
                   const double               distance)
  {
    double largest = 0;
    for (const double m : mode)
      largest = std::max(largest, std::abs(m));
    VectorType moved = u;
    // Each process moves its own entries: on several, an entry added by
    // every process would move P times.
    for (const auto i : moved.locally_owned_elements())
      if (mode[i] != 0)
        moved[i] += distance / largest * mode[i];
    moved.compress(dealii::VectorOperation::add);
    return moved;
  }
} // namespace rodnet

#endif
