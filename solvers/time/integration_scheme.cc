#include <solvers/time/integration_scheme.h>
#include <solvers/time/integration_scheme_registry.h>

namespace rodnet
{
  void
  StepSystem::zero_massless_rows(VectorType &v) const
  {
    for (const global_dof_index i : massless_rows)
      v[i] = 0;
    v.compress(dealii::VectorOperation::insert);
  }

  bool
  IntegrationScheme::dynamic() const
  {
    return integration_scheme_registry().traits(name()).dynamic;
  }

  bool
  IntegrationScheme::needs_stored_energy() const
  {
    return integration_scheme_registry().traits(name()).needs_stored_energy;
  }

  void
  IntegrationScheme::set_up(const StepStart       &step,
                            NewtonSolver::Problem &problem)
  {
    const double c = mass_coefficient(step.h);
    // The step minimizes Pi(y) + c/2 |y - base|_M^2 - p . y (the
    // incremental potential of the scheme), whose gradient is the residual.
    problem.set_potential([this, &step](const VectorType &y, VectorType *r) {
      const double energy =
        system.model.assemble(y, step.load_factor, r, nullptr, true);
      return energy + add_inertia(step, y, r);
    });
    problem.tangent = [this, &step, c](const VectorType &y, MatrixType &k) {
      system.model.assemble(y, step.load_factor, nullptr, &k, true);
      if (c != 0)
        k.add(c, system.constrained_mass);
      add_damping_tangent(step.h, k);
    };
  }

  double
  IntegrationScheme::add_inertia(const StepStart  &step,
                                 const VectorType &y,
                                 VectorType       *r)
  {
    const double c = mass_coefficient(step.h);
    if (c == 0)
      return 0;
    if (difference.size() != y.size())
      {
        difference.reinit(y);
        product.reinit(y);
      }
    difference = y;
    difference -= step.base;
    system.mass.vmult(product, difference);
    const VectorType *extra = extra_inertial_force();
    const double      energy =
      0.5 * c * (difference * product) - (extra != nullptr ? *extra * y : 0.0);
    if (r != nullptr)
      {
        r->add(c, product);
        if (extra != nullptr)
          r->add(-1.0, *extra);
      }
    const double dissipation = add_damping(step, y, r);
    if (r != nullptr)
      system.model.constraints().set_zero(*r);
    return energy + dissipation;
  }

  double
  IntegrationScheme::add_damping(const StepStart  &step,
                                 const VectorType &y,
                                 VectorType       *r)
  {
    if (system.damping.m() == 0)
      return 0;
    if (damped_velocity.size() != y.size())
      {
        damped_velocity.reinit(y);
        damping_force.reinit(y);
      }
    // The force C v at v = a d - b v_n, d = y - u_n, is the gradient of
    // a/2 d.C d - b y.C v_n: the scheme's Rayleigh dissipation function
    // over the step, which keeps the step a minimization.
    const auto [a, b] = damping_velocity(step.h);
    damped_velocity   = y;
    damped_velocity -= step.u;
    system.damping.vmult(damping_force, damped_velocity);
    double potential = 0.5 * a * (damped_velocity * damping_force);
    damping_force *= a;
    if (b != 0)
      {
        // v_n = (base - u_n) / h.
        damped_velocity = step.base;
        damped_velocity -= step.u;
        damped_velocity *= b / step.h;
        VectorType start_force(damped_velocity);
        system.damping.vmult(start_force, damped_velocity);
        potential -= y * start_force;
        damping_force -= start_force;
      }
    if (r != nullptr)
      r->add(1.0, damping_force);
    return potential;
  }

  void
  IntegrationScheme::add_damping_tangent(const double h, MatrixType &k) const
  {
    if (system.damping.m() != 0)
      k.add(damping_velocity(h).a, system.constrained_damping);
  }

  void
  IntegrationScheme::initial_inertial_force(const VectorType &u,
                                            const VectorType &v,
                                            const double      load_factor,
                                            VectorType       &force) const
  {
    system.model.assemble(u, load_factor, &force, nullptr, true);
    if (system.damping.m() != 0)
      system.damping.vmult_add(force, v);
    force *= -1.0;
    system.zero_massless_rows(force);
  }

  void
  IntegrationScheme::first_order_velocity(const StepStart  &step,
                                          const VectorType &x,
                                          VectorType       &v)
  {
    v = x;
    v -= step.u;
    v /= step.h;
  }

  void
  IntegrationScheme::second_order_velocity(const StepStart  &step,
                                           const VectorType &x,
                                           VectorType       &v)
  {
    // v_{n+1} = 2 (x - u_n) / h - v_n, in the order of the original
    // update: v = -v_n, then v += (2 / h) (x - u_n).
    VectorType change = x;
    change -= step.u;
    v *= -1.0;
    v.add(2 / step.h, change);
  }
} // namespace rodnet
