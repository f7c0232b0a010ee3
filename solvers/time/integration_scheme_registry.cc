// The registry of integration schemes: a new scheme adds its line (class,
// name, description, traits) to the list below and nothing else.
#include <solvers/time/backward_euler_scheme.h>
#include <solvers/time/generalized_alpha_scheme.h>
#include <solvers/time/integration_scheme_registry.h>
#include <solvers/time/midpoint_scheme.h>
#include <solvers/time/newmark_scheme.h>
#include <solvers/time/quasi_static_scheme.h>

namespace rodnet
{
  const IntegrationSchemeRegistry &
  integration_scheme_registry()
  {
    // One explicit list rather than static objects: its order is that of
    // the "Integrator" selection.
    static const IntegrationSchemeRegistry registry = [] {
      IntegrationSchemeRegistry     r("time integrator",
                                  "time integrators",
                                  RegistryOrder::registration);
      const IntegrationSchemeTraits inertia, no_inertia{false, false},
        conserving{true, true};
      r.add<QuasiStaticScheme>(
        "quasi-static",
        "equilibrium at every time, no inertia (creep, relaxation)",
        no_inertia);
      r.add<BackwardEulerScheme>("backward euler",
                                 "first order, damped",
                                 inertia);
      r.add<NewmarkScheme>("newmark",
                           "average acceleration, second order, undamped",
                           inertia);
      r.add<MidpointScheme>(
        "midpoint",
        "midpoint rule with a discrete gradient, conserves the energy of "
        "elastic rods (not viscoelastic)",
        conserving);
      r.add<GeneralizedAlphaScheme>("generalized alpha",
                                    "second order, damps stiff modes",
                                    inertia);
      return r;
    }();
    return registry;
  }
} // namespace rodnet
