#include <io/gmsh_line_mesh.h>
#include <io/gmsh_rods.h>

#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The nodes along the chain of @p graph (each node's neighbours) from
    /// @p start, until it ends or returns to @p start.
    std::vector<long>
    walk(const std::map<long, std::vector<long>> &graph, const long start)
    {
      std::vector<long>   nodes;
      std::optional<long> previous;
      long                current = start;
      while (true)
        {
          nodes.push_back(current);
          std::optional<long> step;
          for (const long candidate : graph.at(current))
            if (candidate != previous)
              step = candidate;
          if (!step || *step == start)
            return nodes;
          previous = current;
          current  = *step;
        }
    }
  } // namespace

  std::vector<RodChain>
  read_gmsh_rods(const std::string &path, ReadNotes *notes)
  {
    // rodnet's own parser, not deal.II's GridIn: GridIn loops forever on a
    // file whose section lacks its $End line (a truncated file), and
    // reports bad input as assertions with a stack trace.
    const GmshLineMesh mesh = read_gmsh_line_mesh(path);

    // Per tag: each node's neighbours along the tag's segments.
    std::map<int, std::map<long, std::vector<long>>> neighbours;
    std::map<int, std::set<long>>                    first_vertices;
    for (const GmshLineElement &line : mesh.lines)
      {
        first_vertices[line.physical].insert(line.nodes[0]);
        auto &graph = neighbours[line.physical];
        graph[line.nodes[0]].push_back(line.nodes[1]);
        graph[line.nodes[1]].push_back(line.nodes[0]);
      }

    std::vector<RodChain>    rods;
    std::vector<std::string> one_hinge;
    for (const auto &[tag, graph] : neighbours)
      {
        const std::string where =
          "mesh \"" + path + "\", physical tag " + std::to_string(tag);
        // An open chain runs along its line elements: it starts at the end
        // that is the first vertex of its segment (the lower node tag if the
        // elements disagree). A closed one starts anywhere.
        std::optional<long> start;
        unsigned int        n_ends = 0;
        for (const auto &[v, next] : graph)
          {
            if (next.size() > 2)
              throw std::invalid_argument(
                where + ": " + std::to_string(next.size()) +
                " segments meet at a vertex; a rod must be a single chain: "
                "for a network of beams meeting at junctions use "
                "\"Generator = gmsh network\"");
            if (next.size() == 1)
              {
                const bool leads = first_vertices[tag].count(v) > 0;
                if (!start || (leads && first_vertices[tag].count(*start) == 0))
                  start = v;
                ++n_ends;
              }
          }
        if (n_ends != 0 && n_ends != 2)
          throw std::invalid_argument(where + ": the segments form " +
                                      std::to_string(n_ends / 2) +
                                      " separate chains; use one tag per "
                                      "rod, or for a network of beams "
                                      "meeting at junctions use "
                                      "\"Generator = gmsh network\"");
        if (n_ends == 0)
          start = graph.begin()->first;

        const std::vector<long> nodes = walk(graph, *start);
        RodChain                chain;
        chain.tag    = tag;
        chain.closed = n_ends == 0;
        if (nodes.size() != graph.size())
          throw std::invalid_argument(where + ": the segments form more than "
                                              "one chain; use one tag per rod");
        for (const long node : nodes)
          chain.points.push_back(mesh.nodes.at(node));
        if (!chain.closed && nodes.size() == 3)
          one_hinge.push_back("rod " + std::to_string(rods.size()) +
                              " (physical tag " + std::to_string(tag) +
                              ", its hinge at node " +
                              std::to_string(nodes[1]) + ")");
        rods.push_back(chain);
      }
    if (notes != nullptr)
      {
        if (const std::string merged = merged_nodes_note(mesh, path);
            !merged.empty())
          notes->info.push_back(merged);
        if (const std::string warning = one_hinge_warning(
              path,
              one_hinge,
              "refine the mesh (the gmsh generator takes the mesh's segments "
              "as they are)");
            !warning.empty())
          notes->warnings.push_back(warning);
      }
    return rods;
  }
} // namespace rodnet
