#ifndef RODNET_BASE_REGISTRY_H
#define RODNET_BASE_REGISTRY_H

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * A name-keyed factory of extensions of one kind (ASPECT's plugin
   * pattern): hinge measures, materials, element families. Each entry has a
   * name, a one-line description and a factory; an unknown name is refused
   * with a message that lists the known ones. Names are kept sorted, so
   * listings do not depend on the order in which registrations run.
   *
   * Every kind has one registry object, returned by a function of its own
   * (defined in one .cc file, so that the library and the programs linked
   * to it share it); implementations add themselves with a static object
   * in their own .cc file, the one registration line of an extension.
   */
  template <class Product, class... Arguments>
  class Registry
  {
  public:
    using Factory = std::function<std::unique_ptr<Product>(Arguments...)>;

    /// @p singular and @p plural name the kind in messages ("material",
    /// "materials").
    Registry(std::string singular, std::string plural)
        : singular(std::move(singular))
        , plural(std::move(plural))
    {
    }

    /// Registers @p factory under @p name; a name registered twice is a
    /// programming error (create() would depend on the order of static
    /// initialization), refused with std::logic_error.
    void
    add(const std::string &name,
        const std::string &description,
        Factory            factory)
    {
      if (!factory || !entries.emplace(name, Entry{description, factory}).second)
        throw std::logic_error(singular + " \"" + name +
                               "\" registered twice or without a factory");
    }

    /// Creates the extension registered as @p name; throws
    /// std::invalid_argument listing the known names otherwise.
    std::unique_ptr<Product>
    create(const std::string &name, Arguments... arguments) const
    {
      return find(name).factory(std::forward<Arguments>(arguments)...);
    }

    /// Whether @p name is registered.
    bool
    contains(const std::string &name) const
    {
      return entries.count(name) > 0;
    }

    /// Registered names, sorted.
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const auto &entry : entries)
        result.push_back(entry.first);
      return result;
    }

    /// Description given at registration.
    const std::string &
    description(const std::string &name) const
    {
      return find(name).description;
    }

  private:
    struct Entry
    {
      std::string description;
      Factory     factory;
    };

    const Entry &
    find(const std::string &name) const
    {
      const auto found = entries.find(name);
      if (found != entries.end())
        return found->second;
      std::string known;
      for (const auto &entry : entries)
        known += (known.empty() ? "\"" : ", \"") + entry.first + '"';
      throw std::invalid_argument("unknown " + singular + " \"" + name +
                                  "\"; known " + plural + ": " +
                                  (known.empty() ? "(none)" : known));
    }

    std::string                  singular;
    std::string                  plural;
    std::map<std::string, Entry> entries;
  };
} // namespace rodnet

#endif
