#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

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

  NewtonSolver::Result
  StaticSolver::solve_at(VectorType       &u,
                         const double      load_factor,
                         const VectorType *extra_force,
                         const VectorType *scale_state)
  {
    model.apply_boundary_values(u, load_factor);
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &x, VectorType &r) {
      model.assemble(x, load_factor, &r, nullptr, true, extra_force);
    };
    problem.tangent = [&](const VectorType &x, MatrixType &k) {
      model.assemble(x, load_factor, nullptr, &k, true, extra_force);
    };

    // The force scale of the step: the applied load, or the out-of-balance
    // force of the first iterate (displacement-driven steps).
    VectorType r     = model.create_vector();
    double     scale = load_factor * model.external_force().l2_norm();
    double     floor = 0;
    try
      {
        if (scale_state != nullptr)
          {
            VectorType start = *scale_state;
            model.apply_boundary_values(start, load_factor);
            model.assemble(start, load_factor, &r, nullptr, true, extra_force);
            scale = std::max(scale, r.l2_norm());
          }
        model.assemble(u, load_factor, &r, &tangent, true, extra_force);
        if (scale_state == nullptr)
          scale = std::max(scale, r.l2_norm());
        floor = residual_roundoff_floor(model, tangent);
      }
    catch (const std::exception &e)
      {
        NewtonSolver::Result failed;
        failed.failure = e.what();
        return failed;
      }
    NewtonSolver::Parameters newton = parameters.newton;
    newton.tolerance = std::max({parameters.relative_tolerance * scale,
                                 floor,
                                 std::numeric_limits<double>::min()});
    return NewtonSolver(newton).solve(problem, u, tangent);
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

  double
  residual_roundoff_floor(const RodModel &model, const MatrixType &tangent)
  {
    double max_diagonal = 0;
    for (unsigned int i = 0; i < tangent.m(); ++i)
      if (!model.constraints().is_constrained(i))
        max_diagonal =
          std::max(max_diagonal, std::abs(tangent.diag_element(i)));
    return std::numeric_limits<double>::epsilon() * max_diagonal *
           model.length_scale() * std::sqrt(double(tangent.m()));
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
    const double nominal             = 1.0 / parameters.n_steps;
    const double minimum             = nominal * parameters.min_step_fraction;
    double       lambda              = 0;
    double       step                = nominal;
    unsigned int count               = 0;
    double       previous_eigenvalue = std::nan("");
    VectorType   previous            = u;
    // Change of the state over the last converged step (of length
    // last_step), quaternion increments included: they are zeroed by the
    // reference reset, so they are taken before it.
    VectorType increment = u;
    increment            = 0;
    double last_step     = 0;

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
        step                       = target - lambda;
        VectorType           trial = u;
        NewtonSolver::Result result;
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
                result                = NewtonSolver::Result{true, 0, 0, ""};
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
                std::to_string(minimum) + " (Solver/Minimum step fraction)");
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
        info.step          = ++count;
        info.load_factor   = target;
        info.iterations    = result.iterations;
        info.residual_norm = result.residual_norm;
        if (parameters.track_lowest_eigenvalue ||
            parameters.find_critical_load ||
            parameters.branch_switch_amplitude > 0)
          info.lowest_eigenvalue = lowest_eigenvalue(u, target);

        if (parameters.find_critical_load && std::isnan(critical_load) &&
            previous_eigenvalue > 0 && info.lowest_eigenvalue <= 0)
          {
            const Configuration unstable_configuration = model.configuration();
            try
              {
                bisect_critical_load(previous,
                                     stable_configuration,
                                     lambda,
                                     previous_eigenvalue,
                                     target,
                                     info.lowest_eigenvalue);
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
        info.wall_time = timer.wall_time();

        if (log != nullptr)
          {
            char line[200];
            std::snprintf(line,
                          sizeof(line),
                          "step %4u  load factor %.6f  iterations %2u  "
                          "residual %.2e  time %.3f s",
                          info.step,
                          info.load_factor,
                          info.iterations,
                          info.residual_norm,
                          info.wall_time);
            *log << line;
            if (!std::isnan(info.lowest_eigenvalue))
              *log << "  lowest eigenvalue " << info.lowest_eigenvalue;
            *log << std::endl;
          }
        on_converged(info, u);

        previous_eigenvalue = info.lowest_eigenvalue;
        lambda              = target;
        step                = std::min(2 * step, nominal);
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
        if (!solve_at(trial, load_factor).converged)
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
                                     double               eigenvalue_stable,
                                     double               lambda_unstable,
                                     double               eigenvalue_unstable)
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
        const double mu = lowest_eigenvalue(u_mid, lambda_mid);
        if (mu > 0)
          {
            lambda_stable     = lambda_mid;
            eigenvalue_stable = mu;
            u_lo              = u_mid;
            config            = model.configuration();
          }
        else
          {
            lambda_unstable     = lambda_mid;
            eigenvalue_unstable = mu;
          }
      }
    // Linear interpolation of the eigenvalue inside the final bracket.
    critical_load = lambda_stable + (lambda_unstable - lambda_stable) *
                                      eigenvalue_stable /
                                      (eigenvalue_stable - eigenvalue_unstable);
    if (log != nullptr)
      *log << "critical load factor " << critical_load
           << " (lowest eigenvalue crosses zero)" << std::endl;
  }
} // namespace rodnet
