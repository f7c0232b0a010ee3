#include <solvers/relaxation/dynamic_relaxation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace rodnet
{
  namespace
  {
    [[noreturn]] void
    refuse(const std::string &entry,
           const std::string &requirement,
           double             value)
    {
      std::ostringstream message;
      message << "dynamic relaxation: " << entry << " " << requirement
              << ", got " << value;
      throw std::invalid_argument(message.str());
    }
  } // namespace


  DynamicRelaxation::DynamicRelaxation(const DrModel    &model,
                                       const Parameters &parameters,
                                       std::ostream     *log)
      : model(model)
      , parameters(parameters)
      , log(log)
  {
    const Parameters &p = parameters;
    if (p.n_steps < 1)
      refuse("the number of load steps", "must be >= 1", p.n_steps);
    if (!(p.time_step > 0) || !std::isfinite(p.time_step))
      refuse("the time step", "must be positive and finite", p.time_step);
    if (!(p.mass_scaling >= 1) || !std::isfinite(p.mass_scaling))
      refuse("the mass scaling", "must be >= 1 and finite", p.mass_scaling);
    if (!(p.residual_tolerance > 0))
      refuse("the residual tolerance",
             "must be positive",
             p.residual_tolerance);
    if (p.max_iterations < 1)
      refuse("the maximum number of iterations",
             "must be >= 1",
             p.max_iterations);
    if (!(p.instability_growth > 1))
      refuse("the instability growth", "must be > 1", p.instability_growth);
    if (!(p.min_time_step_fraction > 0 && p.min_time_step_fraction <= 1))
      refuse("the minimum time step fraction",
             "must be in (0, 1]",
             p.min_time_step_fraction);
  }


  double
  DynamicRelaxation::free_norm(const DrVector &r) const
  {
    // Each DoF counted on its owner (one process: every DoF).
    const DrProcessShare &share = model.process_share();
    double                sum   = 0;
    for (const unsigned int i : share.owned_free_dofs())
      sum += r[i] * r[i];
    return std::sqrt(share.sum(sum));
  }


  double
  DynamicRelaxation::reaction_norm(const DrVector &r) const
  {
    double sum = 0;
    for (const Support &s : model.supports())
      sum += model.support_force(s, r).squaredNorm();
    return std::sqrt(sum);
  }


  double
  DynamicRelaxation::residual_floor(const DrVector &masses) const
  {
    // Rounding errors of the positions, eps L, times the stiffness row sums
    // S_i = 2 m_i / scaling bound what residual row i can reach; the floor
    // sums them row by row (the largest row times sqrt(n) would let one
    // stiff element excuse every other row, as in Newton's statics).
    return std::max(std::numeric_limits<double>::epsilon() *
                      (2 * free_norm(masses) / parameters.mass_scaling) *
                      model.length_scale(),
                    std::numeric_limits<double>::min());
  }


  double
  DynamicRelaxation::leapfrog(DrVector       &u,
                              const DrVector &r,
                              const double    dt,
                              Motion         &motion,
                              double         &reversal) const
  {
    // Each process moves the DoFs its elements touch (the processes that
    // share a DoF move it alike) and counts the sums on the DoFs it owns.
    const DrProcessShare &share = model.process_share();
    const double          kick  = motion.from_rest ? 0.5 * dt : dt;
    std::vector<double>   sums{0, 0}; // kinetic energy, reversal
    for (const unsigned int i : share.touched_free_dofs())
      {
        const double m         = motion.masses[i];
        const double before    = motion.from_rest ? 0.0 : motion.velocity[i];
        motion.acceleration[i] = -r[i] / m;
        motion.velocity[i]     = before + kick * motion.acceleration[i];
        u[i] += dt * motion.velocity[i];
        if (share.owns(i))
          {
            sums[0] += 0.5 * m * motion.velocity[i] * motion.velocity[i];
            sums[1] += m * motion.velocity[i] * before;
          }
      }
    share.sum(sums);
    reversal = sums[1];
    return sums[0];
  }


  std::string
  DynamicRelaxation::instability(const double kinetic_energy,
                                 const double reversal,
                                 Motion      &motion) const
  {
    if (motion.from_rest || !(kinetic_energy > motion.kinetic_energy_before) ||
        !(reversal < 0))
      {
        motion.growing = 0;
        return "";
      }
    if (motion.growing++ == 0)
      motion.growth_base = motion.kinetic_energy_before;
    if (motion.growing < 5 ||
        !(kinetic_energy >= parameters.instability_growth * motion.growth_base))
      return "";
    std::ostringstream reason;
    reason << "the kinetic energy grew by a factor "
           << kinetic_energy / motion.growth_base << " in " << motion.growing
           << " iterations that each reversed the velocities: central "
              "differences are unstable at this time step";
    return reason.str();
  }


  bool
  DynamicRelaxation::damp_at_peak(DrVector    &u,
                                  const double kinetic_energy,
                                  const double dt,
                                  Motion      &motion) const
  {
    if (motion.from_rest || !(kinetic_energy < motion.kinetic_energy_before))
      {
        motion.from_rest             = false;
        motion.kinetic_energy_before = kinetic_energy;
        return false;
      }
    for (const unsigned int i : model.process_share().touched_free_dofs())
      {
        u[i] -= 1.5 * dt * motion.velocity[i] -
                0.5 * dt * dt * motion.acceleration[i];
        motion.velocity[i] = 0;
      }
    motion.from_rest             = true;
    motion.kinetic_energy_before = 0;
    model.fictitious_masses(u, parameters.mass_scaling, motion.masses);
    return true;
  }


  DynamicRelaxation::Attempt
  DynamicRelaxation::relax(DrVector    &u,
                           const double load_factor,
                           const double dt) const
  {
    Attempt  attempt;
    DrVector r;
    Motion   motion;
    motion.velocity.reinit(model.n_dofs());
    motion.acceleration.reinit(model.n_dofs());
    const auto unstable = [&](const std::string &reason) {
      attempt.unstable = true;
      attempt.reason   = reason;
      return attempt;
    };

    model.apply_boundary_values(u, load_factor);
    try
      {
        model.residual(u, load_factor, r);
        model.fictitious_masses(u, parameters.mass_scaling, motion.masses);
      }
    catch (const std::exception &e)
      {
        return unstable(e.what());
      }
    const double applied = load_factor * free_norm(model.external_force());
    const double floor   = residual_floor(motion.masses);

    for (unsigned int iteration = 0;; ++iteration)
      {
        const double norm     = free_norm(r);
        attempt.iterations    = iteration;
        attempt.residual_norm = norm;
        if (!std::isfinite(norm))
          return unstable("the residual is not finite");
        // The forces in the structure: the applied load, or the reactions
        // where prescribed displacements drive it.
        const double tolerance = std::max(parameters.residual_tolerance *
                                            std::max(applied, reaction_norm(r)),
                                          floor);
        if (norm <= tolerance)
          {
            attempt.converged = true;
            return attempt;
          }
        if (iteration == parameters.max_iterations)
          {
            std::ostringstream reason;
            reason << "no convergence in " << iteration
                   << " iterations: residual " << norm << ", tolerance "
                   << tolerance;
            attempt.reason = reason.str();
            return attempt;
          }
        if (const std::optional<std::string> reason =
              advance(u, r, load_factor, dt, motion, attempt))
          return unstable(*reason);
      }
  }


  std::optional<std::string>
  DynamicRelaxation::advance(DrVector    &u,
                             DrVector    &r,
                             const double load_factor,
                             const double dt,
                             Motion      &motion,
                             Attempt     &attempt) const
  {
    double       reversal       = 0;
    const double kinetic_energy = leapfrog(u, r, dt, motion, reversal);
    if (!std::isfinite(kinetic_energy))
      return "the kinetic energy is not finite";
    if (std::string reason = instability(kinetic_energy, reversal, motion);
        !reason.empty())
      return reason;
    try
      {
        attempt.peaks += damp_at_peak(u, kinetic_energy, dt, motion);
        model.residual(u, load_factor, r);
      }
    catch (const std::exception &e)
      {
        return std::string(e.what());
      }

    const unsigned int done = attempt.iterations + 1;
    if (log != nullptr && parameters.progress_interval > 0 &&
        done % parameters.progress_interval == 0)
      *log << "    DR iteration " << done << ": kinetic energy "
           << kinetic_energy << ", |R| " << free_norm(r) << std::endl;
    return std::nullopt;
  }


  DynamicRelaxation::Attempt
  DynamicRelaxation::relax_cutting_time_step(DrVector          &u,
                                             const DrVector    &last_converged,
                                             const unsigned int step,
                                             const double       load_factor,
                                             double            &dt,
                                             Result            &result) const
  {
    const double min_dt =
      parameters.time_step * parameters.min_time_step_fraction;
    for (;;)
      {
        const Attempt attempt = relax(u, load_factor, dt);
        result.total_iterations += attempt.iterations;
        if (attempt.converged)
          return attempt;
        u = last_converged;
        std::ostringstream where;
        where << "dynamic relaxation, load step " << step << " (load factor "
              << load_factor << "), time step " << dt << ", iteration "
              << attempt.iterations << ": " << attempt.reason;
        if (!attempt.unstable)
          throw SolverFailure(where.str());
        if (!(0.5 * dt >= min_dt))
          throw SolverFailure(where.str() +
                              "; the time step cannot be cut below " +
                              std::to_string(min_dt));
        if (log != nullptr)
          *log << where.str() << "; retrying with time step " << 0.5 * dt
               << std::endl;
        dt *= 0.5;
        ++result.time_step_cuts;
      }
  }


  DynamicRelaxation::Result
  DynamicRelaxation::run(DrVector &u, const Observer &on_converged)
  {
    if (u.size() != model.n_dofs())
      throw std::invalid_argument(
        "dynamic relaxation: the state has " + std::to_string(u.size()) +
        " entries, the model " + std::to_string(model.n_dofs()) + " DoFs");
    Result   result;
    double   dt             = parameters.time_step;
    DrVector last_converged = u;

    for (unsigned int step = 1; step <= parameters.n_steps; ++step)
      {
        const auto    start       = std::chrono::steady_clock::now();
        const double  load_factor = double(step) / parameters.n_steps;
        const Attempt attempt     = relax_cutting_time_step(u,
                                                        last_converged,
                                                        step,
                                                        load_factor,
                                                        dt,
                                                        result);
        // The outputs read every entry (several processes: each moved its
        // own).
        model.process_share().complete(u);
        last_converged = u;

        StepInfo info;
        info.step          = step;
        info.load_factor   = load_factor;
        info.iterations    = attempt.iterations;
        info.peaks         = attempt.peaks;
        info.residual_norm = attempt.residual_norm;
        info.time_step     = dt;
        info.wall_time     = std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count();
        if (log != nullptr)
          *log << "  DR step " << step << ", load factor " << load_factor
               << ": " << attempt.iterations << " iterations, " << attempt.peaks
               << " kinetic-energy peaks, |R| " << attempt.residual_norm << ", "
               << info.wall_time << " s" << std::endl;
        on_converged(info, u);
        ++result.steps;
      }
    result.time_step = dt;
    return result;
  }
} // namespace rodnet
