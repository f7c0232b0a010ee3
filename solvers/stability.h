#ifndef RODNET_SOLVERS_STABILITY_H
#define RODNET_SOLVERS_STABILITY_H

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Eigen/Core>
#include <limits>
#include <memory>
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
    /// zero pivot (a singular tangent) sits; invalid_unsigned_int where an
    /// exactly zero pivot stopped the factorization.
    unsigned int weakest_dof = 0;
    /// That pivot divided by the diagonal entry of its row.
    double weakest_ratio = std::numeric_limits<double>::infinity();
  };

  /**
   * The sparse factorization P K_ff P^T = L D L^T of the tangent restricted
   * to the DoFs that @p constraints leave free (Eigen's SimplicialLDLT, AMD
   * ordering), for the inertia of the tangent and solves with it. It costs
   * about as much as a Newton iteration's factorization, instead of a dense
   * eigen-decomposition. With a @p shift sigma it factorizes K_ff - sigma I
   * instead (shift-invert eigen-solvers, lowest_eigenpairs()), whose
   * inertia counts the eigenvalues of K_ff below sigma.
   */
  class ConstrainedFactorization
  {
  public:
    ConstrainedFactorization(
      const dealii::TrilinosWrappers::SparseMatrix &tangent,
      const dealii::AffineConstraints<double>      &constraints,
      double                                        shift = 0);
    ~ConstrainedFactorization();

    /**
     * Inertia from the pivots D: K = (P^T L) D (P^T L)^T is a congruence,
     * so by Sylvester's law of inertia K_ff has as many negative (zero,
     * positive) eigenvalues as D has negative (zero, positive) entries.
     * Where it can be wrong (doc/user_guide.md, "Stability and strain
     * range"): the factorization does not pivot for stability, so a pivot
     * that rounding leaves near zero (a tangent within rounding of
     * singular, at a bifurcation) has an arbitrary sign. A pivot below
     * @p zero_ratio times its row's diagonal counts as zero.
     */
    Inertia
    inertia(double zero_ratio = 1e-12) const;

    /// K_ff^-1 b_f for @p rhs (one entry per DoF); zero at constrained
    /// DoFs. Throws std::runtime_error where the factorization failed.
    std::vector<double>
    solve(const std::vector<double> &rhs) const;

    /// The free DoFs, in the order of the rows of solve_free()'s blocks.
    const std::vector<unsigned int> &
    free_dofs() const;

    /// Overwrites each column b of @p block (one row per free DoF) by
    /// (K_ff - sigma I)^-1 b. Throws std::runtime_error where the
    /// factorization failed.
    void
    solve_free(Eigen::MatrixXd &block) const;

    /// The mean magnitude of the diagonal of K_ff: the scale of its
    /// eigenvalues where a shift must be small against them.
    double
    diagonal_scale() const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
  };

  /// ConstrainedFactorization(tangent, constraints).inertia(zero_ratio).
  Inertia
  tangent_inertia(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                  const dealii::AffineConstraints<double>      &constraints,
                  double zero_ratio = 1e-12);
} // namespace rodnet

#endif
