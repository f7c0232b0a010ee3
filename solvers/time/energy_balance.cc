// The energy watch of dynamic runs: the total energy against the work of
// the loads, fields and moving supports (solvers/time/energy_balance.h).
#include <core/every_entry.h>
#include <solvers/solver_failure.h>
#include <solvers/time/energy_balance.h>
#include <solvers/time/tensor_body_support_work.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rodnet
{
  namespace
  {
    std::string
    energy_string(const double value)
    {
      std::ostringstream s;
      s.precision(6);
      s << value;
      return s.str();
    }
  } // namespace

  EnergyBalance::EnergyBalance(SolvableModel    &model,
                               const MatrixType &mass,
                               const MatrixType &damping)
      : model(model)
      , mass(mass)
      , damping(damping)
      , follows_load_factor(model.potential_follows_load_factor())
      , follows_time(model.potential_follows_time())
      , is_fixed(model.layout().n_dofs(), false)
      , roles(model)
      , tensor_bodies(rodnet::tensor_bodies(model))
  {
    // The supports' DoFs are the constraint lines without entries; the
    // junction copies' lines have theirs.
    for (const auto &line : model.constraints().get_lines())
      if (line.entries.empty())
        {
          fixed.push_back(line.index);
          is_fixed[line.index] = true;
        }
  }

  void
  EnergyBalance::start(const bool   on,
                       const double limit,
                       const double kinetic,
                       const double potential)
  {
    watching       = on;
    growth_limit   = limit;
    start_energy   = kinetic + potential;
    scale          = std::abs(start_energy);
    balance        = 0;
    external_work  = 0;
    last_kinetic   = kinetic;
    last_potential = potential;
    step_moved     = false;
    last_motion    = {};
    residual_bound = 0;
  }

  bool
  EnergyBalance::parameters_move(
    const StepEnds                      &ends,
    const std::function<double(double)> &load_factor)
  {
    // Only what the potential follows can move it: a model without loads,
    // shapes or fields ramped or driven in time is not even put at the
    // step's times.
    if (!follows_load_factor && !follows_time)
      return false;
    // The loads and fields at the step's ends and force points.
    std::vector<double> times = {ends.time, ends.end_time};
    for (const ForcePoint &point : ends.force_points)
      times.push_back(ends.time + point.s * (ends.end_time - ends.time));
    if (follows_time)
      model.set_time(times[0]);
    const double              lambda = load_factor(times[0]);
    const std::vector<double> fields = model.activation_time_factors();
    bool                      moved  = false;
    for (const double t : times)
      {
        if (follows_time)
          model.set_time(t);
        moved = moved || (follows_load_factor && load_factor(t) != lambda) ||
                model.activation_time_factors() != fields;
      }
    return moved;
  }

  void
  EnergyBalance::add_step(const StepEnds                      &ends,
                          const std::function<double(double)> &load_factor)
  {
    // The fixed DoFs and the motion anywhere: read from replicas on
    // several processes, so that every process takes the same branch.
    const EveryEntry u0(ends.u0), u1(ends.u1);
    const bool       supports_move =
      std::any_of(fixed.begin(), fixed.end(), [&](const auto i) {
        return (*u1)[i] != (*u0)[i];
      });
    step_moved            = parameters_move(ends, load_factor) || supports_move;
    last_motion           = step_motion(*u0, *u1);
    step_potential_change = 0;
    step_support_work     = 0;
    if (step_moved)
      {
        // Per force point, at its time t_n + s h: the potential's change
        // over the step and, where a support moves, grad Pi at the point.
        const double h = ends.end_time - ends.time;
        VectorType   point(ends.u0), gradient(ends.u0), force(ends.u0);
        force = 0;
        for (const auto &[s, weight] : ends.force_points)
          {
            if (follows_time)
              model.set_time(ends.time + s * h);
            const double lambda = load_factor(ends.time + s * h);
            double       energy = std::nan("");
            if (supports_move)
              {
                point.sadd(0.0, 1 - s, ends.u0);
                point.add(s, ends.u1);
                energy =
                  model.assemble(point, lambda, &gradient, nullptr, false);
                force.add(weight, gradient);
              }
            const double start =
              s == 0 && supports_move ?
                energy :
                model.assemble(ends.u0, lambda, nullptr, nullptr);
            const double end =
              s == 1 && supports_move ?
                energy :
                model.assemble(ends.u1, lambda, nullptr, nullptr);
            step_potential_change += weight * (end - start);
          }
        if (supports_move)
          step_support_work = support_work(ends, force);
      }
    if (follows_time)
      model.set_time(ends.end_time);
  }

  double
  EnergyBalance::support_work(const StepEnds   &ends,
                              const VectorType &force) const
  {
    // The impulse h (M a + C v) over the step: M (v_{n+1} - v_n) and the
    // damping force at the mean velocity.
    const double h = ends.end_time - ends.time;
    VectorType   velocity_change(ends.v1), impulse(ends.v1);
    velocity_change -= ends.v0;
    mass.vmult(impulse, velocity_change);
    // What tensor bodies' inertia adds on their held rows, from M (v_{n+1}
    // - v_n) before the damping joins it; every process the reactions of
    // every body, from replicas.
    const EveryEntry                                 u0(ends.u0), u1(ends.u1);
    std::vector<std::pair<global_dof_index, double>> body_reaction;
    if (!tensor_bodies.empty())
      {
        const EveryEntry v0(ends.v0), change(impulse);
        body_reaction = tensor_body_reaction(model,
                                             tensor_bodies,
                                             is_fixed,
                                             *u0,
                                             *u1,
                                             *v0,
                                             *change,
                                             h);
      }
    if (damping.m() != 0)
      {
        VectorType mean_velocity(ends.v1), damping_force(ends.v1);
        mean_velocity += ends.v0;
        damping.vmult(damping_force, mean_velocity);
        impulse.add(h / 2, damping_force);
      }
    const EveryEntry every_impulse(impulse), every_force(force);
    double           work = 0;
    for (const global_dof_index i : fixed)
      work +=
        ((*every_impulse)[i] / h + (*every_force)[i]) * ((*u1)[i] - (*u0)[i]);
    for (const auto &[i, reaction] : body_reaction)
      work += reaction * ((*u1)[i] - (*u0)[i]);
    return work;
  }

  ResidualParts
  EnergyBalance::step_motion(const VectorType &u0, const VectorType &u1) const
  {
    using Kind      = DofRoles::Kind;
    double position = 0, angle = 0;
    for (global_dof_index i = 0; i < roles.n_dofs(); ++i)
      if (!model.constraints().is_constrained(i))
        {
          const double d = u1[i] - u0[i];
          if (roles.kind(i) == Kind::position)
            position += d * d;
          else if (roles.kind(i) == Kind::twist)
            angle += d * d;
          else if (roles.kind(i) == Kind::quaternion)
            angle += 4 * d * d;
        }
    return {std::sqrt(position), std::sqrt(angle)};
  }

  void
  EnergyBalance::check(const std::string   &who,
                       const std::string   &advice,
                       const double         time,
                       const double         kinetic,
                       const double         potential,
                       const ResidualParts &residual)
  {
    if (!watching)
      return;
    const double energy_change =
      kinetic + potential - last_kinetic - last_potential;
    const double step_balance =
      step_moved ?
        kinetic - last_kinetic + step_potential_change - step_support_work :
        energy_change;
    balance += step_balance;
    external_work += energy_change - step_balance;
    last_kinetic   = kinetic;
    last_potential = potential;
    step_moved     = false;
    scale          = std::max(
      {scale, kinetic, std::abs(kinetic + potential), std::abs(external_work)});
    // The step's energy error r . d within the norms of its residual and
    // motion: a balance within their sum is no growth.
    residual_bound +=
      residual.force * last_motion.force + residual.moment * last_motion.moment;
    if (balance > std::max(growth_limit * scale, residual_bound))
      throw SolverFailure(
        who + ": unstable at t = " + energy_string(time) +
        " s, the energy grew from " + energy_string(start_energy) + " to " +
        energy_string(kinetic + potential) + " J, " + energy_string(balance) +
        " J more than the work the loads and supports did on the model (" +
        energy_string(external_work) + " J); take a smaller time step" +
        advice);
  }
} // namespace rodnet
