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
   * Smallest residual norm that rounding errors let a state of @p model
   * reach, from its constrained @p tangent: an axial force EA (|e|/l - 1)
   * carries the rounding error of the positions, eps |x|, times EA / l, the
   * scale of the tangent's diagonal; summed over the DoFs, no residual
   * norm below eps max|K_ii| L sqrt(n_dofs) is meaningful.
   */
  double
  residual_roundoff_floor(const RodModel &model, const MatrixType &tangent);

  /**
   * Static equilibrium by load stepping: the load factor goes from 0 to 1
   * in equal steps, each solved by NewtonSolver from the previous
   * equilibrium moved by a predictor (see Parameters::predict); a failed step
   * is halved until it converges or falls below the minimum. After every
   * converged step the reference configuration is reset and the observer is
   * called. Optionally tracks the lowest eigenvalue of the constrained tangent
   * and locates the load factor where it first crosses zero by bisection.
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
      /// |initial residual of the step|), or below the rounding-error floor
      /// eps * max|K_ii| * L * sqrt(n_dofs), whichever is larger.
      double relative_tolerance = 1e-9;
      /// Start each step from a prediction: the previous state plus the
      /// last converged increment scaled to the step, or, without one, the
      /// linear response to the moved prescribed DoFs (falling back to the
      /// previous state if Newton fails from there).
      bool                     predict = true;
      NewtonSolver::Parameters newton;
      bool                     track_lowest_eigenvalue = false;
      bool                     find_critical_load      = false;
      /// Bisection stops when the bracket is below this (in load factor).
      double critical_load_tolerance = 1e-6;
      /// Where a converged state is unstable (negative lowest eigenvalue),
      /// push it along the buckling mode with a dead force of this fraction
      /// of the applied load, both ways, then remove that force in steps,
      /// and keep the stable equilibrium of lower energy (0 = off). Without
      /// it Newton may follow the unstable branch past a bifurcation.
      double branch_switch_amplitude = 0;
    };

    struct StepInfo
    {
      unsigned int step              = 0;
      double       load_factor       = 0;
      unsigned int iterations        = 0;
      double       residual_norm     = 0;
      double       wall_time         = 0; ///< seconds spent on this step
      double       lowest_eigenvalue = std::nan("");
    };

    using Observer =
      std::function<void(const StepInfo &, const VectorType &solution)>;

    StaticSolver(RodModel         &model,
                 const Parameters &parameters,
                 std::ostream     *log = nullptr);

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
    /**
     * Newton from @p u at @p load_factor; @p u holds the result. The force
     * scale of the tolerance is the larger of the applied load and the
     * residual at @p u, or at @p scale_state instead if given: the
     * unextrapolated start, so that the predictor changes neither way the
     * tolerance (a good prediction would tighten it, one that stretches
     * stiff segments would loosen it).
     */
    NewtonSolver::Result
    solve_at(VectorType       &u,
             double            load_factor,
             const VectorType *extra_force = nullptr,
             const VectorType *scale_state = nullptr);

    /**
     * Newton at @p load_factor from @p u displaced both ways along the
     * lowest eigenmode of the tangent at (@p u, @p mode_load_factor). If a
     * stable equilibrium of energy below @p energy_bound is found, @p u,
     * @p eigenvalue and the model's reference become the lowest-energy one
     * and it returns true; otherwise they are left as they were.
     */
    bool
    solve_along_mode(VectorType &u,
                     double      mode_load_factor,
                     double      load_factor,
                     double      energy_bound,
                     double     &eigenvalue);

    /**
     * Start for a step to @p load_factor from the equilibrium @p u that has
     * no previous increment to extrapolate: the prescribed DoFs move to
     * their values and the free ones follow by one solve with the tangent
     * at @p u. Returns false (and leaves @p trial) when no prescribed DoF
     * moves, since Newton's first iteration is then the same solve.
     */
    bool
    linear_prediction(const VectorType &u,
                      double            load_factor,
                      VectorType       &trial);

    void
    bisect_critical_load(const VectorType    &u_stable,
                         const Configuration &stable_configuration,
                         double               lambda_stable,
                         double               eigenvalue_stable,
                         double               lambda_unstable,
                         double               eigenvalue_unstable);

    RodModel     &model;
    Parameters    parameters;
    std::ostream *log;
    MatrixType    tangent;
    /// Tangent without the support constraints, for linear_prediction().
    MatrixType unconstrained_tangent;
    double     critical_load = std::nan("");
  };
} // namespace rodnet

#endif
