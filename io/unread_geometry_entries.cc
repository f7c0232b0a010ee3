#include <io/generator_registry.h>
#include <io/unread_geometry_entries.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    /// The entries that the generator @p name declares of its own.
    std::vector<std::string>
    own_entries(const std::string &name)
    {
      dealii::ParameterHandler prm;
      GeneratorRegistry::instance().create(name)->declare_parameters(prm);
      std::vector<std::string> entries;
      for (const EntryNode &node : entry_tree(prm).children)
        if (node.is_entry)
          entries.push_back(node.name);
      return entries;
    }

    /// True if @p geometry has the entry @p name set off its default.
    bool
    is_set(const EntryNode &geometry, const std::string &name)
    {
      const EntryNode *entry = geometry.find(name);
      return entry != nullptr && !entry->holds_default();
    }

    /// "the a generator does", "the a and b generators do", "the a, b
    /// and c generators do".
    std::string
    generators_do(const std::vector<std::string> &names)
    {
      std::string list = "the " + names.front();
      for (std::size_t i = 1; i < names.size(); ++i)
        list += (i + 1 == names.size() ? " and " : ", ") + names[i];
      return list + (names.size() > 1 ? " generators do" : " generator does");
    }
  } // namespace

  void
  refuse_unread_geometry_entries(const EntryNode   &geometry,
                                 const std::string &generator)
  {
    const GeneratorRegistry &registry = GeneratorRegistry::instance();
    for (const UnreadEntry &unread :
         registry.create(generator)->unread_shared_entries())
      if (is_set(geometry, unread.entry))
        throw std::invalid_argument(
          "entry \"Geometry/" + unread.entry + "\": the " + generator +
          " generator does not read it: " + unread.reason + "; remove it");
    // Every generator's own entries, and who declares each.
    std::map<std::string, std::vector<std::string>> owners;
    for (const std::string &name : registry.names())
      for (const std::string &entry : own_entries(name))
        owners[entry].push_back(name);
    for (const auto &[entry, names] : owners)
      if (std::find(names.begin(), names.end(), generator) == names.end() &&
          is_set(geometry, entry))
        throw std::invalid_argument("entry \"Geometry/" + entry + "\": the " +
                                    generator +
                                    " generator does not read it, only " +
                                    generators_do(names) + "; remove it");
  }
} // namespace rodnet
