// StaticSolver's load-step loop (run()): the step to the next load factor,
// its cutting on failure, and what follows a converged step (the
// critical-load search, the branch switch, the checks and the report).
#include <deal.II/base/timer.h>

#include <solvers/state_guard.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace rodnet
{
  void
  StaticSolver::run(VectorType &u, const Observer &on_converged)
  {
    const double nominal = 1.0 / parameters.n_steps;
    LoadPath     path;
    path.step     = nominal;
    path.previous = u;
    // Quaternion increments included: they are zeroed by the reference
    // reset, so they are taken before it.
    path.increment = u;
    path.increment = 0;
    refuse_unsolvable(u);

    while (path.lambda < 1.0 - 1e-12)
      {
        dealii::Timer timer;
        const double  target     = next_load_factor(path.lambda, path.step);
        path.step                = target - path.lambda;
        VectorType trial         = u;
        bool       followed_mode = false;
        // The state of u, where a critical-load search may start from it:
        // taken before the attempt, which may commit the trial's.
        const std::optional<ModelState> stable_state =
          parameters.find_critical_load && std::isnan(critical_load) &&
              path.previous_stable ?
            std::optional<ModelState>(model.state()) :
            std::nullopt;
        JudgedResult result =
          attempt_step(path, u, target, trial, followed_mode);
        if (!result.converged)
          {
            cut_step(path, u, target, result);
            continue;
          }
        StepInfo info  = accept_step(path,
                                    u,
                                    trial,
                                    target,
                                    result,
                                    followed_mode,
                                    stable_state);
        info.wall_time = timer.wall_time();
        if (log != nullptr)
          report_step(info);
        on_converged(info, u);
        path.since_equilibrium.restart();

        path.previous_stable = info.check.stable;
        path.lambda          = target;
        path.step            = std::min(2 * path.step, nominal);
      }
  }

  double
  StaticSolver::next_load_factor(const double lambda, const double step) const
  {
    // Cut steps never skip a point of the nominal grid k / n_steps, so that
    // outputs land on the loads the scene asked for; a target within
    // rounding of a grid point is snapped to it, or the sum of cut steps
    // would stop just short of it and leave a sliver of a step.
    const double nominal = 1.0 / parameters.n_steps;
    const double snap    = 1e-6 * nominal;
    const double next_grid =
      std::min((std::floor((lambda + snap) / nominal) + 1) * nominal, 1.0);
    return lambda + step > next_grid - snap ? next_grid : lambda + step;
  }

  JudgedResult
  StaticSolver::attempt_step(const LoadPath   &path,
                             const VectorType &u,
                             const double      target,
                             VectorType       &trial,
                             bool             &followed_mode)
  {
    JudgedResult result;
    try
      {
        // A prescribed rotation's increment from the step's start cannot
        // tell a turn of half a turn or more from a shorter one the other
        // way (SolvableModel::check_rotation_step()): a shorter step turns
        // less.
        model.check_rotation_step(path.lambda, target);
      }
    catch (const std::runtime_error &e)
      {
        result.failure = e.what();
        return result;
      }
    const bool    recover_from_mode = parameters.branch_switch_amplitude > 0;
    dealii::Timer timer;
    if (parameters.predict)
      {
        // With an increment to follow, extrapolate it; without one (first
        // step, after a branch switch) let the free DoFs follow the
        // prescribed ones to first order. Displacement-driven steps
        // otherwise move only the prescribed DoFs in the first iterate, a
        // strain concentrated in one segment that grows with N.
        const bool predicted =
          path.last_step > 0 ?
            (trial.add(path.step / path.last_step, path.increment), true) :
            linear_prediction(u, target, trial);
        if (predicted)
          {
            result = solve_at(trial, target, nullptr, &u);
            if (!result.converged)
              {
                trial = u;
                report_failed_attempt(target,
                                      "the prediction",
                                      result,
                                      "the last equilibrium",
                                      timer);
              }
          }
      }
    if (!result.converged)
      {
        result = solve_at(trial, target);
        if (!result.converged && recover_from_mode)
          report_failed_attempt(target,
                                "the last equilibrium",
                                result,
                                "its buckling mode",
                                timer);
      }
    if (!result.converged && recover_from_mode)
      followed_mode = step_from_mode(u, path.lambda, target, trial, result);
    return result;
  }

  void
  StaticSolver::report_failed_attempt(const double         target,
                                      const std::string   &start,
                                      const JudgedResult  &result,
                                      const std::string   &next,
                                      const dealii::Timer &timer) const
  {
    if (log == nullptr)
      return;
    char time[32];
    std::snprintf(time, sizeof(time), "%.3g s", timer.wall_time());
    *log << "  step to load factor " << target << ": Newton from " << start
         << " failed: " << result.failure << "; " << time
         << " in this step so far; trying from " << next << std::endl;
  }

  bool
  StaticSolver::step_from_mode(const VectorType &u,
                               const double      lambda,
                               const double      target,
                               VectorType       &trial,
                               JudgedResult     &result)
  {
    // Past a bifurcation the Newton step from the previous state (whose
    // tangent is nearly singular there) diverges; start instead from the
    // previous state displaced along its buckling mode. solve_along_mode()
    // commits the reference at the equilibrium it finds and zeroes the
    // trial's quaternion increments: the step is accepted with that
    // reference. The previous one would pair the trial with the frames and
    // junction rotations of the step before (issue 33: a stale rotation,
    // a junction kinked by the step's turn).
    VectorType   start = u;
    double       mu    = std::nan("");
    JudgedResult solved;
    if (!solve_along_mode(start,
                          lambda,
                          target,
                          std::numeric_limits<double>::max(),
                          mu,
                          &solved))
      return false;
    trial  = start;
    result = solved;
    if (log != nullptr)
      *log << "  step to load factor " << target
           << " converged from the buckling mode" << std::endl;
    return true;
  }

  void
  StaticSolver::cut_step(LoadPath           &path,
                         const VectorType   &u,
                         const double        target,
                         const JudgedResult &result)
  {
    const double spent = path.since_equilibrium.wall_time();
    if (parameters.max_step_time > 0 && spent > parameters.max_step_time)
      {
        char times[96];
        std::snprintf(times,
                      sizeof(times),
                      "%.3g s, more than Solver/Max step time = %.3g s",
                      spent,
                      parameters.max_step_time);
        throw SolverFailure("the load step from load factor " +
                            std::to_string(path.lambda) + " has taken " +
                            times + ", without converging (last attempt, to " +
                            std::to_string(target) + ": " + result.failure +
                            "); raise the bound or take more load steps "
                            "(Loads/Steps)");
      }
    if (log != nullptr)
      *log << "  step to load factor " << target << " failed ("
           << result.failure << "); cutting the step" << std::endl;
    path.step *= 0.5;
    const double minimum =
      1.0 / parameters.n_steps * parameters.min_step_fraction;
    if (path.step < minimum)
      throw SolverFailure(
        "the load step from load factor " + std::to_string(path.lambda) +
        " failed: " + result.failure +
        "; the step was cut below "
        "the minimum " +
        std::to_string(minimum) + " (Solver/Minimum step fraction)" +
        singular_tangent(u, path.lambda));
  }

  StaticSolver::StepInfo
  StaticSolver::accept_step(LoadPath                        &path,
                            VectorType                      &u,
                            const VectorType                &trial,
                            const double                     target,
                            const JudgedResult              &result,
                            const bool                       followed_mode,
                            const std::optional<ModelState> &stable_state)
  {
    path.increment = trial;
    path.increment -= u;
    path.last_step = followed_mode ? 0 : path.step;
    path.previous  = u;
    u              = trial;
    // From the buckling mode the reference is committed at the trial
    // already (step_from_mode()).
    if (!followed_mode)
      model.reset_reference(u);

    StepInfo info;
    info.step        = ++path.count;
    info.load_factor = target;
    info.iterations  = result.iterations;
    info.residual    = result.residual;
    if (parameters.track_lowest_eigenvalue)
      info.lowest_eigenvalue = lowest_eigenvalue(u, target);
    if (stable_state && negative_eigenvalues(u, target) > 0)
      search_critical_load(path.previous, *stable_state, path.lambda, target);
    check_state(u, result, info);
    // The stability check (its inertia, symmetry modes left out) decides:
    // a stable step costs no eigen-solve.
    if (parameters.branch_switch_amplitude > 0 && !info.check.stable)
      {
        if (std::isnan(info.lowest_eigenvalue))
          info.lowest_eigenvalue = lowest_eigenvalue(u, target);
        switch_branch(u, target, info);
        // The switch jumps between branches: no increment to follow.
        path.last_step = 0;
        check_state(u, result, info);
      }
    return info;
  }

  void
  StaticSolver::search_critical_load(const VectorType &u_stable,
                                     const ModelState &stable_state,
                                     const double      lambda_stable,
                                     const double      lambda_unstable)
  {
    // The load path goes on from the unstable step's state.
    const StateGuard unstable(model);
    try
      {
        bisect_critical_load(u_stable,
                             stable_state,
                             lambda_stable,
                             lambda_unstable);
      }
    catch (const SolverFailure &e)
      {
        if (log != nullptr)
          *log << "  critical load search abandoned: " << e.what() << std::endl;
      }
  }

  void
  StaticSolver::switch_branch(VectorType  &u,
                              const double load_factor,
                              StepInfo    &info)
  {
    const double unstable = info.lowest_eigenvalue;
    const bool   found =
      solve_along_mode(u,
                       load_factor,
                       load_factor,
                       model.assemble(u, load_factor, nullptr, nullptr),
                       info.lowest_eigenvalue);
    if (log != nullptr)
      *log << "  unstable equilibrium (lowest eigenvalue " << unstable << "): "
           << (found ? "switched to a stable branch" :
                       "no stable branch found nearby")
           << std::endl;
  }

  void
  StaticSolver::report_step(const StepInfo &info) const
  {
    char line[200];
    std::snprintf(line,
                  sizeof(line),
                  "step %4u  load factor %.6f  iterations %2u  "
                  "residual %.2e N, %.2e N m  time %.3f s",
                  info.step,
                  info.load_factor,
                  info.iterations,
                  info.residual.force,
                  info.residual.moment,
                  info.wall_time);
    *log << line;
    if (!std::isnan(info.lowest_eigenvalue))
      *log << "  lowest eigenvalue " << info.lowest_eigenvalue;
    *log << std::endl;
    log_warnings(info);
  }
} // namespace rodnet
