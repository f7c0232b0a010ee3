#include <io/gmsh_line_mesh.h>
#include <io/gmsh_network.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace rodnet
{
  namespace
  {
    using LineElement = GmshLineElement;
    using LineMesh    = GmshLineMesh;

    /// The lines of a .msh file as token lists, with their line numbers
    /// for error messages.
    class MshText
    {
    public:
      explicit MshText(const std::string &path)
          : path(path)
      {
        std::ifstream in(path);
        if (!in)
          throw std::invalid_argument("cannot open the mesh file \"" + path +
                                      "\"");
        for (std::string line; std::getline(in, line);)
          lines.push_back(line);
      }

      bool
      at_end() const
      {
        return current == lines.size();
      }

      /// The next line, untokenized.
      const std::string &
      next_line()
      {
        if (at_end())
          throw std::invalid_argument("mesh \"" + path +
                                      "\": the file ends inside a section");
        return lines[current++];
      }

      /// The tokens of the next line; at least @p n of them.
      std::vector<std::string>
      next(const std::size_t n = 1)
      {
        std::istringstream       words(next_line());
        std::vector<std::string> tokens;
        for (std::string w; words >> w;)
          tokens.push_back(w);
        if (tokens.size() < n)
          fail("expected at least " + std::to_string(n) + " fields, found " +
               std::to_string(tokens.size()));
        return tokens;
      }

      /// The line that next() or next_line() returned last.
      const std::string &
      last_line() const
      {
        return lines[current - 1];
      }

      [[noreturn]] void
      fail(const std::string &message) const
      {
        throw std::invalid_argument(path + ":" + std::to_string(current) +
                                    ": " + message);
      }

      long
      integer(const std::string &token) const
      {
        char *end;
        errno        = 0;
        const long i = std::strtol(token.c_str(), &end, 10);
        if (end == token.c_str() || *end != '\0' || errno == ERANGE)
          fail("\"" + token + "\" is not an integer");
        return i;
      }

      double
      real(const std::string &token) const
      {
        char *end;
        errno          = 0;
        const double x = std::strtod(token.c_str(), &end);
        if (end == token.c_str() || *end != '\0' || errno == ERANGE ||
            !std::isfinite(x))
          fail("\"" + token + "\" is not a number");
        return x;
      }

      /// Skips to the line "$End<section>".
      void
      skip_section(const std::string &section)
      {
        while (next_line().rfind("$End" + section, 0) != 0)
          ;
      }

      void
      expect_end(const std::string &section)
      {
        const auto t = next();
        if (t[0] != "$End" + section)
          fail("expected \"$End" + section + "\", found \"" + t[0] + "\"");
      }

      const std::string path;

    private:
      std::vector<std::string> lines;
      std::size_t              current = 0;
    };

    /// Version of the format: 2 (2.x) or 4 (4.1).
    int
    read_mesh_format(MshText &text)
    {
      const auto t = text.next(3);
      if (t[1] != "0")
        text.fail("binary .msh files are not supported; save as ASCII");
      if (t[0].rfind("2", 0) == 0)
        return 2;
      if (t[0] == "4.1")
        return 4;
      text.fail("format version " + t[0] + " is not supported (2.2 or 4.1)");
    }

    /// "dim tag "name"" lines; names may hold blanks.
    void
    read_physical_names(MshText &text, LineMesh &mesh)
    {
      const long n = text.integer(text.next()[0]);
      for (long i = 0; i < n; ++i)
        {
          const auto         t     = text.next(3);
          const std::string &line  = text.last_line();
          const auto         open  = line.find('"');
          const auto         close = line.rfind('"');
          if (open == std::string::npos || close == open)
            text.fail("a physical name must be in double quotes");
          mesh.physical_names[{text.integer(t[0]), text.integer(t[1])}] =
            line.substr(open + 1, close - open - 1);
        }
    }

    /// Physical tags of the point and curve entities (format 4.1): there,
    /// elements know their entity only.
    struct Entities
    {
      std::map<long, std::vector<int>> points, curves;
    };

    Entities
    read_entities(MshText &text)
    {
      Entities   entities;
      const auto counts = text.next(4);
      // Points: tag x y z n_physical physical...; curves: tag and a
      // bounding box of six numbers before their physical tags.
      for (const auto &[map, count, skip] :
           {std::tuple{&entities.points, counts[0], 4},
            std::tuple{&entities.curves, counts[1], 7}})
        for (long i = 0, n = text.integer(count); i < n; ++i)
          {
            const auto t          = text.next(skip + 1);
            const long n_physical = text.integer(t[skip]);
            if (n_physical < 0 || t.size() < std::size_t(skip + 1 + n_physical))
              text.fail("entity " + t[0] + " lists too few physical tags");
            auto &tags = (*map)[text.integer(t[0])];
            for (long k = 0; k < n_physical; ++k)
              tags.push_back(text.integer(t[skip + 1 + k]));
          }
      text.skip_section("Entities");
      return entities;
    }

    void
    add_node(MshText &text, LineMesh &mesh, const long tag, const Vector3 &x)
    {
      if (!mesh.nodes.emplace(tag, x).second)
        text.fail("node " + std::to_string(tag) + " is defined twice");
    }

    Vector3
    coordinates(const MshText &text, const std::vector<std::string> &t, int i)
    {
      return Vector3(text.real(t[i]), text.real(t[i + 1]), text.real(t[i + 2]));
    }

    void
    read_nodes(MshText &text, LineMesh &mesh, const int version)
    {
      if (version == 2)
        {
          for (long i = 0, n = text.integer(text.next()[0]); i < n; ++i)
            {
              const auto t = text.next(4);
              add_node(text, mesh, text.integer(t[0]), coordinates(text, t, 1));
            }
          return;
        }
      // 4.1: blocks of node tags, then their coordinates (followed by
      // parametric coordinates, one per entity dimension, if asked for).
      for (long b = 0, n = text.integer(text.next(4)[0]); b < n; ++b)
        {
          const auto        header = text.next(4);
          const long        count  = text.integer(header[3]);
          std::vector<long> tags;
          for (long i = 0; i < count; ++i)
            tags.push_back(text.integer(text.next()[0]));
          for (const long tag : tags)
            add_node(text, mesh, tag, coordinates(text, text.next(3), 0));
        }
    }

    [[noreturn]] void
    unsupported_element(const MshText &text, const long tag, const long type)
    {
      text.fail("element " + std::to_string(tag) + " has type " +
                std::to_string(type) +
                "; a network mesh holds lines (type 1) and points (type 15) "
                "only");
    }

    /// Adds element @p tag of @p type with the nodes @p t[first...].
    void
    add_element(const MshText                  &text,
                LineMesh                       &mesh,
                const long                      tag,
                const long                      type,
                const std::vector<int>         &physical,
                const std::vector<std::string> &t,
                const std::size_t               first)
    {
      const std::size_t n_nodes = type == 1 ? 2 : 1;
      if (t.size() != first + n_nodes)
        text.fail("element " + std::to_string(tag) + " of type " +
                  std::to_string(type) + " has " +
                  std::to_string(long(t.size()) - long(first)) +
                  " nodes, not " + std::to_string(n_nodes));
      if (type == 15)
        {
          for (const int p : physical)
            if (p != 0)
              mesh.node_points[text.integer(t[first])].insert(p);
          return;
        }
      if (physical.size() > 1)
        text.fail("line element " + std::to_string(tag) +
                  " belongs to several physical groups; a beam has one "
                  "material group");
      mesh.lines.push_back(
        LineElement{tag,
                    physical.empty() ? 0 : physical[0],
                    {text.integer(t[first]), text.integer(t[first + 1])}});
    }

    void
    read_elements(MshText        &text,
                  LineMesh       &mesh,
                  const int       version,
                  const Entities &entities)
    {
      if (version == 2)
        {
          // tag type n_tags physical elementary ... nodes
          for (long i = 0, n = text.integer(text.next()[0]); i < n; ++i)
            {
              const auto t      = text.next(3);
              const long tag    = text.integer(t[0]);
              const long type   = text.integer(t[1]);
              const long n_tags = text.integer(t[2]);
              if (type != 1 && type != 15)
                unsupported_element(text, tag, type);
              if (n_tags < 0 || t.size() < std::size_t(3 + n_tags))
                text.fail("element " + t[0] + " lists too few tags");
              std::vector<int> physical;
              if (n_tags > 0)
                physical.push_back(text.integer(t[3]));
              add_element(text, mesh, tag, type, physical, t, 3 + n_tags);
            }
          return;
        }
      for (long b = 0, n = text.integer(text.next(4)[0]); b < n; ++b)
        {
          const auto  header = text.next(4);
          const long  dim    = text.integer(header[0]);
          const long  entity = text.integer(header[1]);
          const long  type   = text.integer(header[2]);
          const long  count  = text.integer(header[3]);
          const auto &map    = dim == 0 ? entities.points : entities.curves;
          const auto  it     = map.find(entity);
          const std::vector<int> physical =
            (dim <= 1 && it != map.end()) ? it->second : std::vector<int>();
          for (long i = 0; i < count; ++i)
            {
              const auto t   = text.next(1);
              const long tag = text.integer(t[0]);
              if (type != 1 && type != 15)
                unsupported_element(text, tag, type);
              add_element(text, mesh, tag, type, physical, t, 1);
            }
        }
    }

    LineMesh
    read_line_mesh(const std::string &path)
    {
      MshText  text(path);
      LineMesh mesh;
      Entities entities;
      int      version = 0;
      while (!text.at_end())
        {
          const std::string &line = text.next_line();
          if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
          if (line[0] != '$')
            text.fail("expected a section such as $Nodes, found \"" + line +
                      "\"");
          const std::string section =
            line.substr(1, line.find_last_not_of(" \t\r"));
          if (section == "MeshFormat")
            version = read_mesh_format(text);
          else if (version == 0)
            text.fail("the file does not begin with $MeshFormat");
          else if (section == "PhysicalNames")
            read_physical_names(text, mesh);
          else if (section == "Entities" && version == 4)
            {
              entities = read_entities(text);
              continue;
            }
          else if (section == "Nodes")
            read_nodes(text, mesh, version);
          else if (section == "Elements")
            read_elements(text, mesh, version, entities);
          else
            {
              text.skip_section(section);
              continue;
            }
          text.expect_end(section);
        }
      return mesh;
    }

    std::optional<JunctionKind>
    kind_named(const std::string &name)
    {
      for (const JunctionKind kind : {JunctionKind::welded,
                                      JunctionKind::pinned,
                                      JunctionKind::clamped,
                                      JunctionKind::welded_pinned})
        if (to_string(kind) == name)
          return kind;
      return std::nullopt;
    }

    /// Turns the mesh's chains of line elements into beams.
    class ChainBuilder
    {
    public:
      ChainBuilder(const LineMesh &mesh, const std::string &path)
          : mesh(mesh)
          , where("mesh \"" + path + "\"")
      {
        for (unsigned int e = 0; e < mesh.lines.size(); ++e)
          {
            incident[mesh.lines[e].nodes[0]].push_back(e);
            incident[mesh.lines[e].nodes[1]].push_back(e);
          }
      }

      RodGraph
      build()
      {
        RodGraph graph;
        add_nodes(graph);
        std::vector<Chain> chains;
        visited.assign(mesh.lines.size(), false);
        for (const auto &[node, elements] : incident)
          if (is_branch(node))
            for (const unsigned int e : elements)
              if (!visited[e])
                chains.push_back(walk(node, e));
        for (unsigned int e = 0; e < mesh.lines.size(); ++e)
          if (!visited[e])
            fail("element " + std::to_string(mesh.lines[e].tag) +
                 " lies on a closed chain of line elements without a branch "
                 "node: closed beam loops are not supported in networks");
        std::sort(chains.begin(),
                  chains.end(),
                  [](const auto &a, const auto &b) {
                    return a.first_tag < b.first_tag;
                  });

        for (const Chain &chain : chains)
          {
            RodGraph::Beam beam;
            beam.from = node_index.at(chain.nodes.front());
            beam.to   = node_index.at(chain.nodes.back());
            if (chain.physical != 0)
              beam.groups = physical_line_groups(chain.physical);
            for (std::size_t k = 1; k + 1 < chain.nodes.size(); ++k)
              beam.interior.push_back(mesh.nodes.at(chain.nodes[k]));
            if (chain.nodes.size() == 3)
              one_hinge.push_back(describe_one_hinge(graph, chain));
            graph.beams.push_back(beam);
          }
        return graph;
      }

      /// The beams that build() made of two line elements, described for
      /// one_hinge_warning().
      const std::vector<std::string> &
      one_hinge_chains() const
      {
        return one_hinge;
      }

    private:
      /// Mesh nodes along a beam, its ends included.
      struct Chain
      {
        std::vector<long> nodes;
        long              first_tag;
        int               physical;
      };

      [[noreturn]] void
      fail(const std::string &message) const
      {
        throw std::invalid_argument(where + ": " + message);
      }

      /// The groups of a beam of the physical line @p tag: its tag ("3"),
      /// and its name where the mesh gives one.
      std::vector<std::string>
      physical_line_groups(const int tag) const
      {
        std::vector<std::string> groups{std::to_string(tag)};
        const auto               name = mesh.physical_names.find({1, tag});
        if (name != mesh.physical_names.end() && !name->second.empty() &&
            name->second != groups.front())
          groups.push_back(name->second);
        return groups;
      }

      /// "beam 3 (node1 to node5, its hinge at node 4)": @p chain, of two
      /// elements, which becomes the next beam of @p graph.
      std::string
      describe_one_hinge(const RodGraph &graph, const Chain &chain) const
      {
        return "beam " + std::to_string(graph.beams.size()) + " (" +
               graph.nodes[node_index.at(chain.nodes.front())].name + " to " +
               graph.nodes[node_index.at(chain.nodes.back())].name +
               ", its hinge at node " + std::to_string(chain.nodes[1]) + ")";
      }

      bool
      is_branch(const long node) const
      {
        const std::vector<unsigned int> &elements = incident.at(node);
        return elements.size() != 2 ||
               mesh.lines[elements[0]].physical !=
                 mesh.lines[elements[1]].physical ||
               mesh.node_points.count(node) > 0;
      }

      /// The branch nodes, named and with their kinds from the physical
      /// points.
      void
      add_nodes(RodGraph &graph)
      {
        std::map<int, long> named_by;
        for (const auto &[node, physical] : mesh.node_points)
          if (incident.count(node) == 0)
            fail("node " + std::to_string(node) +
                 " carries a physical point but no line element touches it");
        for (const auto &[node, elements] : incident)
          {
            if (!is_branch(node))
              continue;
            RodGraph::Node n;
            n.position       = mesh.nodes.at(node);
            const auto point = mesh.node_points.find(node);
            for (const int p : point == mesh.node_points.end() ?
                                 std::set<int>() :
                                 point->second)
              {
                const auto        it = mesh.physical_names.find({0, p});
                const std::string name =
                  it == mesh.physical_names.end() ? "" : it->second;
                const auto kind = kind_named(name);
                if (kind && n.kind && *kind != *n.kind)
                  fail("node " + std::to_string(node) + " is both " +
                       to_string(*n.kind) + " and " + to_string(*kind));
                if (kind)
                  n.kind = kind;
                else if (!name.empty())
                  {
                    if (!n.name.empty())
                      fail("node " + std::to_string(node) +
                           " has two names, \"" + n.name + "\" and \"" + name +
                           "\"");
                    const auto [first, unique] = named_by.emplace(p, node);
                    if (!unique)
                      fail("the physical point \"" + name + "\" holds nodes " +
                           std::to_string(first->second) + " and " +
                           std::to_string(node) +
                           "; a name must belong to one node (kinds may hold "
                           "several)");
                    n.name = name;
                  }
              }
            if (n.name.empty())
              n.name = "node" + std::to_string(node);
            node_index[node] = graph.nodes.size();
            graph.nodes.push_back(n);
          }
      }

      /// The chain that leaves branch node @p start through element @p e.
      Chain
      walk(const long start, unsigned int e)
      {
        Chain chain{{start}, mesh.lines[e].tag, mesh.lines[e].physical};
        std::vector<unsigned int> elements;
        for (long current = start;;)
          {
            visited[e] = true;
            elements.push_back(e);
            const LineElement &line = mesh.lines[e];
            const long         next =
              line.nodes[0] == current ? line.nodes[1] : line.nodes[0];
            chain.nodes.push_back(next);
            if (is_branch(next))
              break;
            const std::vector<unsigned int> &two = incident.at(next);
            e       = two[0] == e ? two[1] : two[0];
            current = next;
          }
        if (chain.nodes.back() == start)
          fail("the line elements from element " +
               std::to_string(mesh.lines[elements[0]].tag) +
               " return to node " + std::to_string(start) +
               ": closed beam loops are not supported in networks (a "
               "physical point on the loop splits it into two beams)");

        // Orient the chain as its element of lowest tag.
        const auto lowest =
          std::min_element(elements.begin(),
                           elements.end(),
                           [&](unsigned int a, unsigned int b) {
                             return mesh.lines[a].tag < mesh.lines[b].tag;
                           });
        const std::size_t k = lowest - elements.begin();
        chain.first_tag     = mesh.lines[*lowest].tag;
        if (mesh.lines[*lowest].nodes[0] != chain.nodes[k])
          std::reverse(chain.nodes.begin(), chain.nodes.end());
        return chain;
      }

      const LineMesh                           &mesh;
      const std::string                         where;
      std::map<long, std::vector<unsigned int>> incident;
      std::map<long, unsigned int>              node_index;
      std::vector<bool>                         visited;
      std::vector<std::string>                  one_hinge;
    };
  } // namespace

  GmshLineMesh
  read_gmsh_line_mesh(const std::string &path)
  {
    LineMesh mesh = read_line_mesh(path);
    for (const LineElement &line : mesh.lines)
      {
        const auto fail = [&](const std::string &message) {
          throw std::invalid_argument("mesh \"" + path + "\": element " +
                                      std::to_string(line.tag) + message);
        };
        for (const long node : line.nodes)
          if (mesh.nodes.count(node) == 0)
            fail(" refers to node " + std::to_string(node) +
                 ", which $Nodes does not define");
        if (line.nodes[0] == line.nodes[1])
          fail(" joins node " + std::to_string(line.nodes[0]) + " to itself");
      }
    if (mesh.lines.empty())
      throw std::invalid_argument("mesh \"" + path +
                                  "\": the mesh has no line elements");
    merge_coincident_nodes(mesh, path);
    return mesh;
  }

  RodGraph
  read_gmsh_network(const std::string &path, ReadNotes *notes)
  {
    const LineMesh mesh = read_gmsh_line_mesh(path);
    ChainBuilder   builder(mesh, path);
    RodGraph       graph = builder.build();
    if (notes == nullptr)
      return graph;
    if (const std::string merged = merged_nodes_note(mesh, path);
        !merged.empty())
      notes->info.push_back(merged);
    if (const std::string warning = one_hinge_warning(
          path,
          builder.one_hinge_chains(),
          "refine the mesh, or mark the hinge's node with a physical point: "
          "it becomes a welded junction, and Geometry/Segments splits the two "
          "beams of one element each");
        !warning.empty())
      notes->warnings.push_back(warning);
    return graph;
  }
} // namespace rodnet
