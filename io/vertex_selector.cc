#include <deal.II/base/utilities.h>

#include <io/vertex_selector.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// Splits "rod:where" into the rod index and "where".
    std::pair<unsigned int, std::string>
    split_rod(const RodNetwork  &network,
              const std::string &text,
              const std::string &entry)
    {
      const std::string trimmed = dealii::Utilities::trim(text);
      const auto        colon   = trimmed.find(':');
      unsigned int      rod     = 0;
      std::string       where   = trimmed;
      if (colon != std::string::npos)
        {
          const std::string rod_text =
            dealii::Utilities::trim(trimmed.substr(0, colon));
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
              throw std::invalid_argument(
                "entry \"" + entry + "\": \"" + rod_text +
                "\" is not a rod index in \"" + text + "\"");
            }
          where = dealii::Utilities::trim(trimmed.substr(colon + 1));
        }
      if (rod >= network.rods().size())
        throw std::invalid_argument(
          "entry \"" + entry + "\": rod " + std::to_string(rod) +
          " does not exist (the scene has " +
          std::to_string(network.rods().size()) + " rods)");
      return {rod, where};
    }
  } // namespace

  unsigned int
  select_vertex(const RodNetwork  &network,
                const std::string &text,
                const std::string &entry)
  {
    const std::string trimmed = dealii::Utilities::trim(text);
    if (!trimmed.empty() && trimmed[0] == '@')
      try
        {
          return network.named_vertex(trimmed.substr(1));
        }
      catch (const std::invalid_argument &e)
        {
          throw std::invalid_argument("entry \"" + entry + "\": " + e.what());
        }
    const auto [rod_index, where] = split_rod(network, text, entry);
    const Rod &rod                = network.rods()[rod_index];
    const int  n                  = rod.vertices.size();
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
      "], or @<name> of a named vertex");
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
    const auto [rod, where] = split_rod(network, text, entry);
    if (where != "start" && where != "end")
      throw std::invalid_argument("entry \"" + entry + "\": \"" + text +
                                  "\" names no rod end; use [rod:]start, "
                                  "[rod:]end or @<name> of a rod end or "
                                  "junction");
    return RodEnd{rod, where == "start"};
  }

  RotationTarget
  select_rotation_target(const RodNetwork  &network,
                         const std::string &text,
                         const std::string &entry)
  {
    const std::string name = dealii::Utilities::trim(text);
    for (unsigned int j = 0; j < network.junctions().size(); ++j)
      if (network.junctions()[j].name == name)
        return {network.junctions()[j].vertex, j};
    const unsigned int v = select_vertex(network, text, entry);
    return {v, network.junction_at(v)};
  }
} // namespace rodnet
