#include <io/network_file.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    /// The tokens of one statement and where it stands, for messages.
    struct Statement
    {
      std::string              where; ///< "file:line"
      std::vector<std::string> tokens;

      [[noreturn]] void
      fail(const std::string &message) const
      {
        throw std::invalid_argument(where + ": " + message);
      }

      const std::string &
      token(const std::size_t i, const char *what) const
      {
        if (i >= tokens.size())
          fail("\"" + tokens[0] + "\" is missing " + what);
        return tokens[i];
      }

      double
      number(const std::size_t i, const char *what) const
      {
        const std::string &t = token(i, what);
        char              *end;
        errno          = 0;
        const double x = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0' || errno == ERANGE ||
            !std::isfinite(x))
          fail("\"" + t + "\" is not a number (" + what + ")");
        return x;
      }

      Vector3
      vector(const std::size_t i, const char *what) const
      {
        return Vector3(number(i, what),
                       number(i + 1, what),
                       number(i + 2, what));
      }
    };

    std::optional<JunctionKind>
    parse_kind(const Statement &s, const std::size_t i)
    {
      if (i >= s.tokens.size())
        return std::nullopt;
      // The file spells the kinds without blanks, which split tokens.
      std::string name = s.tokens[i];
      std::replace(name.begin(), name.end(), '-', ' ');
      try
        {
          return junction_kind_from_string(name);
        }
      catch (const std::invalid_argument &)
        {
          s.fail("unknown node kind \"" + s.tokens[i] +
                 "\"; known kinds: welded, pinned, clamped, "
                 "welded-and-pinned");
        }
    }

    /// A beam line waits for the end of the file: nodes may come later.
    struct PendingBeam
    {
      Statement   statement;
      std::string from, to;
    };

    /// Node name -> (index, line): beams look their nodes up here, and a
    /// duplicate points to the first declaration.
    using NodeLookup =
      std::map<std::string, std::pair<unsigned int, unsigned int>>;

    /// The statement of line @p number, @p line, of the file @p path:
    /// its tokens before any comment ('#').
    Statement
    parse_statement(const std::string &path,
                    const unsigned int number,
                    const std::string &line)
    {
      Statement s;
      s.where = path + ":" + std::to_string(number);
      std::istringstream words(line.substr(0, line.find('#')));
      for (std::string w; words >> w;)
        s.tokens.push_back(w);
      return s;
    }

    /// Adds the node of the "node" statement @p s, on line @p number, to
    /// @p graph and @p node_lookup.
    void
    add_network_node(const Statement   &s,
                     const unsigned int number,
                     RodGraph          &graph,
                     NodeLookup        &node_lookup)
    {
      RodGraph::Node node;
      node.name     = s.token(1, "a node name");
      node.position = s.vector(2, "a coordinate x y z");
      node.kind     = parse_kind(s, 5);
      if (s.tokens.size() > 6)
        s.fail("unexpected \"" + s.tokens[6] + "\" after the node");
      const auto [it, inserted] =
        node_lookup.emplace(node.name, std::pair(graph.nodes.size(), number));
      if (!inserted)
        s.fail("node \"" + node.name + "\" is declared twice (first on line " +
               std::to_string(it->second.second) + ")");
      graph.nodes.push_back(node);
    }

    /// The beam of @p pending, its nodes found in @p node_lookup.
    RodGraph::Beam
    resolve_beam(const PendingBeam &pending, const NodeLookup &node_lookup)
    {
      const Statement &s    = pending.statement;
      const auto       node = [&](const std::string &name) {
        const auto it = node_lookup.find(name);
        if (it == node_lookup.end())
          s.fail("unknown node \"" + name + "\"");
        return it->second.first;
      };
      RodGraph::Beam beam;
      beam.from   = node(pending.from);
      beam.to     = node(pending.to);
      bool has_d1 = false;
      for (std::size_t i = 3; i < s.tokens.size();)
        if (s.tokens[i] == "group")
          {
            beam.groups.push_back(s.token(i + 1, "the group's name"));
            i += 2;
          }
        else if (s.tokens[i] == "d1" && !has_d1)
          {
            beam.director_hint = s.vector(i + 1, "a director d1 x y z");
            has_d1             = true;
            i += 4;
          }
        else
          s.fail("unexpected \"" + s.tokens[i] +
                 "\"; a beam takes \"group <name>\" (one per group) and "
                 "\"d1 <x> <y> <z>\" (at most once)");
      return beam;
    }
  } // namespace

  RodGraph
  read_network_file(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw std::invalid_argument("cannot open the network file \"" + path +
                                  "\"");
    RodGraph                 graph;
    NodeLookup               node_lookup;
    std::vector<PendingBeam> beams;
    std::string              line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        const Statement s = parse_statement(path, number, line);
        if (s.tokens.empty())
          continue;
        if (s.tokens[0] == "node")
          add_network_node(s, number, graph, node_lookup);
        else if (s.tokens[0] == "beam")
          {
            PendingBeam beam{s,
                             s.token(1, "the name of its first node"),
                             s.token(2, "the name of its second node")};
            beams.push_back(beam);
          }
        else
          s.fail("unknown keyword \"" + s.tokens[0] +
                 "\"; a line is \"node ...\" or \"beam ...\"");
      }
    for (const PendingBeam &pending : beams)
      graph.beams.push_back(resolve_beam(pending, node_lookup));
    return graph;
  }
} // namespace rodnet
