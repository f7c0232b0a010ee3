// The registry of integration schemes: a new scheme adds its line to
// `registry` below (name and factory) and nothing else.
#include <solvers/backward_euler_scheme.h>
#include <solvers/integration_scheme_registry.h>
#include <solvers/midpoint_scheme.h>
#include <solvers/newmark_scheme.h>
#include <solvers/quasi_static_scheme.h>

#include <functional>
#include <stdexcept>
#include <utility>

namespace rodnet
{
  namespace
  {
    using Factory =
      std::function<std::unique_ptr<IntegrationScheme>(const StepSystem &)>;

    template <typename Scheme>
    std::unique_ptr<IntegrationScheme>
    make(const StepSystem &system)
    {
      return std::make_unique<Scheme>(system);
    }

    const std::vector<std::pair<std::string, Factory>> &
    registry()
    {
      static const std::vector<std::pair<std::string, Factory>> schemes = {
        {"quasi-static", make<QuasiStaticScheme>},
        {"backward euler", make<BackwardEulerScheme>},
        {"newmark", make<NewmarkScheme>},
        {"midpoint", make<MidpointScheme>}};
      return schemes;
    }
  } // namespace

  std::vector<std::string>
  integration_scheme_names()
  {
    std::vector<std::string> names;
    for (const auto &entry : registry())
      names.push_back(entry.first);
    return names;
  }

  std::unique_ptr<IntegrationScheme>
  create_integration_scheme(const std::string &name, const StepSystem &system)
  {
    std::string known;
    for (const auto &[registered, factory] : registry())
      {
        if (registered == name)
          return factory(system);
        known += (known.empty() ? "" : ", ") + registered;
      }
    throw std::invalid_argument("unknown time integrator \"" + name +
                                "\"; known: " + known);
  }
} // namespace rodnet
