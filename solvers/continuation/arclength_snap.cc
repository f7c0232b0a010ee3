#include <solvers/checks/equilibrium_check.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/newton/newton_globalization.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rodnet
{
  namespace
  {
    /// The fold is located to this fraction of the step that passed it.
    constexpr double fold_bracket = 1e-4;

    /// The jump lands this far past the fold's load factor (relative to
    /// max(1, |lambda|)): far enough that the fold's state is out of
    /// balance well above the tolerance, close enough to draw the jump as
    /// the vertical line of a load-controlled experiment.
    constexpr double snap_overshoot = 1e-3;

    /// A state past the fold found by Newton from the fold's is taken
    /// within this distance of it (W norm: model sizes, rad): the end of
    /// another branch there.
    constexpr double near_fold = 0.1;

    /// The descent from a fold to the state it snaps to takes the trust
    /// region some 400 iterations for the bent ribbon (N = 100 and 200),
    /// 75 for Lee's frame.
    constexpr unsigned int descent_iterations = 1000;
  } // namespace

  ArclengthContinuation::PathPoint
  ArclengthContinuation::locate_fold(const PathPoint &p,
                                     const double     ds,
                                     StepInfo        &info)
  {
    double       s_lo = 0, s_hi = ds, lambda_lo = p.lambda;
    VectorType   u_lo = p.u;
    JudgedResult result_lo;
    // A point between, for the sign of its dlambda/ds (its tangent
    // oriented along the chord from p, as the path's).
    PathPoint probe;
    probe.symmetries = p.symmetries;
    model.set_state(*p.state);
    while (s_hi - s_lo > fold_bracket * ds)
      {
        const double       s_mid = 0.5 * (s_lo + s_hi);
        double             lambda;
        const JudgedResult result =
          point_along(p, s_lo, u_lo, lambda_lo, s_mid, probe.u, lambda);
        if (!result.converged)
          // The bracket found so far: the fold lies within it.
          break;
        probe.lambda       = lambda;
        const VectorType u = probe.u;
        compute_tangent(probe, &p);
        // Before the turn: lambda still rising, and the critical
        // eigenvalue, which crosses zero there, not yet across. It is
        // counted as accept() will count it, from the state's own
        // reference: so close to zero, the other reference's tangent may
        // give it the other sign.
        model.reset_reference(probe.u);
        const bool before = probe.t_lambda > 0 &&
                            negative_eigenvalues(model,
                                                 probe.u,
                                                 lambda,
                                                 tangent,
                                                 &factorizations) == p.negative;
        model.set_state(*p.state);
        if (before)
          {
            s_lo      = s_mid;
            lambda_lo = lambda;
            u_lo      = u;
            result_lo = result;
          }
        else
          s_hi = s_mid;
      }
    model.set_state(*p.state);
    if (s_lo == 0)
      return p;
    return accept(u_lo, lambda_lo, &p, result_lo, info);
  }

  bool
  ArclengthContinuation::solve_past_fold(const PathPoint   &fold,
                                         const double       lambda,
                                         const std::string &line_search,
                                         const unsigned int iterations,
                                         const double       within,
                                         VectorType        &u,
                                         JudgedResult      &result,
                                         std::string       &tried)
  {
    StaticSolver::Parameters settings;
    settings.relative_tolerance      = parameters.relative_tolerance;
    settings.newton.linear_solver    = parameters.linear_solver;
    settings.newton.line_search      = line_search;
    settings.newton.max_iterations   = iterations;
    settings.branch_switch_amplitude = 0;
    StaticSolver solver(model, settings);
    model.set_state(*fold.state);
    u                = fold.u;
    result           = solver.solve_from_far_start(u, lambda);
    VectorType moved = u;
    moved -= fold.u;
    const double distance = std::sqrt(dot_w(moved, moved));
    std::string  outcome;
    if (!result.converged)
      outcome = result.failure;
    else if (distance > within)
      outcome = "a state " + number(distance) + " away";
    else if (const unsigned int negative =
               negative_eigenvalues(model, u, lambda, tangent, &factorizations);
             negative > 0)
      outcome = "an unstable state, " + std::to_string(negative) +
                " negative eigenvalue(s)";
    else
      return true;
    tried += (tried.empty() ? "" : "; ") +
             line_search_registry().traits(line_search).phrase +
             " from the fold's state: " + outcome;
    model.set_state(*fold.state);
    return false;
  }

  bool
  ArclengthContinuation::follow_to_load(const PathPoint &fold,
                                        const double     lambda,
                                        VectorType      &u,
                                        JudgedResult    &result,
                                        std::string     &tried)
  {
    PathPoint   p  = fold;
    double      ds = parameters.initial_step;
    std::string outcome =
      "does not come back to the load on a stable state within " +
      std::to_string(parameters.max_steps) +
      " points (entry \"Solver/Continuation/Max points\")";
    for (unsigned int points = 0; points < parameters.max_steps;)
      {
        double l = 0;
        if (!step(p, ds, u, l, result))
          {
            ds /= 2;
            if (ds >= parameters.min_step)
              continue;
            outcome = "stops at load factor " + number(p.lambda) + ": " +
                      result.failure;
            break;
          }
        ++points;
        double ds_taken = ds;
        if (p.lambda < lambda && l >= lambda &&
            land(p, lambda, u, l, result, ds_taken) &&
            negative_eigenvalues(model, u, lambda, tangent, &factorizations) ==
              0)
          return true;
        StepInfo  info;
        PathPoint q = accept(u, l, &p, result, info);
        p           = std::move(q);
        ds          = next_step_length(ds, result.iterations);
      }
    tried += (tried.empty() ? "" : "; ") +
             std::string("the path followed on from the fold ") + outcome;
    model.set_state(*fold.state);
    return false;
  }

  bool
  ArclengthContinuation::jump_past_fold(const PathPoint &fold,
                                        const double     lambda,
                                        VectorType      &u,
                                        JudgedResult    &result,
                                        std::string     &tried)
  {
    // Where the path folds onto the end of another branch (the over-curved
    // ring's lobes closing onto the triply covered ring), the state past
    // the fold lies next to the fold's: Newton finds it at once.
    if (solve_past_fold(fold,
                        lambda,
                        "full step",
                        25,
                        near_fold,
                        u,
                        result,
                        tried))
      return true;
    // Otherwise the structure moves away, down its energy, to a minimum:
    // the trust region descends the same way, leaving the fold along its
    // critical mode. Inextensible rods have no potential to descend (their
    // equilibria are stationary points of a Lagrangian).
    if (model.multiplier_dofs().empty())
      {
        if (log != nullptr)
          *log << "descending from the fold by the trust region" << std::endl;
        if (solve_past_fold(fold,
                            lambda,
                            "trust region",
                            descent_iterations,
                            std::numeric_limits<double>::infinity(),
                            u,
                            result,
                            tried))
          return true;
      }
    // Last, the path itself: through a snap-back it comes back to the load
    // on the branch the structure snaps to (Lee's frame, the deep arch).
    if (log != nullptr)
      *log << "following the path on from the fold to load factor "
           << number(lambda) << std::endl;
    return follow_to_load(fold, lambda, u, result, tried);
  }

  void
  ArclengthContinuation::snap(PathPoint      &p,
                              const double    ds,
                              const Observer &on_converged)
  {
    StepInfo fold_info;
    fold_info.kind       = PointKind::fold;
    const PathPoint fold = locate_fold(p, ds, fold_info);
    passed_limit_points.push_back(fold.lambda);
    if (log != nullptr)
      *log << "limit point at load factor " << number(fold.lambda)
           << ": the structure snaps (Limit points = snap)" << std::endl;
    if (fold.s != p.s)
      finish_point(fold_info, fold, on_converged);

    // Just past the fold, or on an output point or the range's end before.
    const double past =
      fold.lambda + snap_overshoot * std::max(1.0, std::abs(fold.lambda));
    const double target = crossed_target(fold.lambda, past).value_or(past);
    VectorType   u      = fold.u;
    JudgedResult result;
    std::string  tried;
    if (!jump_past_fold(fold, target, u, result, tried))
      throw SolverFailure("the structure snaps at the limit point at load "
                          "factor " +
                          number(fold.lambda) +
                          ", but no stable equilibrium was found past it at "
                          "load factor " +
                          number(target) + " (" + tried + ")");

    VectorType jump = u;
    jump -= fold.u;
    const double length = std::sqrt(
      dot_w(jump, jump) + (target - fold.lambda) * (target - fold.lambda));
    StepInfo info;
    info.kind = PointKind::jump;
    // The new branch starts with the load factor rising.
    PathPoint landed = accept(u, target, nullptr, result, info);
    landed.s         = fold.s + length;
    info.arclength   = landed.s;
    ++branch;
    points_on_path = 0;
    just_switched  = false;
    if (log != nullptr)
      *log << "jump at load factor " << number(target) << " to a stable state "
           << number(length) << " away (W norm: model sizes, rad), branch "
           << branch << std::endl;
    finish_point(info, landed, on_converged);
    p = std::move(landed);
  }
} // namespace rodnet
