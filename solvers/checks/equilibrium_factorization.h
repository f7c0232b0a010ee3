#ifndef RODNET_SOLVERS_CHECKS_EQUILIBRIUM_FACTORIZATION_H
#define RODNET_SOLVERS_CHECKS_EQUILIBRIUM_FACTORIZATION_H

#include <core/solvable_model.h>
#include <solvers/newton/tangent_factorization.h>
#include <solvers/stability/stability.h>

#include <memory>

namespace rodnet
{
  /**
   * The factorization of a constrained tangent that the equilibrium checks
   * read (check_equilibrium(), negative_eigenvalues()): the inertia of the
   * Hessian on the constraint manifold, and solves with it. Two kinds,
   * chosen by create() from where the tangent's rows are:
   *  - On one process, ConstrainedFactorization: Eigen's sparse LDL^T of
   *    the free block, the multipliers regularized.
   *  - On several processes, MUMPS's distributed LDL^T of the whole KKT
   *    tangent, each process factorizing its part of the fronts, instead
   *    of each repeating the serial LDL^T of an imported copy (which took
   *    about a tenth of each process's time on the welded lattice,
   *    doc/performance.md). MUMPS pivots in 2 x 2 blocks, so the zero
   *    diagonal of the multipliers needs no regularization:
   *    K = [H, G^T; G, 0] with G of full rank m has the inertia of
   *    Z^T H Z (G Z = 0) plus m positive and m negative eigenvalues (Gould
   *    1985), and the fixed DoFs' rows hold only a positive diagonal
   *    (DirectScatter). So inertia() is MUMPS's count of negative pivots
   *    less one per multiplier; a zero pivot that stops MUMPS is a zero
   *    eigenvalue (its DoF unknown: Inertia::weakest_dof is invalid). The
   *    solves give the exact constrained inverse Z (Z^T H Z)^-1 Z^T where
   *    ConstrainedFactorization gives the regularized one.
   */
  class EquilibriumFactorization
  {
  public:
    virtual ~EquilibriumFactorization() = default;

    /**
     * The factorization of @p tangent (assembled with the constraints
     * applied) of @p model. On several processes it takes the MUMPS
     * factorization of @p factorizations where it has one for
     * @p tangent (the Newton solver's, whose analysis it reuses) and
     * refactorizes it; the Newton solver factorizes again before it solves.
     * Collective where @p tangent is distributed.
     */
    static std::unique_ptr<EquilibriumFactorization>
    create(const SolvableModel       &model,
           const MatrixType          &tangent,
           TangentFactorizationCache *factorizations = nullptr);

    /// The signs of the eigenvalues of the Hessian on the constraint
    /// manifold (the fixed DoFs and the multipliers left out).
    virtual Inertia
    inertia() const = 0;

    /// x = K^-1 b on the free DoFs but the multipliers, whose right-hand
    /// sides count as zero; x is zero at the fixed DoFs and multipliers.
    /// Throws std::runtime_error where the tangent is singular. Collective
    /// where the vectors are distributed.
    virtual void
    solve(const VectorType &b, VectorType &x) const = 0;
  };
} // namespace rodnet

#endif
