#include <io/generator_registry.h>
#include <io/network_generator_entries.h>
#include <io/rod_generator_entries.h>

#include <stdexcept>

namespace rodnet
{
  std::optional<ProblemSize>
  GeometryGenerator::planned_size(const dealii::ParameterHandler &,
                                  const GeneratorInput &) const
  {
    return std::nullopt;
  }

  std::string
  GeometryGenerator::size_entry() const
  {
    return "Geometry/Segments";
  }

  bool
  GeometryGenerator::open_rods() const
  {
    return false;
  }

  const GeneratorRegistry &
  GeneratorRegistry::instance()
  {
    // Registered here, in the order of the "Generator" selection, rather
    // than by static objects: that order would depend on the link order.
    static const GeneratorRegistry registry = [] {
      GeneratorRegistry r;
      register_rod_generators(r);
      register_network_generators(r);
      return r;
    }();
    return registry;
  }

  void
  GeneratorRegistry::add(const std::string &name,
                         const std::string &description,
                         Factory            factory)
  {
    for (const Entry &e : entries)
      if (e.name == name)
        throw std::logic_error("generator \"" + name + "\" registered twice");
    entries.push_back({name, description, std::move(factory)});
  }

  const GeneratorRegistry::Entry &
  GeneratorRegistry::find(const std::string &name) const
  {
    std::string known;
    for (const Entry &e : entries)
      {
        if (e.name == name)
          return e;
        known += (known.empty() ? "" : ", ") + e.name;
      }
    throw std::invalid_argument(
      "unknown generator \"" + name +
      "\"; known generators: " + (known.empty() ? "(none)" : known));
  }

  std::unique_ptr<GeometryGenerator>
  GeneratorRegistry::create(const std::string &name) const
  {
    return find(name).factory();
  }

  std::vector<std::string>
  GeneratorRegistry::names() const
  {
    std::vector<std::string> result;
    for (const Entry &e : entries)
      result.push_back(e.name);
    return result;
  }

  std::string
  GeneratorRegistry::description(const std::string &name) const
  {
    return find(name).description;
  }
} // namespace rodnet
