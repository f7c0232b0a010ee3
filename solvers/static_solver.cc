#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <solvers/equilibrium_check.h>
#include <solvers/free_motions.h>
#include <solvers/stability.h>
#include <solvers/static_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rodnet
{
  StaticSolver::StaticSolver(RodModel         &model,
                             const Parameters &parameters,
                             std::ostream     *log)
      : model(model)
      , parameters(parameters)
      , log(log)
      , criterion(model)
      , strains(model, parameters.strain_limits)
  {
    if (parameters.n_steps < 1)
      throw std::invalid_argument("the number of load steps must be >= 1");
    if (model.has_internal_variables())
      // Load steps have no time: a history-dependent material would answer
      // with an arbitrary rate.
      throw std::invalid_argument(
        "static load stepping cannot solve a material with internal "
        "variables (a viscoelastic law): its response depends on time; "
        "use time stepping (quasi-static or dynamic, doc/dynamics.md)");
    model.initialize_matrix(tangent);
  }

  JudgedResult
  StaticSolver::solve_at(VectorType       &u,
                         const double      load_factor,
                         const VectorType *extra_force,
                         const VectorType *scale_state,
                         const bool        far_start)
  {
    model.apply_boundary_values(u, load_factor);
    ResidualParts         tolerance, reached;
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &x, VectorType &r) {
      model.assemble(x, load_factor, &r, nullptr, true, extra_force);
    };
    problem.tangent = [&](const VectorType &x, MatrixType &k) {
      model.assemble(x, load_factor, nullptr, &k, true, extra_force);
    };
    problem.converged = criterion.newton_test(tolerance, reached);

    JudgedResult  outcome;
    ResidualParts scale;
    RoundoffNoise noise;
    try
      {
        VectorType start = scale_state != nullptr ? *scale_state : u;
        model.apply_boundary_values(start, load_factor);
        scale        = criterion.load_scale(start, load_factor, extra_force);
        VectorType r = model.create_vector();
        model.assemble(u, load_factor, &r, &tangent, true, extra_force);
        noise = criterion.roundoff_noise(u, load_factor, extra_force);
        if (far_start)
          {
            const ResidualParts out_of_balance = criterion.norms(u, r);
            scale.force  = std::max(scale.force, out_of_balance.force);
            scale.moment = std::max(scale.moment, out_of_balance.moment);
          }
      }
    catch (const std::exception &e)
      {
        outcome.failure = e.what();
        return outcome;
      }

    // The reactions in the scale are those of the start; the solution's
    // are what counts. Where they ask for a tighter tolerance, Newton goes
    // on from the solution. The noise hardly changes within a step: it is
    // measured at the start only.
    unsigned int iterations = 0;
    outcome.noise           = noise;
    for (unsigned int round = 0; round < 3; ++round)
      {
        tolerance = ResidualCriterion::tolerance(scale,
                                                 noise.floor,
                                                 parameters.relative_tolerance);
        static_cast<NewtonSolver::Result &>(outcome) =
          NewtonSolver(parameters.newton).solve(problem, u, tangent);
        iterations += outcome.iterations;
        outcome.iterations = iterations;
        outcome.residual   = reached;
        if (!outcome.converged)
          {
            outcome.failure +=
              "; " + ResidualCriterion::describe(reached, tolerance);
            return outcome;
          }
        try
          {
            scale = criterion.load_scale(u, load_factor, extra_force);
          }
        catch (const std::exception &e)
          {
            outcome.converged = false;
            outcome.failure   = e.what();
            return outcome;
          }
        const ResidualParts judged =
          ResidualCriterion::tolerance(scale,
                                       noise.floor,
                                       parameters.relative_tolerance);
        if (far_start || ResidualCriterion::within(reached, judged))
          {
            outcome.scale = scale;
            outcome.rounding_limited =
              ResidualCriterion::inconclusive(noise.floor,
                                              scale,
                                              parameters.rounding_floor_limit);
            return outcome;
          }
      }
    outcome.converged = false;
    outcome.failure   = "the reactions kept changing the tolerance";
    return outcome;
  }

  bool
  StaticSolver::linear_prediction(const VectorType &u,
                                  const double      load_factor,
                                  VectorType       &trial)
  {
    VectorType moved = u;
    model.apply_boundary_values(moved, load_factor);
    VectorType prescribed_change = moved;
    prescribed_change -= u;
    if (prescribed_change.linfty_norm() == 0)
      return false;
    try
      {
        if (unconstrained_tangent.m() == 0)
          model.initialize_matrix(unconstrained_tangent);
        VectorType r = model.create_vector();
        model.assemble(u, load_factor, &r, &unconstrained_tangent, false);
        // K_ff du_f = -r_f - K_fc du_c, with du_c the prescribed change.
        VectorType rhs = model.create_vector();
        unconstrained_tangent.vmult(rhs, prescribed_change);
        rhs += r;
        rhs *= -1.0;
        model.constraints().set_zero(rhs);
        model.assemble(u, load_factor, nullptr, &tangent, true);
        VectorType                             du = model.create_vector();
        dealii::SolverControl                  control(1, 0);
        dealii::TrilinosWrappers::SolverDirect direct(control);
        direct.solve(tangent, du, rhs);
        trial = moved;
        trial += du;
        return std::isfinite(trial.l2_norm());
      }
    catch (const std::exception &)
      {
        // A tangent that cannot be built or factored: start unpredicted.
        return false;
      }
  }

  void
  StaticSolver::refuse_unsolvable(const VectorType &u)
  {
    const std::string free_motions = describe_free_motions(model, u);
    if (!free_motions.empty())
      throw std::invalid_argument(free_motions);
  }

  ResidualParts
  StaticSolver::solved_residual(const VectorType &u, const double load_factor)
  {
    VectorType r = model.create_vector();
    model.assemble(u, load_factor, &r, nullptr, true);
    return criterion.norms(u, r);
  }

  unsigned int
  StaticSolver::negative_eigenvalues(const VectorType &u,
                                     const double      load_factor)
  {
    model.assemble(u, load_factor, nullptr, &tangent, true);
    return tangent_inertia(tangent, model.constraints()).negative;
  }

  void
  StaticSolver::check_state(const VectorType   &u,
                            const JudgedResult &result,
                            StepInfo           &info)
  {
    info.check  = check_equilibrium(model,
                                   criterion,
                                   u,
                                   info.load_factor,
                                   tangent,
                                   result,
                                   parameters.rounding_uncertainty_limit);
    refuse_undetermined_state(info.check,
                              parameters.rounding_failure_limit,
                              "load factor " +
                                std::to_string(info.load_factor));
    info.strain = strains.evaluate(u);
  }

  void
  StaticSolver::log_warnings(const StepInfo &info) const
  {
    if (!info.check.stable)
      *log << "warning: the equilibrium at load factor " << info.load_factor
           << " is unstable: its tangent has "
           << info.check.negative_eigenvalues
           << " negative eigenvalue(s); any imperfection leaves it (Solver/"
              "Branch switching amplitude follows a stable branch)"
           << std::endl;
    const std::string strain_warning = strains.warning(info.strain);
    if (!strain_warning.empty())
      *log << strain_warning << std::endl;
    if (!info.check.rounding_warning.empty())
      *log << "warning: rounding leaves the state at load factor "
           << info.load_factor << " uncertain by "
           << info.check.rounding_uncertainty
           << " of the model size (the Newton correction of its residual; "
           << parameters.rounding_uncertainty_limit
           << " allowed): " << info.check.rounding_warning << std::endl;
  }

  std::string
  StaticSolver::singular_tangent(const VectorType &u, const double load_factor)
  {
    Inertia inertia;
    try
      {
        model.assemble(u, load_factor, nullptr, &tangent, true);
        inertia = tangent_inertia(tangent, model.constraints());
      }
    catch (const std::exception &)
      {
        return "";
      }
    if (inertia.zero == 0)
      return "";
    char ratio[32];
    std::snprintf(ratio, sizeof(ratio), "%.1e", inertia.weakest_ratio);
    const std::string where =
      inertia.weakest_dof == dealii::numbers::invalid_unsigned_int ?
        "an exactly zero pivot" :
        "a pivot of " + std::string(ratio) + " times its diagonal, at " +
          criterion.roles().describe(inertia.weakest_dof);
    return "; the tangent at load factor " + std::to_string(load_factor) +
           " is singular (" + where +
           "): part of the structure can move without deforming (a "
           "mechanism); hold it with a support or stiffen its joints";
  }

  double
  StaticSolver::lowest_eigenvalue(const VectorType &u, const double load_factor)
  {
    model.assemble(u, load_factor, nullptr, &tangent);
    const std::vector<double> values =
      lowest_eigenvalues(tangent, model.constraints(), 1);
    return values.empty() ? std::nan("") : values[0];
  }

  void
  StaticSolver::run(VectorType &u, const Observer &on_converged)
  {
    const double nominal         = 1.0 / parameters.n_steps;
    const double minimum         = nominal * parameters.min_step_fraction;
    double       lambda          = 0;
    double       step            = nominal;
    unsigned int count           = 0;
    bool         previous_stable = true;
    VectorType   previous        = u;
    // Change of the state over the last converged step (of length
    // last_step), quaternion increments included: they are zeroed by the
    // reference reset, so they are taken before it.
    VectorType increment = u;
    increment            = 0;
    double last_step     = 0;
    refuse_unsolvable(u);

    while (lambda < 1.0 - 1e-12)
      {
        dealii::Timer timer;
        // Cut steps never skip a point of the nominal grid k / n_steps, so
        // that outputs land on the loads the scene asked for; a target within
        // rounding of a grid point is snapped to it, or the sum of cut steps
        // would stop just short of it and leave a sliver of a step.
        const double snap = 1e-6 * nominal;
        const double next_grid =
          std::min((std::floor((lambda + snap) / nominal) + 1) * nominal, 1.0);
        const double target =
          lambda + step > next_grid - snap ? next_grid : lambda + step;
        step               = target - lambda;
        VectorType   trial = u;
        JudgedResult result;
        if (parameters.predict)
          {
            // With an increment to follow, extrapolate it; without one
            // (first step, after a branch switch) let the free DoFs follow
            // the prescribed ones to first order. Displacement-driven steps
            // otherwise move only the prescribed DoFs in the first iterate,
            // a strain concentrated in one segment that grows with N.
            const bool predicted =
              last_step > 0 ? (trial.add(step / last_step, increment), true) :
                              linear_prediction(u, target, trial);
            if (predicted)
              {
                result = solve_at(trial, target, nullptr, &u);
                if (!result.converged)
                  trial = u;
              }
          }
        if (!result.converged)
          result = solve_at(trial, target);
        bool followed_mode = false;
        if (!result.converged && parameters.branch_switch_amplitude > 0)
          {
            // Past a bifurcation the Newton step from the previous state
            // (whose tangent is nearly singular there) diverges; start
            // instead from the previous state displaced along its buckling
            // mode.
            VectorType          start                  = u;
            double              mu                     = std::nan("");
            const Configuration previous_configuration = model.configuration();
            if (solve_along_mode(start,
                                 lambda,
                                 target,
                                 std::numeric_limits<double>::max(),
                                 mu))
              {
                trial                 = start;
                result.converged      = true;
                result.residual       = solved_residual(trial, target);
                followed_mode         = true;
                model.configuration() = previous_configuration;
                if (log != nullptr)
                  *log << "  step to load factor " << target
                       << " converged from the buckling mode" << std::endl;
              }
            else
              model.configuration() = previous_configuration;
          }
        if (!result.converged)
          {
            if (log != nullptr)
              *log << "  step to load factor " << target << " failed ("
                   << result.failure << "); cutting the step" << std::endl;
            step *= 0.5;
            if (step < minimum)
              throw SolverFailure(
                "the load step from load factor " + std::to_string(lambda) +
                " failed: " + result.failure +
                "; the step was cut below "
                "the minimum " +
                std::to_string(minimum) + " (Solver/Minimum step fraction)" +
                singular_tangent(u, lambda));
            continue;
          }

        const Configuration stable_configuration = model.configuration();
        increment                                = trial;
        increment -= u;
        last_step = followed_mode ? 0 : step;
        previous  = u;
        u         = trial;
        model.reset_reference(u);

        StepInfo info;
        info.step        = ++count;
        info.load_factor = target;
        info.iterations  = result.iterations;
        info.residual    = result.residual;
        if (parameters.track_lowest_eigenvalue ||
            parameters.branch_switch_amplitude > 0)
          info.lowest_eigenvalue = lowest_eigenvalue(u, target);

        if (parameters.find_critical_load && std::isnan(critical_load) &&
            previous_stable && negative_eigenvalues(u, target) > 0)
          {
            const Configuration unstable_configuration = model.configuration();
            try
              {
                bisect_critical_load(previous,
                                     stable_configuration,
                                     lambda,
                                     target);
              }
            catch (const SolverFailure &e)
              {
                if (log != nullptr)
                  *log << "  critical load search abandoned: " << e.what()
                       << std::endl;
              }
            model.configuration() = unstable_configuration;
          }
        if (parameters.branch_switch_amplitude > 0 &&
            info.lowest_eigenvalue < 0)
          {
            const double unstable = info.lowest_eigenvalue;
            const bool   found =
              solve_along_mode(u,
                               target,
                               target,
                               model.assemble(u, target, nullptr, nullptr),
                               info.lowest_eigenvalue);
            // The switch jumps between branches: no increment to follow.
            last_step = 0;
            if (log != nullptr)
              *log << "  unstable equilibrium (lowest eigenvalue " << unstable
                   << "): "
                   << (found ? "switched to a stable branch" :
                               "no stable branch found nearby")
                   << std::endl;
          }
        check_state(u, result, info);
        info.wall_time = timer.wall_time();

        if (log != nullptr)
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
        on_converged(info, u);

        previous_stable = info.check.stable;
        lambda          = target;
        step            = std::min(2 * step, nominal);
      }
  }

  bool
  StaticSolver::solve_along_mode(VectorType  &u,
                                 const double mode_load_factor,
                                 const double load_factor,
                                 double       energy_bound,
                                 double      &eigenvalue)
  {
    model.assemble(u, mode_load_factor, nullptr, &tangent);
    const std::vector<double> mode =
      lowest_eigenpair(tangent, model.constraints()).second;
    // Displace the state along the mode so that its largest component
    // moves by the given fraction of the model size, and let Newton find
    // the equilibrium nearby, on both sides.
    double largest = 0;
    for (const double m : mode)
      largest = std::max(largest, std::abs(m));
    const double amplitude =
      parameters.branch_switch_amplitude * model.length_scale() / largest;

    const Configuration start_configuration = model.configuration();
    Configuration       best_configuration  = start_configuration;
    VectorType          best                = u;
    bool                found               = false;
    for (const double sign : {1.0, -1.0})
      {
        model.configuration() = start_configuration;
        VectorType trial      = u;
        for (unsigned int i = 0; i < mode.size(); ++i)
          trial[i] += sign * amplitude * mode[i];
        trial.compress(dealii::VectorOperation::add);
        if (!solve_at(trial, load_factor, nullptr, nullptr, true).converged)
          continue;
        model.reset_reference(trial);
        const double energy =
          model.assemble(trial, load_factor, nullptr, nullptr);
        const double mu = lowest_eigenvalue(trial, load_factor);
        if (mu > 0 && energy < energy_bound)
          {
            energy_bound       = energy;
            eigenvalue         = mu;
            best               = trial;
            best_configuration = model.configuration();
            found              = true;
          }
      }
    model.configuration() = best_configuration;
    u                     = best;
    return found;
  }

  void
  StaticSolver::bisect_critical_load(const VectorType    &u_stable,
                                     const Configuration &stable_configuration,
                                     double               lambda_stable,
                                     double               lambda_unstable)
  {
    VectorType    u_lo   = u_stable;
    Configuration config = stable_configuration;
    while (lambda_unstable - lambda_stable > parameters.critical_load_tolerance)
      {
        const double lambda_mid = 0.5 * (lambda_stable + lambda_unstable);
        model.configuration()   = config;
        VectorType                 u_mid  = u_lo;
        const NewtonSolver::Result result = solve_at(u_mid, lambda_mid);
        if (!result.converged)
          throw SolverFailure("bisection for the critical load failed at load "
                              "factor " +
                              std::to_string(lambda_mid) + ": " +
                              result.failure);
        model.reset_reference(u_mid);
        if (negative_eigenvalues(u_mid, lambda_mid) == 0)
          {
            lambda_stable = lambda_mid;
            u_lo          = u_mid;
            config        = model.configuration();
          }
        else
          lambda_unstable = lambda_mid;
      }
    critical_load = 0.5 * (lambda_stable + lambda_unstable);
    if (log != nullptr)
      *log << "critical load factor " << critical_load
           << " (the tangent's lowest eigenvalue crosses zero)" << std::endl;
  }
} // namespace rodnet
