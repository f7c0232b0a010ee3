#ifndef RODNET_SOLVERS_STABILITY_STABILITY_H
#define RODNET_SOLVERS_STABILITY_STABILITY_H

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <Eigen/Core>
#include <Epetra_CrsMatrix.h>
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
   *
   * <h3>Constraints by multipliers</h3>
   * Where the model has Lagrange multipliers (@p multipliers, e.g.
   * SolvableModel::multiplier_dofs()), the tangent is the KKT matrix
   * [H, G^T; G, 0] and what counts is the Hessian H on the constraint
   * manifold, Z^T H Z with G Z = 0 (Nocedal & Wright 16.2): the KKT matrix
   * has one negative eigenvalue per constraint besides (Gould 1985), and its
   * zero diagonal stops an LDL^T without pivoting. So the multiplier rows
   * are regularized, [H + rho G^T G, G^T; G, -I/rho] with rho = 1 / (c a)
   * per row (a its largest entry, c = 1e-2): its LDL^T exists in any
   * order where H is positive on the manifold (a quasi-definite matrix,
   * Vanderbei 1995); eliminating the multipliers leaves H + 2 rho G^T G,
   * whose negative eigenvalues are those of Z^T H Z once the penalty
   * dominates (Debreu's lemma). inertia() subtracts the one negative pivot
   * per multiplier; the shift acts on the other DoFs only (the eigenproblem
   * H v = lambda v on the manifold), and the solves, free_dofs() and
   * solve_free() leave the multipliers out: they apply the inverse of the
   * condensed operator H + 2 rho G^T G - sigma I, whose lowest eigenvalues
   * are those on the manifold to a fraction c (l / L)^2 (l the segment's
   * length, L the mode's wavelength; the penalty acts like a stretching
   * rigidity EI / (c l^2)).
   */
  class ConstrainedFactorization
  {
  public:
    ConstrainedFactorization(
      const dealii::TrilinosWrappers::SparseMatrix       &tangent,
      const dealii::AffineConstraints<double>            &constraints,
      double                                              shift       = 0,
      const std::vector<dealii::types::global_dof_index> &multipliers = {});
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

    /// Whether the factorization is regular with no eigenvalue below its
    /// shift: every pivot positive (inertia(0.0) counts no negative and no
    /// zero pivot).
    bool
    positive_definite() const;

    /// K_ff^-1 b_f for @p rhs (one entry per DoF); zero at constrained
    /// DoFs (and at multipliers, see the class documentation). Throws
    /// std::runtime_error where the factorization failed.
    std::vector<double>
    solve(const std::vector<double> &rhs) const;

    /// The free DoFs but the multipliers, in the order of the rows of
    /// solve_free()'s blocks.
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

  /// ConstrainedFactorization(tangent, constraints, 0, multipliers)
  /// .inertia(zero_ratio).
  Inertia
  tangent_inertia(
    const dealii::TrilinosWrappers::SparseMatrix       &tangent,
    const dealii::AffineConstraints<double>            &constraints,
    const std::vector<dealii::types::global_dof_index> &multipliers = {},
    double                                              zero_ratio  = 1e-12);

  /**
   * Every row of @p tangent on this process: its own matrix where this
   * process holds all rows, otherwise an import of all rows into
   * @p gathered (a map that repeats every row on every process). What is
   * computed from it is then the same, and serial, on every process:
   * O(nnz) memory per process (doc/architecture.md, "Several processes").
   * Collective where @p tangent is distributed.
   */
  const Epetra_CrsMatrix &
  every_row(const dealii::TrilinosWrappers::SparseMatrix &tangent,
            std::unique_ptr<Epetra_CrsMatrix>            &gathered);
} // namespace rodnet

#endif
