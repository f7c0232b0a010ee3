#ifndef RODNET_SOLVERS_CHECKS_EQUILIBRIUM_CHECK_H
#define RODNET_SOLVERS_CHECKS_EQUILIBRIUM_CHECK_H

#include <core/solvable_model.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/newton/tangent_factorization.h>

#include <string>

namespace rodnet
{
  /**
   * The negative eigenvalues of the constrained tangent of @p model at
   * (@p u, @p load_factor), assembled into @p tangent, from its inertia
   * (ConstrainedFactorization::inertia()), on the complement of the
   * symmetry modes there (symmetry_modes(): motions along which the energy
   * does not change, whose eigenvalue is rounding of either sign), so that
   * the buckled elastica with EI1 = EI2 counts as stable. On several
   * processes the tangent is factorized by MUMPS, the analysis of
   * @p factorizations reused where it holds one for @p tangent
   * (EquilibriumFactorization).
   */
  unsigned int
  negative_eigenvalues(const SolvableModel       &model,
                       const VectorType          &u,
                       double                     load_factor,
                       MatrixType                &tangent,
                       TangentFactorizationCache *factorizations = nullptr);

  /// What the solvers check at a converged equilibrium besides its residual.
  struct EquilibriumCheck
  {
    /// Negative eigenvalues of the constrained tangent (its inertia).
    unsigned int negative_eigenvalues = 0;
    /// No negative eigenvalue: a perturbation does not grow.
    bool stable = true;
    /// Where the tolerance was a round-off floor: the Newton correction of
    /// the residual (positions over the model size, angles in rad), the
    /// distance to the exact discrete equilibrium; 0 otherwise.
    double rounding_uncertainty = 0;
    /// Why, where rounding_uncertainty exceeds its limit; empty otherwise.
    std::string rounding_warning;
  };

  /**
   * Checks the equilibrium @p u at @p load_factor that the solve @p result
   * accepted: one LDL^T of the constrained tangent (assembled into
   * @p tangent) gives its inertia (negative_eigenvalues(): symmetry modes
   * do not count),
   * and, where @p result was rounding-limited, the Newton correction of its
   * residual on the complement of the symmetry modes (along which every
   * state is an equilibrium), which may not exceed @p uncertainty_limit
   * without a warning (ResidualCriterion::rounding_hint()).
   * @p factorizations as for negative_eigenvalues().
   */
  EquilibriumCheck
  check_equilibrium(const SolvableModel       &model,
                    const ResidualCriterion   &criterion,
                    const VectorType          &u,
                    double                     load_factor,
                    MatrixType                &tangent,
                    const JudgedResult        &result,
                    double                     uncertainty_limit,
                    TangentFactorizationCache *factorizations = nullptr);

  /**
   * Throws SolverFailure where @p check finds the state at @p where (e.g.
   * "load factor 0.5") undetermined: its rounding-limited residual calls for
   * a Newton correction beyond @p failure_limit (of the model size, or rad).
   * Such a residual is no evidence of equilibrium (a rod of 1e5 segments
   * under a load below its round-off floor "converges" at iteration 0 with
   * a correction of 100 model sizes); the message names where rounding
   * weighs most.
   */
  void
  refuse_undetermined_state(const EquilibriumCheck &check,
                            double                  failure_limit,
                            const std::string      &where);
} // namespace rodnet

#endif
