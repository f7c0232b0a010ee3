#include <io/generator_registry.h>
#include <io/network_generator_entries.h>
#include <io/rod_generator_entries.h>

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

  std::vector<UnreadEntry>
  GeometryGenerator::unread_shared_entries() const
  {
    return {};
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
} // namespace rodnet
