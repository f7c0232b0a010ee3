#include <solvers/checks/free_motions.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/continuation/limit_point_estimate.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>

namespace rodnet
{
  bool
  ArclengthContinuation::land(const PathPoint &p,
                              const double     target,
                              VectorType      &u,
                              double          &lambda,
                              JudgedResult    &result,
                              double          &ds)
  {
    // From the chord's point at the target, Newton at fixed lambda.
    const double f        = (target - p.lambda) / (lambda - p.lambda);
    VectorType   u_target = p.u;
    u_target.sadd(1 - f, f, u);
    double lambda_target = target;
    model.set_state(*p.state);
    JudgedResult landed = correct(p,
                                  Constraint{nullptr, 1, target - p.lambda},
                                  u_target,
                                  lambda_target);
    if (!landed.converged)
      return false;
    landed.iterations += result.iterations;
    VectorType chord = u_target;
    chord -= p.u;
    ds     = dot_w(p.t_u, chord) + p.t_lambda * (target - p.lambda);
    u      = u_target;
    lambda = target;
    result = landed;
    return true;
  }

  void
  ArclengthContinuation::finish_point(StepInfo        &info,
                                      const PathPoint &p,
                                      const Observer  &on_converged)
  {
    info.step      = n_points++;
    info.branch    = branch;
    info.wall_time = timer.wall_time();
    timer.restart();
    report(info);
    on_converged(info, p.u);
    recent = {{recent[1], recent[2], {p.s, p.lambda}}};
    ++points_on_path;
  }

  void
  ArclengthContinuation::run(VectorType &u, const Observer &on_converged)
  {
    const std::string free_motions = describe_free_motions(model, u);
    if (!free_motions.empty())
      throw std::invalid_argument(free_motions);
    timer.restart();
    n_points       = 0;
    points_on_path = 0;
    branch         = 0;
    recent         = {};
    other_sides.clear();

    // The start: the equilibrium at load factor 0 nearest to u.
    PathPoint origin;
    origin.u            = u;
    origin.state        = model.state();
    double       zero   = 0;
    JudgedResult result = correct(origin, Constraint{nullptr, 1, 0}, u, zero);
    if (!result.converged)
      throw SolverFailure("no equilibrium at load factor 0 from the start: " +
                          result.failure);
    StepInfo  info;
    PathPoint p = accept(u, 0, nullptr, result, info);
    finish_point(info, p, on_converged);

    follow_path(p, parameters.initial_step, on_converged);
    u = p.u;
    // The other sides of the switched branches, each from its bifurcation
    // (follow_both_branches); the path's last point stays u's.
    while (!other_sides.empty())
      {
        auto [start, start_info] = other_sides.front();
        other_sides.erase(other_sides.begin());
        ++branch;
        if (log != nullptr)
          *log << "branch " << branch << ": the other side of the "
               << "bifurcation at load factor " << number(start.lambda)
               << std::endl;
        points_on_path = 0;
        just_switched  = true;
        model.set_state(*start.state);
        finish_point(start_info, start, on_converged);
        follow_path(start, parameters.initial_step, on_converged);
      }
  }

  void
  ArclengthContinuation::follow_path(PathPoint      &p,
                                     double          ds,
                                     const Observer &on_converged)
  {
    StepInfo     info;
    JudgedResult result;
    while (p.lambda < parameters.upper_limit &&
           p.lambda > parameters.lower_limit)
      {
        check_points_left(p);
        VectorType next   = p.u;
        double     lambda = 0, ds_taken = ds;
        info = StepInfo();
        if (!step_onto_path(p, ds_taken, next, lambda, result, info))
          {
            ds /= 2;
            if (ds < parameters.min_step)
              throw SolverFailure(
                "the continuation step from load factor " + number(p.lambda) +
                " failed down to the smallest step length (entry \"Solver/"
                "Continuation/Minimum step\"): " +
                result.failure);
            continue;
          }
        PathPoint q = accept(next, lambda, &p, result, info);
        if (q.t_lambda * p.t_lambda < 0 && parameters.snap_at_limit_points &&
            p.t_lambda > 0)
          {
            snap(p, ds_taken, on_converged);
            ds = parameters.initial_step;
            continue;
          }
        if (q.t_lambda * p.t_lambda < 0)
          note_limit_point(p, q, info);
        else if (q.negative != p.negative && !just_switched)
          {
            if (follow_bifurcation(p, q, ds_taken, info, on_converged))
              continue;
            // No path from p keeps its count up to q: the step jumped onto
            // another branch. A shorter one stays on this path.
            ds = ds_taken / 2;
            continue;
          }
        just_switched = false;
        finish_point(info, q, on_converged);
        p  = q;
        ds = next_step_length(ds, result.iterations);
      }
  }

