// The registry of line searches: a new one adds its line (name,
// description, traits, factory) to the list below and nothing else.
#include <solvers/newton/energy_line_search.h>
#include <solvers/newton/newton_globalization.h>
#include <solvers/newton/nox_line_search.h>
#include <solvers/newton/trust_region_newton.h>

#include <memory>

namespace rodnet
{
  namespace
  {
    /// A factory of NOX's line search @p method.
    LineSearchRegistry::Factory
    nox_method(const std::string &method)
    {
      return [method] { return std::make_unique<NoxLineSearch>(method); };
    }
  } // namespace

  const LineSearchRegistry &
  line_search_registry()
  {
    // One explicit list rather than static objects: its order is that of
    // the "Line search" selection.
    static const LineSearchRegistry registry = [] {
      LineSearchRegistry r("line search",
                           "line searches",
                           RegistryOrder::registration);
      r.add("energy",
            "Wolfe conditions on the potential",
            {true, "the energy line search"},
            [] {
              return std::make_unique<NoxLineSearch>(
                "User Defined",
                Teuchos::rcp(new EnergyLineSearchFactory));
            });
      r.add("backtrack",
            "NOX's backtracking on |R|",
            {false, "the backtracking line search"},
            nox_method("Backtrack"));
      r.add("polynomial",
            "NOX's polynomial fit on |R|",
            {false, "the polynomial line search"},
            nox_method("Polynomial"));
      r.add("full step",
            "the Newton step as it is",
            {false, "Newton in full steps"},
            nox_method("Full Step"));
      r.add<TrustRegionGlobalization>(
        "trust region",
        "on the potential's quadratic model",
        {true, "the trust region"});
      return r;
    }();
    return registry;
  }
} // namespace rodnet
