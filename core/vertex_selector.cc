#include <deal.II/base/utilities.h>

#include <base/nearest_names.h>
#include <core/vertex_selector.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    /// At most this many names are listed where a name is unknown.
    constexpr unsigned int max_names_listed = 8;

    /// True if @p where names a place along a rod: start, end, mid or a
    /// vertex index.
    bool
    is_place_along_a_rod(const std::string &where)
    {
      if (where == "start" || where == "end" || where == "mid")
        return true;
      try
        {
          std::size_t used = 0;
          std::stoi(where, &used);
          return used == where.size();
        }
      catch (const std::exception &)
        {
          return false;
        }
    }

    /// The message that refuses the unknown @p name of a @p kind ("vertex
    /// or junction") in @p entry: the names there are, or the nearest ones
    /// where there are many.
    std::string
    unknown_name(const std::string              &entry,
                 const std::string              &kind,
                 const std::string              &name,
                 const std::vector<std::string> &names)
    {
      std::string message = "entry \"" + entry + "\": there is no " + kind +
                            " called \"" + name + "\"; ";
      if (names.empty())
        return message + "the scene names none (networks name their nodes)";
      if (names.size() <= max_names_listed)
        return message + "the names are " + quoted_list(names);
      return message + "the nearest of its " + std::to_string(names.size()) +
             " names are " +
             quoted_list(nearest_names(names, name, max_names_listed));
    }

    /// Splits "rod:where" into the rod index and "where". A place along a
    /// rod without the rod means rod 0 in a scene of one rod; where there
    /// are more rods it is ambiguous and refused, @p named_vertex saying
    /// how else to name the place.
    std::pair<unsigned int, std::string>
    split_rod(const RodNetwork  &network,
              const std::string &text,
              const std::string &entry,
              const std::string &named_vertex)
    {
      const std::string trimmed = dealii::Utilities::trim(text);
      const auto        colon   = trimmed.find(':');
      const std::size_t n_rods  = network.rods().size();
      if (colon == std::string::npos)
        {
          if (n_rods > 1 && is_place_along_a_rod(trimmed))
            throw std::invalid_argument(
              "entry \"" + entry + "\": \"" + trimmed +
              "\" names no rod, and the scene has " + std::to_string(n_rods) +
              " rods; write \"<rod>:" + trimmed + "\" (\"0:" + trimmed +
              "\" for rod 0) or " + named_vertex);
          return {0, trimmed};
        }
      const std::string rod_text =
        dealii::Utilities::trim(trimmed.substr(0, colon));
      unsigned int rod = 0;
      try
        {
          std::size_t used = 0;
          const int   r    = std::stoi(rod_text, &used);
          if (used != rod_text.size() || r < 0)
            throw std::invalid_argument("");
          rod = r;
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument("entry \"" + entry + "\": \"" + rod_text +
                                      "\" is not a rod index in \"" + text +
                                      "\"");
        }
      if (rod >= n_rods)
        throw std::invalid_argument("entry \"" + entry + "\": rod " +
                                    std::to_string(rod) +
                                    " does not exist (the scene has " +
                                    std::to_string(n_rods) + " rods)");
      return {rod, dealii::Utilities::trim(trimmed.substr(colon + 1))};
    }

    /// The vertex called @p name ("@name" without the "@"); throws naming
    /// @p entry where there is none.
    unsigned int
    vertex_called(const RodNetwork  &network,
                  const std::string &name,
                  const std::string &entry)
    {
      const std::vector<std::string> names = network.vertex_name_list();
      if (!std::binary_search(names.begin(), names.end(), name))
        throw std::invalid_argument(
          unknown_name(entry, "vertex or junction", name, names));
      return network.named_vertex(name);
    }
  } // namespace

  unsigned int
  select_vertex(const RodNetwork  &network,
                const std::string &text,
                const std::string &entry)
  {
    const std::string trimmed = dealii::Utilities::trim(text);
    if (!trimmed.empty() && trimmed[0] == '@')
      return vertex_called(network, trimmed.substr(1), entry);
    const auto [rod_index, where] =
      split_rod(network, text, entry, "\"@<name>\" of a named vertex");
    const Rod &rod = network.rods()[rod_index];
    const int  n   = rod.vertices.size();
    if (where == "start")
      return rod.vertices.front();
    if (where == "end")
      return rod.vertices.back();
    if (where == "mid")
      return rod.vertices[n / 2];
    try
      {
        std::size_t used = 0;
        const int   i    = std::stoi(where, &used);
        if (used == where.size() && i >= -n && i < n)
          return rod.vertices[i < 0 ? n + i : i];
      }
    catch (const std::exception &)
      {
      }
    throw std::invalid_argument(
      "entry \"" + entry + "\": \"" + text +
      "\" names no vertex; use [rod:]start, end, mid or an index in [" +
      std::to_string(-n) + ", " + std::to_string(n - 1) +
      "] (the rod is needed where there are several), or @<name> of a named "
      "vertex");
  }

  std::variant<RodEnd, unsigned int>
  select_rod_end(const RodNetwork  &network,
                 const std::string &text,
                 const std::string &entry)
  {
    const std::string trimmed = dealii::Utilities::trim(text);
    if (!trimmed.empty() && trimmed[0] == '@')
      {
        const unsigned int v = select_vertex(network, trimmed, entry);
        if (const auto junction = network.junction_at(v))
          return *junction;
        const auto &rods = network.rods();
        for (unsigned int r = 0; r < rods.size(); ++r)
          if (!rods[r].closed &&
              (v == rods[r].vertices.front() || v == rods[r].vertices.back()))
            return RodEnd{r, v == rods[r].vertices.front()};
        throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                    "\" is " + network.describe_vertex(v) +
                                    ", neither a rod end nor a junction");
      }
    const auto        colon = trimmed.find(':');
    const std::string end   = dealii::Utilities::trim(
      colon == std::string::npos ? trimmed : trimmed.substr(colon + 1));
    if (end != "start" && end != "end")
      throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                  "\" names no rod end; use [rod:]start, "
                                  "[rod:]end or @<name> of a rod end or "
                                  "junction");
    const unsigned int rod =
      split_rod(network,
                text,
                entry,
                "\"@<name>\" of a free network end or junction")
        .first;
    return RodEnd{rod, end == "start"};
  }

  RotationTarget
  select_rotation_target(const RodNetwork  &network,
                         const std::string &text,
                         const std::string &entry)
  {
    const std::string        name = dealii::Utilities::trim(text);
    std::vector<std::string> junction_names;
    for (unsigned int j = 0; j < network.junctions().size(); ++j)
      {
        if (network.junctions()[j].name == name)
          return {network.junctions()[j].vertex, j};
        junction_names.push_back(network.junctions()[j].name);
      }
    // Neither "@name", "rod:where" nor a place along the only rod.
    if (name.empty() ||
        (name[0] != '@' && name.find(':') == std::string::npos &&
         !is_place_along_a_rod(name)))
      {
        std::sort(junction_names.begin(), junction_names.end());
        throw std::invalid_argument(
          unknown_name(entry, "junction", name, junction_names));
      }
    const unsigned int v = select_vertex(network, text, entry);
    return {v, network.junction_at(v)};
  }
} // namespace rodnet
