#ifndef RODNET_SOLVERS_STATICS_STATIC_SOLVER_H
#define RODNET_SOLVERS_STATICS_STATIC_SOLVER_H

#include <deal.II/base/timer.h>

#include <core/solvable_model.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/checks/strain_range.h>
#include <solvers/newton/newton_solver.h>
#include <solvers/newton/tangent_factorization.h>
#include <solvers/solver_failure.h>

#include <cmath>
#include <functional>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace rodnet
{
  /**
   * Static equilibrium by load stepping: the load factor goes from 0 to 1
   * in equal steps, each solved by NewtonSolver from the previous
   * equilibrium moved by a predictor (see Parameters::predict); a failed step
   * is halved until it converges or falls below the minimum. After every
   * converged step the reference configuration is reset and the observer is
   * called. Optionally tracks the lowest eigenvalue of the constrained tangent
   * (dense) and locates the load factor where the state first turns unstable
   * by bisection (on the inertia of the tangent, sparse).
   *
   * A step converges when the force and the moment parts of the residual
   * are each small against the loads (ResidualCriterion). Every converged
   * state is checked for stability (the inertia of the constrained tangent)
   * and for strains past the range of the rod model (StrainMonitor); either
   * prints a warning on the log and shows in StepInfo.
   */
  class StaticSolver
  {
  public:
    struct Parameters
    {
      unsigned int n_steps = 10;
      /// Smallest load step, as a fraction of the nominal 1 / n_steps.
      double min_step_fraction = 1.0 / 1024;
      /// Wall time in seconds a load step may take, over all its attempts
      /// and cuts, before the run stops (checked after each failed
      /// attempt); 0: no bound.
      double max_step_time = 0;
      /// Newton converges when the force part of the residual is at most
      /// this times the force scale S of the loads and reactions, and the
      /// moment part at most this times S L, or each is at its round-off
      /// floor if that is larger (ResidualCriterion).
      double relative_tolerance = 1e-9;
      /// Where the round-off floor of a part exceeds this fraction of its
      /// loads, the residual cannot show equilibrium by itself
      /// (ResidualCriterion::inconclusive()); the Newton correction of the
      /// accepted residual is then checked against the next limit.
      double rounding_floor_limit = 1e-3;
      /// Largest Newton correction of such a state (positions over the
      /// model size, angles in rad) without a warning that names where
      /// rounding weighs most (ResidualCriterion::rounding_hint()).
      double rounding_uncertainty_limit = 1e-6;
      /// Newton correction of such a state beyond which the step is not
      /// accepted: the run stops with SolverFailure
      /// (refuse_undetermined_state()).
      double rounding_failure_limit = 1e-3;
      /// Strains past these get a warning (StrainMonitor).
      StrainLimits strain_limits;
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
      /// Where a converged state is unstable (the stability check counts a
      /// negative eigenvalue) or a step fails past one, move the state along
      /// the lowest mode by this fraction of the model size, both ways, and
      /// keep the stable equilibrium of lower energy found from there by
      /// Newton (0 = off). Without it Newton may follow the unstable branch
      /// past a bifurcation (a straight column under a load above Euler's).
      double branch_switch_amplitude = 0.1;

      /// Declares the entries of these parameters (those of newton, then
      /// "Relative tolerance", "Predictor", "Minimum step fraction" and the
      /// critical load and branch switching entries; n_steps is the scene's
      /// "Loads/Steps") in the current subsection of @p prm, with their
      /// defaults and help.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Reads the entries of declare_parameters() from the current
      /// subsection of @p prm.
      void
      parse_parameters(const dealii::ParameterHandler &prm);
    };

    struct StepInfo
    {
      unsigned int step        = 0;
      double       load_factor = 0;
      unsigned int iterations  = 0;
      /// Force (N) and moment (N m) norms of the final residual.
      ResidualParts residual;
      double        wall_time         = 0; ///< seconds spent on this step
      double        lowest_eigenvalue = std::nan("");
      /// Stability and rounding of the converged state.
      EquilibriumCheck check;
      StrainRange      strain;
    };

    using Observer =
      std::function<void(const StepInfo &, const VectorType &solution)>;

    StaticSolver(SolvableModel    &model,
                 const Parameters &parameters,
                 std::ostream     *log = nullptr);

    /**
     * Runs the load steps from the state @p u (usually zero) at load factor
     * 0. Throws std::invalid_argument before the first step for a model
     * with a rigid motion that no support stops (describe_free_motions()).
     * Throws SolverFailure naming the load factor and the reason when a
     * step cannot be completed (a singular tangent, a mechanism, is named
     * as such).
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

    /**
     * Newton, globalized as the parameters say, at @p load_factor from
     * @p u, a start that may lie far from equilibrium (its out-of-balance
     * counts in the scale of the tolerance, as for a branch switch);
     * @p u holds the last iterate on return. The path following's jump
     * past a limit point (ArclengthContinuation) solves with it.
     */
    JudgedResult
    solve_from_far_start(VectorType &u, double load_factor)
    {
      return solve_at(u, load_factor, nullptr, nullptr, true);
    }

  private:
    /**
     * Newton from @p u at @p load_factor; @p u holds the result. The scales
     * of the tolerance are those of the loads and reactions at @p u, or at
     * @p scale_state instead if given: the unextrapolated start, so that
     * the predictor does not change the tolerance. The reactions of the
     * solution are what counts: if the solution's tolerance is tighter,
     * Newton continues from there. Throws SolverFailure if rounding limits
     * the residual to more than roundoff_limit of the loads.
     */
    JudgedResult
    solve_at(VectorType       &u,
             double            load_factor,
             const VectorType *extra_force = nullptr,
             const VectorType *scale_state = nullptr,
             bool              far_start   = false);

    /// What the Newton rounds of one solve_at() share: where they solve,
    /// and the loads' scale, the rounding noise and the tolerance, which
    /// the convergence test reads through step
    /// (ResidualCriterion::stall_aware_test()) and the rounds update.
    struct JudgedSolve
    {
      JudgedSolve(const double      load_factor,
                  const VectorType *extra_force,
                  const bool        far_start,
                  const double      relative_tolerance)
          : load_factor(load_factor)
          , extra_force(extra_force)
          , far_start(far_start)
          , step{noise,
                 tolerance,
                 scale,
                 relative_tolerance,
                 load_factor,
                 extra_force}
      {
      }

      /// step refers to the members of this one.
      JudgedSolve(const JudgedSolve &) = delete;
      JudgedSolve &
      operator=(const JudgedSolve &) = delete;

      double            load_factor;
      const VectorType *extra_force;
      /// Whether the start may lie far from equilibrium: its out-of-balance
      /// counts in the scale (solve_from_far_start()).
      bool                             far_start;
      ResidualParts                    tolerance, reached, scale;
      RoundoffNoise                    noise;
      ResidualCriterion::StepTolerance step;
    };

    /// The equilibrium equations at @p load_factor (and the dead force
    /// @p extra_force, if given) for NewtonSolver, without the convergence
    /// test: the potential where there are no multipliers, the tangent
    /// with the frames' free turns at @p u held (free_frame_turns()).
    NewtonSolver::Problem
    equilibrium_problem(const VectorType &u,
                        double            load_factor,
                        const VectorType *extra_force);

    /// The rounding noise at @p u and the scale of the loads and reactions
    /// at the start (@p scale_state if given, else @p u, with the supports
    /// moved), widened to @p u's out-of-balance for a far start, into
    /// @p solve; throws where they cannot be evaluated.
    void
    judge_start(const VectorType &u,
                const VectorType *scale_state,
                JudgedSolve      &solve);

    /// Up to three Newton solves of @p problem from @p u, each to the
    /// tolerance of the reactions at the last one's solution, until the
    /// solution meets its own (judge_round()); @p u holds the result, or
    /// a far start's fallback where the tighter rounds fail.
    JudgedResult
    newton_rounds(const NewtonSolver::Problem &problem,
                  JudgedSolve                 &solve,
                  VectorType                  &u);

    /// The scale of the loads and reactions at the converged @p u into
    /// @p solve and @p outcome; whether @p u meets the tolerance it gives.
    /// Where the scale cannot be evaluated, @p outcome becomes a failure.
    bool
    judge_round(const VectorType &u, JudgedSolve &solve, JudgedResult &outcome);

    /// Whether the residual @p solve reached is within @p relative_tolerance
    /// of its scale (or at its rounding floor).
    static bool
    within_relative(const JudgedSolve &solve, double relative_tolerance);

    /**
     * Newton at @p load_factor from @p u displaced both ways along the
     * lowest eigenmode of the tangent at (@p u, @p mode_load_factor). If a
     * stable equilibrium of energy below @p energy_bound is found, @p u,
     * @p eigenvalue and the model's reference become the lowest-energy one
     * (the reference committed at @p u, whose quaternion increments are
     * then zero), @p solved (if given) the result of its solve, and it
     * returns true; otherwise they are left as they were.
     */
    bool
    solve_along_mode(VectorType   &u,
                     double        mode_load_factor,
                     double        load_factor,
                     double        energy_bound,
                     double       &eigenvalue,
                     JudgedResult *solved = nullptr);

    /// What solve_along_mode() found so far: the stable equilibrium of
    /// lowest energy below energy_bound (best_state empty if none), and
    /// whether any Newton solve from the mode converged at all.
    struct ModeSearch
    {
      VectorType                best;
      double                    energy_bound;
      double                    eigenvalue = std::nan("");
      std::optional<ModelState> best_state;
      JudgedResult              best_result;
      bool                      any_converged = false;
    };

    /// Newton at @p load_factor from @p u moved by @p distance along
    /// @p mode, both ways, into @p search; the model's state is @p u's on
    /// return.
    void
    search_both_ways(const VectorType          &u,
                     const std::vector<double> &mode,
                     double                     distance,
                     double                     load_factor,
                     ModeSearch                &search);

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

    /// Throws std::invalid_argument for a model that cannot be solved
    /// from @p u (see run()).
    void
    refuse_unsolvable(const VectorType &u);

    /// Stability (the inertia of the tangent), the Newton correction where
    /// @p result was rounding-limited, and the strain range of the
    /// converged @p u at info.load_factor, into @p info.
    void
    check_state(const VectorType   &u,
                const JudgedResult &result,
                StepInfo           &info);

    /// Warning lines for an unstable state, strains out of range, or a
    /// state that rounding leaves uncertain.
    void
    log_warnings(const StepInfo &info) const;

    /// Why a step from (@p u, @p load_factor) could fail for good: a
    /// singular tangent (a mechanism), naming where; empty otherwise.
    std::string
    singular_tangent(const VectorType &u, double load_factor);

    /**
     * Bisects the load factor between the stable equilibrium @p u_stable
     * (with its @p stable_state) at @p lambda_stable and an
     * unstable one at @p lambda_unstable, down to critical_load_tolerance,
     * by the inertia of the tangent (tangent_inertia(): the count of
     * negative pivots is exact where a dense eigenvalue of a stiff tangent
     * is only accurate to eps |K|); the critical load is the bracket's
     * midpoint.
     */
    void
    bisect_critical_load(const VectorType &u_stable,
                         const ModelState &stable_state,
                         double            lambda_stable,
                         double            lambda_unstable);

    /// Where the load path of run() stands between steps.
    struct LoadPath
    {
      double       lambda          = 0; ///< load factor of the last equilibrium
      double       step            = 0; ///< length of the next attempt
      unsigned int count           = 0; ///< converged steps
      bool         previous_stable = true;
      /// The equilibrium before the last converged step.
      VectorType previous;
      /// Change of the state over the last converged step, of length
      /// last_step (0: none to extrapolate).
      VectorType increment;
      double     last_step = 0;
      /// Wall time since the last equilibrium, over the attempts and cuts
      /// of the step from it (Parameters::max_step_time).
      dealii::Timer since_equilibrium;
    };

    /// The load factor the step of @p step from @p lambda aims at: never
    /// past the next point of the nominal grid k / n_steps.
    double
    next_load_factor(double lambda, double step) const;

    /**
     * Newton to @p target from the equilibrium @p u: from the predictor,
     * else from @p u, else (branch switching) from @p u displaced along its
     * buckling mode, which sets @p followed_mode. @p trial holds the
     * solution of a converged result.
     */
    JudgedResult
    attempt_step(const LoadPath   &path,
                 const VectorType &u,
                 double            target,
                 VectorType       &trial,
                 bool             &followed_mode);

    /// Writes to the log that the step's Newton solve from @p start failed
    /// (why: @p result's failure), the wall time the step took so far by
    /// @p timer, and that it tries again from @p next: a hard step can take
    /// several Newton solves, and a user sees where the time goes.
    void
    report_failed_attempt(double               target,
                          const std::string   &start,
                          const JudgedResult  &result,
                          const std::string   &next,
                          const dealii::Timer &timer) const;

    /// The branch-switch start of attempt_step(). Where it converges,
    /// @p result becomes that solve's and the model's reference is
    /// committed at @p trial; otherwise the model's state stays that of
    /// @p u.
    bool
    step_from_mode(const VectorType &u,
                   double            lambda,
                   double            target,
                   VectorType       &trial,
                   JudgedResult     &result);

    /// Halves the step after the failed @p result; throws SolverFailure
    /// below the minimum step.
    void
    cut_step(LoadPath           &path,
             const VectorType   &u,
             double              target,
             const JudgedResult &result);

    /**
     * Makes the converged @p trial at @p target the state @p u (the
     * reference reset, already done where the step @p followed_mode), then
     * the eigenvalue, the critical-load search from @p stable_state (the
     * state of @p u before the step, where a search is due) and the branch
     * switch it asks for, and the checks of the state.
     */
    StepInfo
    accept_step(LoadPath                        &path,
                VectorType                      &u,
                const VectorType                &trial,
                double                           target,
                const JudgedResult              &result,
                bool                             followed_mode,
                const std::optional<ModelState> &stable_state);

    /// bisect_critical_load(), after which the model's state is the
    /// unstable step's again; a failed search is logged, not thrown.
    void
    search_critical_load(const VectorType &u_stable,
                         const ModelState &stable_state,
                         double            lambda_stable,
                         double            lambda_unstable);

    /// From the unstable equilibrium @p u, to a stable one nearby of lower
    /// energy if there is one (solve_along_mode()).
    void
    switch_branch(VectorType &u, double load_factor, StepInfo &info);

    /// The log line of a converged step and its warnings.
    void
    report_step(const StepInfo &info) const;

    /// Negative eigenvalues of the constrained tangent at (@p u,
    /// @p load_factor), from its inertia.
    unsigned int
    negative_eigenvalues(const VectorType &u, double load_factor);

    SolvableModel    &model;
    Parameters        parameters;
    std::ostream     *log;
    ResidualCriterion criterion;
    StrainMonitor     strains;
    MatrixType        tangent;
    /// The tangent's factorization, kept across Newton solves.
    TangentFactorizationCache factorizations;
    /// Tangent without the support constraints, for linear_prediction().
    MatrixType unconstrained_tangent;
    double     critical_load = std::nan("");
  };
} // namespace rodnet

#endif
