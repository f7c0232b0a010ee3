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
  /// The order in which a Registry lists its names.
  enum class RegistryOrder
  {
    /// Sorted, so that listings do not depend on the order in which
    /// registrations by static objects in several files run.
    sorted,
    /// The order of registration, for a registry filled from one explicit
    /// list whose order means something (the first name is the default of
    /// a scene's selection, the list is its order in --help).
    registration
  };

  /**
   * A name-keyed factory of extensions of one kind (ASPECT's plugin
   * pattern): hinge measures, materials, element families, geometry
   * generators, time integrators. Each entry has a name, a one-line
   * description and a factory; an unknown name is refused with a message
   * that lists the known ones. Names are listed sorted, or in the order of
   * registration (RegistryOrder).
   *
   * Every kind has one registry object, returned by a function of its own
   * (defined in one .cc file, so that the library and the programs linked
   * to it share it); implementations add themselves with a static object
   * in their own .cc file, the one registration line of an extension, or,
   * where the order of registration matters, with one line each in one
   * explicit list.
   */
  template <class Product, class... Arguments>
  class Registry
  {
  public:
    using Factory = std::function<std::unique_ptr<Product>(Arguments...)>;

    /// @p singular and @p plural name the kind in messages ("material",
    /// "materials"); @p order is the order of names().
    Registry(std::string         singular,
             std::string         plural,
             const RegistryOrder order = RegistryOrder::sorted)
        : singular(std::move(singular))
        , plural(std::move(plural))
        , order(order)
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
      registered.push_back(name);
    }

    /// Registers @p Extension, made from the arguments of create(), under
    /// @p name.
    template <class Extension>
    void
    add(const std::string &name, const std::string &description)
    {
      add(name, description, [](Arguments... arguments) {
        return std::make_unique<Extension>(
          std::forward<Arguments>(arguments)...);
      });
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

    /// Registered names, sorted or in the order of registration.
    std::vector<std::string>
    names() const
    {
      if (order == RegistryOrder::registration)
        return registered;
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

    /// The names joined by "|", in the order of names(): the choices of a
    /// dealii::Patterns::Selection.
    std::string
    selection() const
    {
      std::string joined;
      for (const std::string &name : names())
        joined += (joined.empty() ? "" : "|") + name;
      return joined;
    }

    /// "name: description. " for every name, in the order of names(): the
    /// help of a selection.
    std::string
    listing() const
    {
      std::string text;
      for (const std::string &name : names())
        text += name + ": " + description(name) + ". ";
      return text;
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
      for (const std::string &n : names())
        known += (known.empty() ? "\"" : ", \"") + n + '"';
      throw std::invalid_argument("unknown " + singular + " \"" + name +
                                  "\"; known " + plural + ": " +
                                  (known.empty() ? "(none)" : known));
    }

    std::string                  singular;
    std::string                  plural;
    RegistryOrder                order;
    std::map<std::string, Entry> entries;
    /// The names in the order of registration.
    std::vector<std::string> registered;
  };

  /**
   * A Registry whose entries carry traits as well: what a caller needs to
   * know of an extension before it can make one (whether a time integrator
   * has inertia, whether a line search needs a potential). Each entry is
   * registered with its traits.
   */
  template <class Traits, class Product, class... Arguments>
  class TraitRegistry : public Registry<Product, Arguments...>
  {
  public:
    using Base    = Registry<Product, Arguments...>;
    using Factory = typename Base::Factory;
    using Base::Base;

    /// Registers @p factory with its @p traits under @p name.
    void
    add(const std::string &name,
        const std::string &description,
        const Traits      &traits,
        Factory            factory)
    {
      Base::add(name, description, std::move(factory));
      traits_of.emplace(name, traits);
    }

    /// Registers @p Extension, made from the arguments of create(), with
    /// its @p traits under @p name.
    template <class Extension>
    void
    add(const std::string &name,
        const std::string &description,
        const Traits      &traits)
    {
      Base::template add<Extension>(name, description);
      traits_of.emplace(name, traits);
    }

    /// The traits of @p name; throws std::invalid_argument listing the
    /// known names for an unknown one.
    const Traits &
    traits(const std::string &name) const
    {
      // description() refuses an unknown name with the registry's message.
      Base::description(name);
      return traits_of.at(name);
    }

  private:
    std::map<std::string, Traits> traits_of;
  };
} // namespace rodnet

#endif
