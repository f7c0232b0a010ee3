#include <solvers/time/newmark_scheme.h>

namespace rodnet
{
  NewmarkScheme::NewmarkScheme(const StepSystem &system)
      : IntegrationScheme(system)
      , inertial_force(system.model.create_vector())
  {
  }

  void
  NewmarkScheme::start(const VectorType &u,
                       const VectorType &v,
                       const double      load_factor)
  {
    initial_inertial_force(u, v, load_factor, inertial_force);
  }

  void
  NewmarkScheme::finish(const StepStart  &step,
                        const VectorType &x,
                        VectorType       &v)
  {
    second_order_velocity(step, x, v);
    VectorType change = x;
    change -= step.base;
    VectorType mass_change = change;
    system.mass.vmult(mass_change, change);
    inertial_force *= -1.0;
    inertial_force.add(mass_coefficient(step.h), mass_change);
  }
} // namespace rodnet
