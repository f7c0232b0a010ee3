#ifndef RODNET_SOLVERS_TIME_INTEGRATION_SCHEME_REGISTRY_H
#define RODNET_SOLVERS_TIME_INTEGRATION_SCHEME_REGISTRY_H

#include <base/registry.h>
#include <solvers/time/integration_scheme.h>

namespace rodnet
{
  /// What a scene must know of an integrator before there is a model to
  /// make its scheme on.
  struct IntegrationSchemeTraits
  {
    /// Whether it has inertia (needs the mass matrix and every material's
    /// density).
    bool dynamic = true;
    /// Whether it conserves a stored energy, which materials with internal
    /// variables (viscoelastic laws) do not have.
    bool needs_stored_energy = false;
  };

  /// Integration schemes by name, made on a StepSystem, with their traits.
  using IntegrationSchemeRegistry = TraitRegistry<IntegrationSchemeTraits,
                                                  IntegrationScheme,
                                                  const StepSystem &>;

  /**
   * The time integrators (TimeIntegrator::Parameters::integrator, the scene
   * entry "Integrator"), in the order of registration, which is the order
   * of the selection and its help in --help: "quasi-static", "backward
   * euler", "newmark", "midpoint", "generalized alpha". A new scheme adds
   * its line to integration_scheme_registry.cc.
   */
  const IntegrationSchemeRegistry &
  integration_scheme_registry();
} // namespace rodnet

#endif
