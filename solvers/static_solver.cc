#include <deal.II/base/timer.h>

#include <solvers/stability.h>
#include <solvers/static_solver.h>

#include <algorithm>
#include <cstdio>

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
    model.initialize_matrix(tangent);
  }

  NewtonSolver::Result
  StaticSolver::solve_at(VectorType &u, const double load_factor)
  {
    model.apply_boundary_values(u, load_factor);
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &x, VectorType &r) {
      model.assemble(x, load_factor, &r, nullptr);
    };
    problem.tangent = [&](const VectorType &x, MatrixType &k) {
      model.assemble(x, load_factor, nullptr, &k);
    };

    // The force scale of the step: the applied load, or the out-of-balance
    // force of the first iterate (displacement-driven steps).
    VectorType r = model.create_vector();
    double     scale = load_factor * model.external_force().l2_norm();
    try
      {
        model.assemble(u, load_factor, &r, nullptr);
        scale = std::max(scale, r.l2_norm());
      }
    catch (const std::exception &e)
      {
        NewtonSolver::Result failed;
        failed.failure = e.what();
        return failed;
      }
    NewtonSolver::Parameters newton = parameters.newton;
    newton.tolerance =
      std::max(parameters.relative_tolerance * scale,
               std::numeric_limits<double>::min());
    return NewtonSolver(newton).solve(problem, u, tangent);
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
    const double nominal = 1.0 / parameters.n_steps;
    const double minimum = nominal * parameters.min_step_fraction;
    double       lambda  = 0;
    double       step    = nominal;
    unsigned int count   = 0;
    double previous_eigenvalue = std::nan("");
    VectorType   previous = u;

    while (lambda < 1.0 - 1e-12)
      {
        dealii::Timer timer;
        step                  = std::min(step, 1.0 - lambda);
        const double target   = lambda + step;
        VectorType   trial    = u;
        const NewtonSolver::Result result = solve_at(trial, target);
        if (!result.converged)
          {
            if (log != nullptr)
              *log << "  step to load factor " << target << " failed ("
                   << result.failure << "); cutting the step" << std::endl;
            step *= 0.5;
            if (step < minimum)
              throw SolverFailure(
                "the load step from load factor " + std::to_string(lambda) +
                " failed: " + result.failure + "; the step was cut below "
                "the minimum " + std::to_string(minimum) +
                " (Solver/Minimum step fraction)");
            continue;
          }

        const Configuration stable_configuration = model.configuration();
        previous = u;
        u        = trial;
        model.reset_reference(u);

        StepInfo info;
        info.step          = ++count;
        info.load_factor   = target;
        info.iterations    = result.iterations;
        info.residual_norm = result.residual_norm;
        if (parameters.track_lowest_eigenvalue ||
            parameters.find_critical_load)
          info.lowest_eigenvalue = lowest_eigenvalue(u, target);

        if (parameters.find_critical_load && std::isnan(critical_load) &&
            previous_eigenvalue > 0 && info.lowest_eigenvalue <= 0)
          {
            const Configuration unstable_configuration = model.configuration();
            bisect_critical_load(previous, stable_configuration, lambda,
                                 previous_eigenvalue, target,
                                 info.lowest_eigenvalue);
            model.configuration() = unstable_configuration;
          }
        info.wall_time = timer.wall_time();

        if (log != nullptr)
          {
            char line[200];
            std::snprintf(line, sizeof(line),
                          "step %4u  load factor %.6f  iterations %2u  "
                          "residual %.2e  time %.3f s",
                          info.step, info.load_factor, info.iterations,
                          info.residual_norm, info.wall_time);
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
        VectorType u_mid        = u_lo;
        const NewtonSolver::Result result = solve_at(u_mid, lambda_mid);
        if (!result.converged)
          throw SolverFailure("bisection for the critical load failed at load "
                              "factor " + std::to_string(lambda_mid) + ": " +
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
