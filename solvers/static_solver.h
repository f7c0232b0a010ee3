#ifndef RODNET_SOLVERS_STATIC_SOLVER_H
#define RODNET_SOLVERS_STATIC_SOLVER_H

#include <core/rod_model.h>
#include <solvers/newton_solver.h>

#include <cmath>
#include <functional>
#include <ostream>
#include <stdexcept>

namespace rodnet
{
  /// Thrown when a load step cannot be completed even at the smallest
  /// allowed step; earlier converged steps have already been reported.
  class SolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Static equilibrium by load stepping: the load factor goes from 0 to 1
   * in equal steps, each solved by NewtonSolver from the previous
   * equilibrium; a failed step is halved until it converges or falls below
   * the minimum. After every converged step the reference configuration is
   * reset and the observer is called. Optionally tracks the lowest
   * eigenvalue of the constrained tangent and locates the load factor where
   * it first crosses zero by bisection.
   */
  class StaticSolver
  {
  public:
    struct Parameters
    {
      unsigned int n_steps = 10;
      /// Smallest load step, as a fraction of the nominal 1 / n_steps.
      double min_step_fraction = 1.0 / 1024;
      /// Newton converges when |residual| <= tolerance * max(|lambda f|,
      /// |initial residual of the step|).
      double relative_tolerance = 1e-9;
      NewtonSolver::Parameters newton;
      bool   track_lowest_eigenvalue = false;
      bool   find_critical_load      = false;
      /// Bisection stops when the bracket is below this (in load factor).
      double critical_load_tolerance = 1e-6;
    };

    struct StepInfo
    {
      unsigned int step = 0;
      double       load_factor = 0;
      unsigned int iterations = 0;
      double       residual_norm = 0;
      double       wall_time = 0; ///< seconds spent on this step
      double       lowest_eigenvalue = std::nan("");
    };

    using Observer =
      std::function<void(const StepInfo &, const VectorType &solution)>;

    StaticSolver(RodModel &model, const Parameters &parameters,
                 std::ostream *log = nullptr);

    /**
     * Runs the load steps from the state @p u (usually zero) at load factor
     * 0. Throws SolverFailure naming the load factor and the reason when a
     * step cannot be completed.
     */
    void
    run(VectorType &u, const Observer &on_converged);

    /// Load factor where the lowest eigenvalue first crossed zero (NaN if it
    /// did not, or if the search was off).
    double
    critical_load_factor() const
    {
      return critical_load;
    }

    /// Lowest eigenvalue of the constrained tangent at @p u.
    double
    lowest_eigenvalue(const VectorType &u, double load_factor);

  private:
    /// Newton from @p u at @p load_factor; @p u holds the result.
    NewtonSolver::Result
    solve_at(VectorType &u, double load_factor);

    void
    bisect_critical_load(const VectorType   &u_stable,
                         const Configuration &stable_configuration,
                         double              lambda_stable,
                         double              eigenvalue_stable,
                         double              lambda_unstable,
                         double              eigenvalue_unstable);

    RodModel    &model;
    Parameters   parameters;
    std::ostream *log;
    MatrixType   tangent;
    double       critical_load = std::nan("");
  };
} // namespace rodnet

#endif
