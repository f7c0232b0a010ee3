#include <deal.II/base/timer.h>

#include <core/same_entries.h>
#include <core/tensor_body_spin.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/free_motions.h>
#include <solvers/stability/stability.h>
#include <solvers/state_guard.h>
#include <solvers/time/body_rotation_inertia.h>
#include <solvers/time/integration_scheme_registry.h>
#include <solvers/time/prescribed_motion.h>
#include <solvers/time/time_integrator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    std::string
    time_string(const double t)
    {
      std::ostringstream s;
      s.precision(6);
      s << t;
      return s.str();
    }

    /// Throws std::invalid_argument for a damping coefficient of @p p that
    /// is negative or not finite, or not zero without inertia.
    void
    check_damping(const TimeIntegrator::Parameters &p,
                  const IntegrationScheme          &scheme)
    {
      const std::pair<const char *, double> coefficients[] = {
        {"Rayleigh mass coefficient", p.rayleigh_mass},
        {"Rayleigh stiffness coefficient", p.rayleigh_stiffness},
        {"viscous drag per length", p.viscous_drag}};
      for (const auto &[name, value] : coefficients)
        if (!(value >= 0) || !std::isfinite(value))
          throw std::invalid_argument(
            std::string("time stepping: the ") + name +
            " must be finite and not negative, got " + time_string(value));
      if (p.damped() && !scheme.dynamic())
        throw std::invalid_argument(
          "time stepping: damping acts on velocities, which the " +
          scheme.name() + " integrator does not have; use a dynamic one");
    }

    /// Throws std::invalid_argument for times, steps or a preload of @p p
    /// out of range.
    void
    check_times(const TimeIntegrator::Parameters &p)
    {
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
    }

    /// Throws std::invalid_argument where @p scheme cannot integrate
    /// @p model with the parameters @p p (its energy, globalization,
    /// damping or rigid bodies).
    void
    check_scheme(const SolvableModel              &model,
                 const TimeIntegrator::Parameters &p,
                 const IntegrationScheme          &scheme)
    {
      if (scheme.needs_stored_energy() && model.has_internal_variables())
        throw std::invalid_argument(
          "time stepping: the midpoint rule conserves a stored energy, which "
          "a material with internal variables (a viscoelastic law) does not "
          "have; use newmark or backward euler");
      if (p.newton.needs_potential() && !scheme.has_incremental_potential())
        throw std::invalid_argument(
          "time stepping: the " + scheme.name() +
          " step is not the minimum of a potential, which the " +
          p.newton.line_search +
          " globalization needs; use newmark, backward euler or quasi-static, "
          "or another line search");
      check_damping(p, scheme);
      check_tensor_bodies(model, scheme);
    }

    /// The residual (and potential, where the problem has one) of a
    /// problem at one state.
    struct Evaluation
    {
      VectorType x, residual;
      double     energy = 0;
    };

    /**
     * Evaluates @p problem at @p x and makes its functions give those
     * values at x from then on without evaluating again: a step's
     * tolerance needs the residual of the predictor, which NOX evaluates
     * first too (one residual assembly a step; two for the midpoint rule).
     * The functions are deterministic, so what they give is what they
     * would compute; any other state is evaluated as before.
     */
    std::shared_ptr<const Evaluation>
    evaluate_once(NewtonSolver::Problem &problem, const VectorType &x)
    {
      auto known = std::make_shared<Evaluation>();
      known->x   = x;
      known->residual.reinit(x);
      if (problem.energy)
        {
          known->energy = problem.energy(x, &known->residual);
          problem.set_potential([potential = problem.energy,
                                 known](const VectorType &y, VectorType *r) {
            if (!same_entries(y, known->x))
              return potential(y, r);
            if (r != nullptr)
              *r = known->residual;
            return known->energy;
          });
        }
      else
        {
          problem.residual(x, known->residual);
          problem.residual = [residual = problem.residual,
                              known](const VectorType &y, VectorType &r) {
            if (same_entries(y, known->x))
              r = known->residual;
            else
              residual(y, r);
          };
        }
      return known;
    }
  } // namespace

  TimeIntegrator::TimeIntegrator(SolvableModel                 &model,
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
    check_times(p);
    if (!model.multiplier_dofs().empty())
      // The multipliers carry no mass: the equations of motion would be
      // differential-algebraic, which the schemes here do not integrate.
      throw std::invalid_argument(
        "time stepping: Lagrange multipliers (of inextensible rods, "
        "ribbons or bonding constraints) are not supported: they make the "
        "equations of motion differential-algebraic; use Newton load steps "
        "or continuation, or extensible rods and elastic springs");
    scheme = integration_scheme_registry().create(p.integrator, system);
    preload_scheme =
      integration_scheme_registry().create("quasi-static", system);
    check_scheme(model, p, *scheme);
    model.initialize_matrix(tangent);
    last_increment = model.create_vector();
    if (!scheme->dynamic())
      return;
    if (inertia.empty())
      throw std::invalid_argument(
        "time stepping: the " + scheme->name() +
        " integrator needs the inertia of every rod (a density); only "
        "quasi-static runs do without");
    assemble_inertia(inertia);
  }

  void
  TimeIntegrator::assemble_inertia(const std::vector<RodInertia> &inertia)
  {
    const Parameters &p = parameters;
    assemble_mass_matrix(model, inertia, p.mass, mass, false);
    assemble_mass_matrix(model, inertia, p.mass, constrained_mass, true);
    copy_nonzeros(mass, mass_nonzeros);
    massless_rows.clear();
    const auto [first, end] = mass.local_range();
    for (global_dof_index i = first; i < end; ++i)
      if (mass.diag_element(i) == 0.0)
        massless_rows.push_back(i);
    if (p.viscous_drag > 0)
      {
        // A force -c v per length on the positions, lumped with each
        // vertex's Voronoi length: the lumped "mass" of density c / A.
        const std::vector<RodInertia> drag_per_length(inertia.size(),
                                                      {p.viscous_drag, 0});
        assemble_mass_matrix(model,
                             drag_per_length,
                             MassKind::lumped,
                             drag,
                             false);
        assemble_mass_matrix(model,
                             drag_per_length,
                             MassKind::lumped,
                             constrained_drag,
                             true);
      }
  }

  void
  TimeIntegrator::assemble_damping(const VectorType &u,
                                   const double      load_factor)
  {
    const Parameters &p = parameters;
    if (!scheme->dynamic() || !p.damped())
      return;
    // Rayleigh damping C = alpha M + beta K_0 (Chopra, Dynamics of
    // Structures, section 11.4) with K_0 the tangent at the start of the
    // run, assembled once: a constant, symmetric C keeps the damping force
    // linear in the velocity, so that the midpoint rule's energy falls by
    // exactly h vbar.C vbar and the modal damping ratio of mode omega is
    // alpha / (2 omega) + beta omega / 2 (doc/dynamics.md, "Damping").
    const bool constrained[] = {false, true};
    for (const bool c : constrained)
      {
        MatrixType &target = c ? constrained_damping : damping;
        model.initialize_matrix(target);
        if (p.rayleigh_stiffness != 0)
          {
            // The condensed tangent in both: the clamps' constraints tie
            // DoFs (the midpoint clamp), which only condensation carries
            // into the free rows (the mass matrix is condensed as well).
            model.assemble(u, load_factor, nullptr, &tangent, true);
            target.add(p.rayleigh_stiffness, tangent);
          }
        if (p.rayleigh_mass != 0)
          target.add(p.rayleigh_mass, c ? constrained_mass : mass);
        if (p.viscous_drag != 0)
          target.add(1.0, c ? constrained_drag : drag);
      }
  }

  void
  TimeIntegrator::start_state(VectorType &u, VectorType &v) const
  {
    const double time = parameters.initial_time();
    model.set_time(time);
    model.apply_boundary_values(u, parameters.load_factor(time), time);
    if (scheme->dynamic() && parameters.preload_time == 0)
      set_prescribed_velocity(model,
                              parameters.load_factor,
                              time,
                              parameters.time_step,
                              u,
                              v);
  }

  void
  TimeIntegrator::run(VectorType &u, VectorType &v, const Observer &observer)
  {
    const Parameters &p = parameters;
    if (!scheme->dynamic() || p.preload_time > 0)
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
        const double from = p.initial_time();
        model.set_time(from);
        model.apply_boundary_values(u, p.load_factor(from), from);
        advance(*preload_scheme, from, p.start_time - h, h, u, v, observer);
        v                = 0;
        last_step_length = 0;
      }
    model.set_time(p.start_time);
    model.apply_boundary_values(u, p.load_factor(p.start_time), p.start_time);
    if (scheme->dynamic())
      set_prescribed_velocity(model,
                              p.load_factor,
                              p.start_time,
                              p.time_step,
                              u,
                              v);
    model.set_time_step(0);
    assemble_damping(u, p.load_factor(p.start_time));
    scheme->start(u, v, p.load_factor(p.start_time));
    advance(*scheme, p.start_time, p.end_time, p.time_step, u, v, observer);
  }

  void
  TimeIntegrator::advance(IntegrationScheme &scheme,
                          const double       from,
                          const double       to,
                          const double       h,
                          VectorType        &u,
                          VectorType        &v,
                          const Observer    &observer)
  {
    watch_energy(scheme, from, u, v);
    converged_energy.known = false;
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
        if (!step(scheme, t, end, u, v, result))
          {
            attempt = halve_step(scheme, t, length, h, result);
            continue;
          }
        t = end;
        if (to_grid)
          {
            ++k;
            attempt = h;
          }
        ++n_steps;
        StepInfo info  = describe_step(scheme, t, length, u, v, result);
        info.wall_time = timer.wall_time();
        check_energy(scheme, info);
        info.external_work = energy_balance.work();
        if (observer)
          observer(info, u, v);
        if (log != nullptr && parameters.progress_interval > 0 &&
            n_steps % parameters.progress_interval == 0)
          *log << "  t = " << t << " s: step " << n_steps << ", "
               << result.iterations << " Newton iterations, energy "
               << info.kinetic_energy + info.potential_energy << " J"
               << (info.external_work != 0 ?
                     ", work done on it " + time_string(info.external_work) +
                       " J" :
                     "")
               << "\n";
      }
  }

  double
  TimeIntegrator::halve_step(const IntegrationScheme &scheme,
                             const double             time,
                             const double             length,
                             const double             h,
                             const JudgedResult      &result) const
  {
    const double attempt = length / 2;
    if (attempt < parameters.min_step_fraction * h)
      throw SolverFailure("time stepping (" + scheme.name() +
                          "): the step from t = " + time_string(time) +
                          " s failed down to a length of " +
                          time_string(length) + " s: " + result.failure);
    if (log != nullptr)
      *log << "  t = " << time << " s: step of " << length << " s failed ("
           << result.failure << "); halving\n";
    return attempt;
  }

  TimeIntegrator::StepInfo
  TimeIntegrator::describe_step(const IntegrationScheme &scheme,
                                const double             time,
                                const double             length,
                                const VectorType        &u,
                                const VectorType        &v,
                                const JudgedResult      &result)
  {
    StepInfo info;
    info.step        = n_steps;
    info.time        = time;
    info.time_step   = length;
    info.load_factor = parameters.load_factor(time);
    info.iterations  = result.iterations;
    info.residual    = result.residual;
    // The energy of the converged state: its scheme's where that was
    // assembled at the same inputs (before the reference reset, which
    // changes it by rounding only), else an assembly.
    info.potential_energy =
      std::isnan(step_energy) ?
        model.assemble(u, info.load_factor, nullptr, nullptr) :
        step_energy;
    step_energy = std::numeric_limits<double>::quiet_NaN();
    remember_energy(u, info.load_factor, info.potential_energy);
    if (scheme.dynamic())
      info.kinetic_energy = kinetic_energy(mass_nonzeros, v) +
                            tensor_body_spin(model, u, v).kinetic_energy;
    check_state(scheme, u, result, info);
    return info;
  }

  void
  TimeIntegrator::remember_energy(const VectorType &u,
                                  const double      load_factor,
                                  const double      energy)
  {
    converged_energy.u            = u;
    converged_energy.load_factor  = load_factor;
    converged_energy.time_factors = model.activation_time_factors();
    converged_energy.value        = energy;
    converged_energy.known        = true;
  }

  double
  TimeIntegrator::energy_at_end(const IntegrationScheme   &scheme,
                                const StepStart           &start,
                                const double               end_time,
                                const std::vector<double> &load_time_fields,
                                const VectorType          &x) const
  {
    // The scheme assembled at the step's load factor and the fields of its
    // load time; the end's energy is wanted at the end's and at a zero
    // time step (the model's time now).
    if (model.has_internal_variables() ||
        !same_potential_load(parameters.load_factor(end_time),
                             start.load_factor) ||
        model.activation_time_factors() != load_time_fields)
      return std::numeric_limits<double>::quiet_NaN();
    return scheme.energy_at(x);
  }

  bool
  TimeIntegrator::same_potential_load(const double a, const double b) const
  {
    return a == b || !model.potential_follows_load_factor();
  }

  double
  TimeIntegrator::known_energy(const VectorType &u,
                               const double      load_factor) const
  {
    // The energy depends on the state, the load factor (loads, ramped
    // natural shape), the fields driven by time and, with internal
    // variables, the time step, which differs (0 after a step).
    const ConvergedEnergy &known = converged_energy;
    if (known.known && !model.has_internal_variables() &&
        same_potential_load(load_factor, known.load_factor) &&
        model.activation_time_factors() == known.time_factors &&
        same_entries(u, known.u))
      return known.value;
    return std::numeric_limits<double>::quiet_NaN();
  }

  void
  TimeIntegrator::watch_energy(const IntegrationScheme &scheme,
                               const double             from,
                               const VectorType        &u,
                               const VectorType        &v)
  {
    // The total energy of a stable dynamic run can only stay (conservative
    // rods) or fall (dissipation) beyond the work that the loads, fields
    // and supports do on it; more marks an unstable integration (Newmark's
    // rule has no energy bound for nonlinear rods), stopped before it runs
    // away.
    const bool on = scheme.dynamic() && scheme.energy_never_grows() &&
                    parameters.energy_growth_limit > 0;
    energy_balance.start(
      on,
      parameters.energy_growth_limit,
      on ? kinetic_energy(mass_nonzeros, v) +
             tensor_body_spin(model, u, v).kinetic_energy :
           0.0,
      on ? model.assemble(u, parameters.load_factor(from), nullptr, nullptr) :
           0.0);
  }

  void
  TimeIntegrator::check_energy(const IntegrationScheme &scheme,
                               const StepInfo          &info)
  {
    if (!std::isfinite(info.potential_energy) ||
        !std::isfinite(info.kinetic_energy))
      throw SolverFailure(
        "time stepping (" + scheme.name() +
        "): the energy is not finite at t = " + time_string(info.time) + " s");
    energy_balance.check("time stepping (" + scheme.name() + ")",
                         scheme.instability_advice(),
                         info.time,
                         info.kinetic_energy,
                         info.potential_energy,
                         info.residual);
  }

  void
  TimeIntegrator::check_state(const IntegrationScheme &scheme,
                              const VectorType        &u,
                              const JudgedResult      &result,
                              StepInfo                &info)
  {
    if (!scheme.dynamic())
      {
        const EquilibriumCheck check =
          check_equilibrium(model,
                            criterion,
                            u,
                            info.load_factor,
                            tangent,
                            result,
                            parameters.rounding_uncertainty_limit,
                            &factorizations);
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
  TimeIntegrator::step(IntegrationScheme &scheme,
                       const double       time,
                       const double       end_time,
                       VectorType        &u,
                       VectorType        &v,
                       JudgedResult      &result)
  {
    StateGuard   before(model);
    const double h = end_time - time;
    // u_n + h v_n: the base of the mass term.
    VectorType base = u;
    base.add(h, v);
    // The fields driven by time at the time the loads are taken at.
    const double load_time = scheme.load_time(time, end_time);
    model.set_time(load_time);
    const double    load_factor = parameters.load_factor(load_time);
    const StepStart start{u,
                          base,
                          h,
                          load_factor,
                          known_energy(u, load_factor)};
    VectorType      x = u;
    if (!predict_step(time, end_time, u, v, x, result))
      return false;
    solve_newton(scheme, start, x, result);
    if (!result.converged)
      {
        noise.rows.clear();
        return false;
      }
    ++steps_since_noise;
    commit_step(scheme, start, time, end_time, x, u, v);
    before.keep();
    return true;
  }

  bool
  TimeIntegrator::predict_step(const double      time,
                               const double      end_time,
                               const VectorType &u,
                               const VectorType &v,
                               VectorType       &x,
                               JudgedResult     &result) const
  {
    try
      {
        model.check_rotation_step(parameters.load_factor(time),
                                  time,
                                  parameters.load_factor(end_time),
                                  end_time);
        x = predict(u, v, end_time - time, end_time);
        return true;
      }
    catch (const std::runtime_error &e)
      {
        // A prescribed rotation that turns by half a turn or more within
        // the step: a shorter step turns less.
        result.converged = false;
        result.failure   = e.what();
        return false;
      }
  }

  void
  TimeIntegrator::solve_newton(IntegrationScheme &scheme,
                               const StepStart   &start,
                               VectorType        &x,
                               JudgedResult      &result)
  {
    const bool modified = parameters.modified_newton && scheme.dynamic();
    if (modified)
      {
        // One factorization per step where the tangent barely changes
        // over it; full Newton where that is not enough.
        const VectorType predicted = x;
        solve_step(scheme, start, x, result, true);
        if (!result.converged)
          {
            x      = predicted;
            result = JudgedResult();
          }
      }
    if (!modified || !result.converged)
      solve_step(scheme, start, x, result);
    if (result.converged && !std::isfinite(x.l2_norm()))
      {
        result.converged = false;
        result.failure   = "the state is not finite";
      }
  }

  void
  TimeIntegrator::commit_step(IntegrationScheme &scheme,
                              const StepStart   &start,
                              const double       time,
                              const double       end_time,
                              VectorType        &x,
                              VectorType        &u,
                              VectorType        &v)
  {
    const std::vector<double> load_time_fields =
      model.activation_time_factors();
    // The commit first: it may throw, and then nothing has moved.
    model.commit_internal_variables(x);
    // Until the next step, evaluations see the converged state: the stored
    // energy at the committed variables (a zero-length step), the fields
    // at the step's end.
    model.set_time_step(0);
    model.set_time(end_time);
    const VectorType start_velocity = energy_balance.on() ? v : VectorType();
    scheme.finish(start, x, v);
    // Rows without mass (junction quaternions) have no velocity.
    system.zero_massless_rows(v);
    // The work of the step, in its chart (before the reference reset).
    if (energy_balance.on())
      energy_balance.add_step(
        {u, x, start_velocity, v, time, end_time, scheme.force_points()},
        parameters.load_factor);
    last_increment = x;
    last_increment -= u;
    last_step_length = start.h;
    step_energy = energy_at_end(scheme, start, end_time, load_time_fields, x);
    model.reset_reference(x);
    u = x;
  }

  VectorType
  TimeIntegrator::predict(const VectorType &u,
                          const VectorType &v,
                          const double      h,
                          const double      end_time) const
  {
    // The last increment, scaled to the step, rather than h v_n: the
    // velocities of stiff modes that the second-order rules do not damp
    // flip sign from step to step, and their mean over the last step is
    // what the next one continues.
    VectorType x = u;
    if (last_step_length > 0)
      x.add(h / last_step_length, last_increment);
    else
      x.add(h, v);
    // The supports at the step's end, whatever time the loads act at.
    model.apply_boundary_values(x, parameters.load_factor(end_time), end_time);
    return x;
  }

  void
  TimeIntegrator::solve_step(IntegrationScheme &scheme,
                             const StepStart   &start,
                             VectorType        &x,
                             JudgedResult      &result,
                             const bool         modified)
  {
    try
      {
        model.set_time_step(start.h);
        NewtonSolver::Problem problem;
        scheme.set_up(start, problem);
        problem.reuse_first_jacobian = modified;
        // The noise follows the slowly changing shape: measured every
        // noise_interval steps (and after a failed step) rather than at
        // every one of thousands.
        if (noise.rows.empty() || steps_since_noise >= noise_interval)
          {
            noise             = criterion.roundoff_noise(x, start.load_factor);
            steps_since_noise = 0;
          }
        const ResidualParts scale = step_scale(scheme, start, problem, x);
        ResidualParts       tolerance =
          ResidualCriterion::tolerance(scale,
                                       noise.floor,
                                       parameters.relative_tolerance);
        ResidualParts                    reached;
        ResidualCriterion::StepTolerance step{noise,
                                              tolerance,
                                              scale,
                                              parameters.relative_tolerance,
                                              start.load_factor,
                                              nullptr};
        problem.converged = criterion.stall_aware_test(step, reached);
        static_cast<NewtonSolver::Result &>(result) =
          NewtonSolver(parameters.newton)
            .solve(problem, x, tangent, &factorizations);
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
  }

  ResidualParts
  TimeIntegrator::step_scale(IntegrationScheme     &scheme,
                             const StepStart       &start,
                             NewtonSolver::Problem &problem,
                             const VectorType      &x)
  {
    // The scales of statics, or the out-of-balance force of the
    // predictor where inertia is what the residual balances. The shared
    // gradient first: the midpoint residual at x takes Pi(x) from its
    // assembly.
    const VectorType *const gradient = scheme.shared_gradient(x);
    const std::shared_ptr<const Evaluation> predictor =
      evaluate_once(problem, x);
    const ResidualParts loads     = criterion.judging_scale(x,
                                                        start.load_factor,
                                                        noise.floor,
                                                        nullptr,
                                                        gradient);
    const ResidualParts predicted = criterion.norms(x, predictor->residual);
    const double        length    = model.length_scale();
    const double        force =
      std::max({loads.force, predicted.force, predicted.moment / length});
    return {force, force * length};
  }
} // namespace rodnet
