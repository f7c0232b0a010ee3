#include <deal.II/base/timer.h>

#include <solvers/equilibrium_check.h>
#include <solvers/free_motions.h>
#include <solvers/stability.h>
#include <solvers/time_integrator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    const std::vector<std::pair<Integrator, std::string>> integrator_names = {
      {Integrator::quasi_static, "quasi-static"},
      {Integrator::backward_euler, "backward euler"},
      {Integrator::newmark, "newmark"},
      {Integrator::midpoint, "midpoint"}};

    /// Coefficient c of the mass term c M (u - u_n - h v_n) of @p method.
    double
    mass_coefficient(const Integrator method, const double h)
    {
      switch (method)
        {
          case Integrator::quasi_static:
            return 0;
          case Integrator::backward_euler:
            return 1 / (h * h);
          case Integrator::newmark:
            return 4 / (h * h);
          case Integrator::midpoint:
            return 2 / (h * h);
        }
      return 0;
    }

    std::string
    time_string(const double t)
    {
      std::ostringstream s;
      s.precision(6);
      s << t;
      return s.str();
    }
  } // namespace

  std::string
  to_string(const Integrator integrator)
  {
    for (const auto &[value, name] : integrator_names)
      if (value == integrator)
        return name;
    return "unknown";
  }

  Integrator
  parse_integrator(const std::string &name)
  {
    std::string known;
    for (const auto &[value, n] : integrator_names)
      {
        if (n == name)
          return value;
        known += (known.empty() ? "" : ", ") + n;
      }
    throw std::invalid_argument("unknown time integrator \"" + name +
                                "\"; known: " + known);
  }

  TimeIntegrator::TimeIntegrator(RodModel                      &model,
                                 const std::vector<RodInertia> &inertia,
                                 const Parameters              &parameters,
                                 std::ostream                  *log)
      : model(model)
      , parameters(parameters)
      , log(log)
      , criterion(model)
      , strains(model, parameters.strain_limits)
  {
    const Parameters &p = parameters;
    if (!(p.time_step > 0) || !std::isfinite(p.time_step))
      throw std::invalid_argument(
        "time stepping: the time step must be positive and finite, got " +
        time_string(p.time_step));
    if (!(p.end_time >= p.start_time) || !std::isfinite(p.end_time))
      throw std::invalid_argument(
        "time stepping: the end time " + time_string(p.end_time) +
        " lies before the start time " + time_string(p.start_time));
    if (!(p.preload_time >= 0) || !std::isfinite(p.preload_time) ||
        (p.preload_time > 0 && p.preload_steps == 0))
      throw std::invalid_argument(
        "time stepping: the preload time must be finite and not negative, "
        "and a preload needs at least one step");
    if (!(p.min_step_fraction > 0 && p.min_step_fraction <= 1))
      throw std::invalid_argument(
        "time stepping: the minimum step fraction must lie in (0, 1]");
    if (p.integrator == Integrator::midpoint && model.has_internal_variables())
      throw std::invalid_argument(
        "time stepping: the midpoint rule conserves a stored energy, which "
        "a material with internal variables (a viscoelastic law) does not "
        "have; use newmark or backward euler");
    model.initialize_matrix(tangent);
    last_increment = model.create_vector();
    if (p.integrator == Integrator::quasi_static)
      return;
    if (inertia.empty())
      throw std::invalid_argument(
        "time stepping: the " + to_string(p.integrator) +
        " integrator needs the inertia of every rod (a density); only "
        "quasi-static runs do without");
    assemble_mass_matrix(model, inertia, p.mass, mass, false);
    assemble_mass_matrix(model, inertia, p.mass, constrained_mass, true);
    has_mass.resize(mass.m());
    for (unsigned int i = 0; i < mass.m(); ++i)
      has_mass[i] = mass.diag_element(i) != 0.0;
    inertial_force = model.create_vector();
  }

  void
  TimeIntegrator::equilibrium_inertial_force(const VectorType &u,
                                             const double      load_factor)
  {
    // M a_0 = lambda f - grad W: the out-of-balance force of the start.
    model.assemble(u, load_factor, &inertial_force, nullptr, true);
    inertial_force *= -1.0;
    for (unsigned int i = 0; i < has_mass.size(); ++i)
      if (!has_mass[i])
        inertial_force[i] = 0;
    inertial_force.compress(dealii::VectorOperation::insert);
  }

  void
  TimeIntegrator::run(VectorType &u, VectorType &v, const Observer &observer)
  {
    const Parameters &p = parameters;
    if (p.integrator == Integrator::quasi_static || p.preload_time > 0)
      {
        const std::string free_motions = describe_free_motions(model, u);
        if (!free_motions.empty())
          throw std::invalid_argument(free_motions);
      }
    if (p.preload_time > 0)
      {
        // Steps end at start - preload_time + (k - 1) h, k = 1..n: all
        // strictly before the start, so that a load released at the start
        // (load factor if(t < 0, 1, 0)) holds during the whole preload.
        const double h    = p.preload_time / p.preload_steps;
        const double from = p.start_time - p.preload_time - h;
        model.apply_boundary_values(u, p.load_factor(from));
        advance(Integrator::quasi_static,
                from,
                p.start_time - h,
                h,
                u,
                v,
                observer);
        v                = 0;
        last_step_length = 0;
      }
    model.apply_boundary_values(u, p.load_factor(p.start_time));
    model.set_time_step(0);
    if (p.integrator == Integrator::newmark)
      equilibrium_inertial_force(u, p.load_factor(p.start_time));
    advance(p.integrator,
            p.start_time,
            p.end_time,
            p.time_step,
            u,
            v,
            observer);
  }

  void
  TimeIntegrator::advance(const Integrator method,
                          const double     from,
                          const double     to,
                          const double     h,
                          VectorType      &u,
                          VectorType      &v,
                          const Observer  &observer)
  {
    // Under a constant load factor the total energy of a dynamic run can
    // only stay (conservative rods) or fall (dissipation); growth beyond
    // energy_growth_limit of its scale marks an unstable integration
    // (Newmark's rule has no energy bound for nonlinear rods), stopped
    // before it runs away. The reference restarts whenever the load moves.
    const bool check_energy =
      method != Integrator::quasi_static && parameters.energy_growth_limit > 0;
    double reference_load   = parameters.load_factor(from);
    double reference_energy = 0, energy_scale = 0;
    if (check_energy)
      {
        reference_energy = kinetic_energy(mass, v) +
                           model.assemble(u, reference_load, nullptr, nullptr);
        energy_scale = std::abs(reference_energy);
      }

    // Times closer than this to a grid point are on it (rounding of t).
    const double on_grid = 1e-9 * h;
    double       t       = from;
    unsigned int k       = 0; ///< grid points passed
    double       attempt = h;
    while (to - t > on_grid)
      {
        const double grid = std::min(from + (k + 1) * h, to);
        // A step that reaches the grid point ends exactly on it, so that
        // the load factor is evaluated there and not a rounding error
        // before (which matters for discontinuous loads).
        const bool    to_grid = attempt >= grid - t - on_grid;
        const double  end     = to_grid ? grid : t + attempt;
        const double  length  = end - t;
        dealii::Timer timer;
        JudgedResult  result;
        if (!step(method, t, end, u, v, result))
          {
            attempt = length / 2;
            if (attempt < parameters.min_step_fraction * h)
              throw SolverFailure("time stepping (" + to_string(method) +
                                  "): the step from t = " + time_string(t) +
                                  " s failed down to a length of " +
                                  time_string(length) +
                                  " s: " + result.failure);
            if (log != nullptr)
              *log << "  t = " << t << " s: step of " << length << " s failed ("
                   << result.failure << "); halving\n";
            continue;
          }
        t = end;
        if (to_grid)
          {
            ++k;
            attempt = h;
          }
        ++n_steps;

        StepInfo info;
        info.step        = n_steps;
        info.time        = t;
        info.time_step   = length;
        info.load_factor = parameters.load_factor(t);
        info.iterations  = result.iterations;
        info.residual    = result.residual;
        info.potential_energy =
          model.assemble(u, info.load_factor, nullptr, nullptr);
        if (method != Integrator::quasi_static)
          info.kinetic_energy = kinetic_energy(mass, v);
        check_state(method, u, result, info);
        info.wall_time = timer.wall_time();
        if (!std::isfinite(info.potential_energy) ||
            !std::isfinite(info.kinetic_energy))
          throw SolverFailure(
            "time stepping (" + to_string(method) +
            "): the energy is not finite at t = " + time_string(t) + " s");
        if (check_energy)
          {
            const double energy = info.kinetic_energy + info.potential_energy;
            if (info.load_factor != reference_load)
              {
                reference_load   = info.load_factor;
                reference_energy = energy;
                energy_scale     = std::abs(energy);
              }
            energy_scale = std::max(energy_scale, info.kinetic_energy);
            if (energy - reference_energy >
                parameters.energy_growth_limit * energy_scale)
              throw SolverFailure(
                "time stepping (" + to_string(method) + "): unstable at t = " +
                time_string(t) + " s, the energy grew from " +
                time_string(reference_energy) + " to " + time_string(energy) +
                " J under a constant load; take a smaller time step" +
                (method == Integrator::newmark ?
                   " or the midpoint rule, which conserves energy" :
                   ""));
          }
        if (observer)
          observer(info, u, v);
        if (log != nullptr && parameters.progress_interval > 0 &&
            n_steps % parameters.progress_interval == 0)
          *log << "  t = " << t << " s: step " << n_steps << ", "
               << result.iterations << " Newton iterations, energy "
               << info.kinetic_energy + info.potential_energy << " J\n";
      }
  }

  void
  TimeIntegrator::check_state(const Integrator    method,
                              const VectorType   &u,
                              const JudgedResult &result,
                              StepInfo           &info)
  {
    if (method == Integrator::quasi_static)
      {
        const EquilibriumCheck check =
          check_equilibrium(model,
                            criterion,
                            u,
                            info.load_factor,
                            tangent,
                            result,
                            parameters.rounding_uncertainty_limit);
        refuse_undetermined_state(check,
                                  parameters.rounding_failure_limit,
                                  "t = " + time_string(info.time) + " s");
        info.stable = check.stable;
        if (!info.stable && log != nullptr)
          *log << "warning: the equilibrium at t = " << info.time
               << " s is unstable: its tangent has "
               << check.negative_eigenvalues
               << " negative eigenvalue(s); any imperfection leaves it\n";
        if (!check.rounding_warning.empty() && log != nullptr)
          *log << "warning: rounding leaves the state at t = " << info.time
               << " s uncertain by " << check.rounding_uncertainty
               << " of the model size: " << check.rounding_warning << "\n";
      }
    info.strain               = strains.evaluate(u);
    const std::string warning = strains.warning(info.strain);
    if (!warning.empty() && log != nullptr)
      *log << "t = " << info.time << " s: " << warning << "\n";
  }

  bool
  TimeIntegrator::step(const Integrator method,
                       const double     time,
                       const double     end_time,
                       VectorType      &u,
                       VectorType      &v,
                       JudgedResult    &result)
  {
    const double h           = end_time - time;
    const double c           = mass_coefficient(method, h);
    const double load_factor = parameters.load_factor(
      method == Integrator::midpoint ? time + h / 2 : end_time);
    const double end_load_factor = parameters.load_factor(end_time);
    const bool   midpoint        = method == Integrator::midpoint;

    // u_n + h v_n: the base of the mass term and the predictor.
    VectorType base = u;
    base.add(h, v);
    // Predictor: the last increment, scaled to the step, rather than
    // h v_n: the velocities of stiff modes that the second-order rules do
    // not damp flip sign from step to step, and their mean over the last
    // step is what the next one continues.
    VectorType x = u;
    if (last_step_length > 0)
      x.add(h / last_step_length, last_increment);
    else
      x.add(h, v);
    model.apply_boundary_values(x, end_load_factor);

    VectorType difference = model.create_vector();
    VectorType product    = model.create_vector();
    // Adds c M (x - base) (minus Newmark's p_n) to r, free rows only.
    const auto add_inertia = [&](const VectorType &y, VectorType &r) {
      if (c == 0)
        return;
      difference = y;
      difference -= base;
      mass.vmult(product, difference);
      r.add(c, product);
      if (method == Integrator::newmark)
        r.add(-1.0, inertial_force);
      model.constraints().set_zero(r);
    };

    double     start_energy = 0;
    VectorType point        = model.create_vector();
    // Midpoint rule: gradients at m and at u, the correction coefficient
    // and the rank-one part of the Jacobian.
    VectorType gradient_m, gradient_y, mass_difference, rank_one_a, rank_one_b;
    if (midpoint)
      {
        gradient_m.reinit(point);
        gradient_y.reinit(point);
        mass_difference.reinit(point);
        rank_one_a.reinit(point);
        rank_one_b.reinit(point);
      }
    // The discrete gradient in the metric of the mass matrix:
    // gradbar = grad Pi(m) + c M d_f, c = [Pi(u) - Pi(u_n) -
    // grad Pi(m).d] / (d_f.M d_f). Any metric keeps gradbar.d =
    // Pi(u) - Pi(u_n); the mass puts the correction where the inertia
    // is, instead of loading the stiff, nearly massless twist DoFs as
    // much as the positions (which made Newton stall at coarse steps),
    // and never on massless quaternion rows.
    const auto correction_terms = [&](const VectorType &y,
                                      const VectorType &gradient,
                                      const double      energy) {
      difference = y;
      difference -= u;
      const double change = energy - start_energy - (gradient * difference);
      model.constraints().set_zero(difference);
      mass.vmult(mass_difference, difference);
      model.constraints().set_zero(mass_difference);
      const double norm2 = difference * mass_difference;
      return std::make_pair(norm2 > 0 ? change / norm2 : 0.0, norm2);
    };
    NewtonSolver::Problem problem;
    if (midpoint)
      {
        problem.residual = [&](const VectorType &y, VectorType &r) {
          point = y;
          point += u;
          point *= 0.5;
          // Unconstrained: grad Pi . d needs the fixed rows too, where
          // prescribed DoFs move.
          model.assemble(point, load_factor, &r, nullptr, false);
          const double energy =
            model.assemble(y, load_factor, nullptr, nullptr);
          const double coefficient = correction_terms(y, r, energy).first;
          model.constraints().set_zero(r);
          r.add(coefficient, mass_difference);
          add_inertia(y, r);
        };
        // The exact Jacobian: the derivative of the correction c M d_f is
        // c M (sparse) plus the dense M d_f (grad c)^T, with
        //   grad c = [grad Pi(u) - grad Pi(m) - K(m) d / 2 - 2 c M d_f]
        //            / (d_f.M d_f)
        // (free rows), which NewtonSolver takes as a rank-one term.
        problem.tangent = [&](const VectorType &y, MatrixType &k) {
          point = y;
          point += u;
          point *= 0.5;
          model.assemble(point, load_factor, &gradient_m, nullptr, false);
          const double energy =
            model.assemble(y, load_factor, &gradient_y, nullptr, false);
          const auto [coefficient, norm2] =
            correction_terms(y, gradient_m, energy);

          model.assemble(point, load_factor, nullptr, &k, true);
          k *= 0.5;
          k.vmult(product, difference);
          k.add(c + coefficient, constrained_mass);

          rank_one_b = gradient_y;
          rank_one_b -= gradient_m;
          rank_one_b -= product;
          rank_one_b.add(-2 * coefficient, mass_difference);
          model.constraints().set_zero(rank_one_b);
          rank_one_b *= norm2 > 0 ? 1 / norm2 : 0.0;
          rank_one_a = mass_difference;
        };
        problem.rank_one =
          [&](const VectorType &, VectorType &a, VectorType &b) {
            a = rank_one_a;
            b = rank_one_b;
          };
      }
    else
      {
        problem.residual = [&](const VectorType &y, VectorType &r) {
          model.assemble(y, load_factor, &r, nullptr, true);
          add_inertia(y, r);
        };
        problem.tangent = [&](const VectorType &y, MatrixType &k) {
          model.assemble(y, load_factor, nullptr, &k, true);
          if (c != 0)
            k.add(c, constrained_mass);
        };
      }

    try
      {
        model.set_time_step(h);
        if (midpoint)
          start_energy = model.assemble(u, load_factor, nullptr, nullptr);
        // The scales of statics, or the out-of-balance force of the
        // predictor where inertia is what the residual balances.
        VectorType r = model.create_vector();
        problem.residual(x, r);
        problem.tangent(x, tangent);
        const ResidualParts loads     = criterion.load_scale(x, load_factor);
        const ResidualParts predicted = criterion.norms(x, r);
        const double        length    = model.length_scale();
        const double        force =
          std::max({loads.force, predicted.force, predicted.moment / length});
        const ResidualParts scale{force, force * length};
        // The noise follows the slowly changing shape: measured every
        // noise_interval steps (and after a failed step) rather than at
        // every one of thousands.
        if (noise.rows.empty() || steps_since_noise >= noise_interval)
          {
            noise             = criterion.roundoff_noise(x, load_factor);
            steps_since_noise = 0;
          }
        const ResidualParts tolerance =
          ResidualCriterion::tolerance(scale,
                                       noise.floor,
                                       parameters.relative_tolerance);
        ResidualParts reached;
        problem.converged = criterion.newton_test(tolerance, reached);
        static_cast<NewtonSolver::Result &>(result) =
          NewtonSolver(parameters.newton).solve(problem, x, tangent);
        result.residual = reached;
        result.scale    = scale;
        result.noise    = noise;
        result.rounding_limited =
          ResidualCriterion::inconclusive(noise.floor,
                                          scale,
                                          parameters.rounding_floor_limit);
        if (!result.converged)
          result.failure +=
            "; " + ResidualCriterion::describe(reached, tolerance);
      }
    catch (const std::exception &e)
      {
        result.converged = false;
        result.failure   = e.what();
      }
    if (result.converged && !std::isfinite(x.l2_norm()))
      {
        result.converged = false;
        result.failure   = "the state is not finite";
      }
    if (!result.converged)
      {
        noise.rows.clear();
        return false;
      }
    ++steps_since_noise;

    // Velocities and Newmark's inertial force at the new state.
    difference = x;
    difference -= u;
    if (method == Integrator::newmark || midpoint)
      {
        v *= -1.0;
        v.add(2 / h, difference);
      }
    else
      {
        v = difference;
        v /= h;
      }
    if (method == Integrator::newmark)
      {
        difference = x;
        difference -= base;
        mass.vmult(product, difference);
        inertial_force *= -1.0;
        inertial_force.add(c, product);
      }
    // Rows without mass (junction quaternions) have no velocity.
    for (unsigned int i = 0; i < has_mass.size(); ++i)
      if (!has_mass[i])
        v[i] = 0;
    v.compress(dealii::VectorOperation::insert);

    model.commit_internal_variables(x);
    // Until the next step, evaluations see the converged state: the stored
    // energy at the committed variables (a zero-length step).
    model.set_time_step(0);
    last_increment = x;
    last_increment -= u;
    last_step_length = h;
    model.reset_reference(x);
    u = x;
    return true;
  }
} // namespace rodnet
