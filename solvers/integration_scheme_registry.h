#ifndef RODNET_SOLVERS_INTEGRATION_SCHEME_REGISTRY_H
#define RODNET_SOLVERS_INTEGRATION_SCHEME_REGISTRY_H

#include <solvers/integration_scheme.h>

#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /// The names of the registered integration schemes, in the order of
  /// registration ("quasi-static", "backward euler", "newmark",
  /// "midpoint").
  std::vector<std::string>
  integration_scheme_names();

  /**
   * The scheme registered as @p name, working on @p system (which must
   * outlive it). Throws std::invalid_argument for an unknown name, listing
   * the known ones.
   */
  std::unique_ptr<IntegrationScheme>
  create_integration_scheme(const std::string &name, const StepSystem &system);
} // namespace rodnet

#endif