  void
  ArclengthContinuation::check_points_left(const PathPoint &p) const
  {
    if (n_points > parameters.max_steps)
      throw SolverFailure(
        "the path did not leave the load factors [" +
        number(parameters.lower_limit) + ", " + number(parameters.upper_limit) +
        "] within " + std::to_string(parameters.max_steps) +
        " points (entry \"Solver/Continuation/Max points\"); it stands "
        "at load factor " +
        number(p.lambda));
  }

  bool
  ArclengthContinuation::step_onto_path(const PathPoint &p,
                                        double          &ds,
                                        VectorType      &u,
                                        double          &lambda,
                                        JudgedResult    &result,
                                        StepInfo        &info)
  {
    if (!step(p, ds, u, lambda, result))
      return false;
    const std::optional<double> target = crossed_target(p.lambda, lambda);
    if (!target)
      return true;
    if (!land(p, *target, u, lambda, result, ds))
      return false;
    info.kind = PointKind::output_point;
    return true;
  }

  void
  ArclengthContinuation::note_limit_point(const PathPoint &p,
                                          const PathPoint &q,
                                          StepInfo        &info)
  {
    info.kind = PointKind::limit_point;
    passed_limit_points.push_back(
      points_on_path >= 2 ?
        parabola_extremum({{recent[1], recent[2], {q.s, q.lambda}}}) :
        slope_extremum(p.s, p.lambda, p.t_lambda, q.s, q.t_lambda));
    if (log != nullptr)
      *log << "limit point at load factor " << std::setprecision(10)
           << passed_limit_points.back() << std::setprecision(6)
           << " (estimated from the points around it)" << std::endl;
  }

  double
  ArclengthContinuation::next_step_length(const double       ds,
                                          const unsigned int iterations) const
  {
    return std::min(parameters.max_step,
                    ds * std::clamp(double(parameters.target_iterations) /
                                      std::max(1u, iterations),
                                    0.5,
                                    2.0));
  }

  bool
  ArclengthContinuation::follow_bifurcation(PathPoint       &p,
                                            const PathPoint &q,
                                            const double     ds,
                                            StepInfo        &q_info,
                                            const Observer  &on_converged)
  {
    StepInfo  info;
    PathPoint b;
    try
      {
        b = locate_bifurcation(p, q, ds, info);
      }
    catch (const SolverFailure &e)
      {
        if (ds / 2 < parameters.min_step)
          throw;
        model.set_state(*p.state);
        if (log != nullptr)
          *log << "the step to load factor " << number(q.lambda)
               << " changed the tangent's negative eigenvalues, but the path "
                  "does not reach that point ("
               << e.what()
               << "): a jump onto another branch; the step is halved"
               << std::endl;
        return false;
      }
    if (log != nullptr)
      *log << "bifurcation at load factor " << std::setprecision(10)
           << located_bifurcations.back() << std::setprecision(6)
           << ": the tangent's negative eigenvalues go from " << p.negative
           << " to " << q.negative << std::endl;
    info.kind = PointKind::bifurcation;
    if (b.s != p.s)
      finish_point(info, b, on_converged);
    if (!parameters.switch_branches)
      {
        finish_point(q_info, q, on_converged);
        p = q;
        return true;
      }
    turn_to_null_vector(b);
    if (parameters.follow_both_branches)
      {
        PathPoint other = b;
        other.t_u *= -1;
        other.t_lambda *= -1;
        other_sides.emplace_back(std::move(other), info);
      }
    p             = b;
    just_switched = true;
    ++branch;
    return true;
  }
} // namespace rodnet
