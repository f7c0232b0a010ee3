#ifndef RODNET_SOLVERS_NEWTON_ENERGY_LINE_SEARCH_H
#define RODNET_SOLVERS_NEWTON_ENERGY_LINE_SEARCH_H

#include <NOX_LineSearch_Generic.H>
#include <NOX_LineSearch_UserDefinedFactory.H>

namespace rodnet
{
  class NoxGroup;

  /**
   * A line search on the total potential energy, for problems whose
   * residual is the gradient of a potential (NewtonSolver::Problem::energy):
   * every static load step is the minimization of the potential, so the
   * energy, not the residual norm, says whether a step went downhill. Along
   * x + a d it finds a step a with the strong Wolfe conditions (Nocedal &
   * Wright, Numerical Optimization, 2nd ed., eqs. 3.7 and algorithms 3.5,
   * 3.6):
   *
   *   Pi(a) <= Pi(0) + c1 a Pi'(0)     (sufficient decrease),
   *   |Pi'(a)| <= c2 |Pi'(0)|          (curvature),
   *
   * with Pi'(a) = R(x + a d) . d, the residual along the direction, so each
   * trial costs one assembly of energy and residual together. The full
   * step a = 1 is tried first; a longer one if the energy still falls
   * steeply there; otherwise the bracket is narrowed by cubic
   * interpolation of the energies and slopes at its ends (N&W eq. 3.59).
   *
   * Where the Newton direction climbs (Pi'(0) > 0: the tangent is not
   * positive definite), the search runs along -d, which descends. Near
   * convergence the change of energy over a step is below the rounding of
   * the energy itself; sufficient decrease is then judged with the
   * energy's rounding allowed (relative_rounding |Pi(0)|), so full Newton
   * steps are taken where Newton converges quadratically anyway.
   */
  class EnergyLineSearch : public NOX::LineSearch::Generic
  {
  public:
    struct Parameters
    {
      /// c1 of the sufficient decrease condition.
      double sufficient_decrease = 1e-4;
      /// c2 of the curvature condition (0.9: loose, as for Newton steps).
      double curvature = 0.9;
      /// Energy and residual evaluations per line search at most.
      unsigned int max_trials = 20;
      /// The longest step tried, as a multiple of the Newton step.
      double max_step = 8;
      /// Relative rounding of the assembled energy.
      double relative_rounding = 1e-12;
    };

    /// With the default Parameters.
    EnergyLineSearch();

    explicit EnergyLineSearch(const Parameters &parameters);

    /// Moves @p grp (a NoxGroup) to x_old + step dir, x_old being the
    /// solver's previous group; false if no step satisfies the conditions
    /// (grp then holds the best point found with sufficient decrease, or
    /// x_old).
    bool
    compute(NOX::Abstract::Group        &grp,
            double                      &step,
            const NOX::Abstract::Vector &dir,
            const NOX::Solver::Generic  &solver) override;

  private:
    Parameters parameters;
  };

  /// Hands EnergyLineSearch to NOX ("User Defined" line search).
  class EnergyLineSearchFactory : public NOX::LineSearch::UserDefinedFactory
  {
  public:
    Teuchos::RCP<NOX::LineSearch::Generic>
    buildLineSearch(const Teuchos::RCP<NOX::GlobalData> &global_data,
                    Teuchos::ParameterList &parameters) const override;
  };
} // namespace rodnet

#endif
