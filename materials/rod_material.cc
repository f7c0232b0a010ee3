#include <deal.II/base/exceptions.h>

#include <materials/rod_material.h>

#include <stdexcept>
#include <utility>

namespace rodnet
{
  namespace
  {
    /// Throws std::invalid_argument listing the registered names unless
    /// @p name is one of them.
    template <typename Map>
    auto
    find_or_throw(const Map &entries, const std::string &name)
    {
      const auto found = entries.find(name);
      if (found == entries.end())
        {
          std::string known;
          for (const auto &entry : entries)
            known += (known.empty() ? "" : ", ") + entry.first;
          throw std::invalid_argument(
            "unknown material \"" + name +
            "\"; known materials: " + (known.empty() ? "(none)" : known));
        }
      return found;
    }
  } // namespace


  MaterialRegistry &
  MaterialRegistry::instance()
  {
    // A function-local static is built on first use, so registrations from
    // static objects in other translation units cannot run before it exists.
    static MaterialRegistry registry;
    return registry;
  }


  void
  MaterialRegistry::add(const std::string &name,
                        const std::string &description,
                        Factory            factory)
  {
    Assert(factory, dealii::ExcMessage("null factory for material " + name));
    // Two classes under one name would make create() depend on static
    // initialization order, so fail even in Release.
    AssertThrow(entries.count(name) == 0,
                dealii::ExcMessage("material \"" + name +
                                   "\" registered twice"));
    entries.emplace(name, Entry{description, std::move(factory)});
  }


  std::unique_ptr<RodMaterial>
  MaterialRegistry::create(const std::string &name) const
  {
    return find_or_throw(entries, name)->second.factory();
  }


  std::vector<std::string>
  MaterialRegistry::names() const
  {
    std::vector<std::string> result;
    for (const auto &entry : entries)
      result.push_back(entry.first);
    return result;
  }


  std::string
  MaterialRegistry::description(const std::string &name) const
  {
    return find_or_throw(entries, name)->second.description;
  }
} // namespace rodnet
