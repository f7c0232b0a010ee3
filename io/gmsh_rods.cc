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

    /// The line elements of one physical tag: each node's neighbours
    /// along the tag's segments, and the nodes that are the first vertex
    /// of a segment.
    struct TagSegments
    {
      std::map<long, std::vector<long>> neighbours;
      std::set<long>                    first_vertices;
    };

    /// The line elements of @p mesh per physical tag.
    std::map<int, TagSegments>
    segments_by_tag(const GmshLineMesh &mesh)
    {
      std::map<int, TagSegments> tags;
      for (const GmshLineElement &line : mesh.lines)
        {
          TagSegments &segments = tags[line.physical];
          segments.first_vertices.insert(line.nodes[0]);
          segments.neighbours[line.nodes[0]].push_back(line.nodes[1]);
          segments.neighbours[line.nodes[1]].push_back(line.nodes[0]);
        }
      return tags;
    }

    /// Where the open chain of @p segments starts; none for a closed one.
    /// Throws std::invalid_argument, naming @p where, for segments that
    /// branch or form separate chains.
    std::optional<long>
    open_chain_start(const TagSegments &segments, const std::string &where)
    {
      // An open chain runs along its line elements: it starts at the end
      // that is the first vertex of its segment (the lower node tag if the
      // elements disagree). A closed one starts anywhere.
      std::optional<long> start;
      unsigned int        n_ends = 0;
      for (const auto &[v, next] : segments.neighbours)
        {
          if (next.size() > 2)
            throw std::invalid_argument(
              where + ": " + std::to_string(next.size()) +
              " segments meet at a vertex; a rod must be a single chain: "
              "for a network of beams meeting at junctions use "
              "\"Generator = gmsh network\"");
          if (next.size() == 1)
            {
              const bool leads = segments.first_vertices.count(v) > 0;
              if (!start ||
                  (leads && segments.first_vertices.count(*start) == 0))
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
      return start;
    }

    /// The rod of the segments of physical tag @p tag of @p mesh, read
    /// from @p path; its nodes in @p nodes.
    RodChain
    tag_chain(const GmshLineMesh &mesh,
              const std::string  &path,
              const int           tag,
              const TagSegments  &segments,
              std::vector<long>  &nodes)
    {
      const std::string where =
        "mesh \"" + path + "\", physical tag " + std::to_string(tag);
      const std::optional<long> start = open_chain_start(segments, where);
      // A closed chain starts anywhere.
      nodes = walk(segments.neighbours,
                   start ? *start : segments.neighbours.begin()->first);
      RodChain chain;
      chain.tag    = tag;
      chain.closed = !start;
      if (nodes.size() != segments.neighbours.size())
        throw std::invalid_argument(where + ": the segments form more than "
                                            "one chain; use one tag per rod");
      for (const long node : nodes)
        chain.points.push_back(mesh.nodes.at(node));
      return chain;
    }

    /// Adds to @p notes, if any, the nodes of @p mesh (read from @p path)
    /// merged and the rods @p one_hinge of one hinge.
    void
    note_mesh_findings(const GmshLineMesh             &mesh,
                       const std::string              &path,
                       const std::vector<std::string> &one_hinge,
                       ReadNotes                      *notes)
    {
      if (notes == nullptr)
        return;
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
  } // namespace

  std::vector<RodChain>
  read_gmsh_rods(const std::string &path, ReadNotes *notes)
  {
    // rodnet's own parser, not deal.II's GridIn: GridIn loops forever on a
    // file whose section lacks its $End line (a truncated file), and
    // reports bad input as assertions with a stack trace.
    const GmshLineMesh mesh = read_gmsh_line_mesh(path);

    std::vector<RodChain>    rods;
    std::vector<std::string> one_hinge;
    for (const auto &[tag, segments] : segments_by_tag(mesh))
      {
        std::vector<long> nodes;
        const RodChain    chain = tag_chain(mesh, path, tag, segments, nodes);
        if (!chain.closed && nodes.size() == 3)
          one_hinge.push_back("rod " + std::to_string(rods.size()) +
                              " (physical tag " + std::to_string(tag) +
                              ", its hinge at node " +
                              std::to_string(nodes[1]) + ")");
        rods.push_back(chain);
      }
    note_mesh_findings(mesh, path, one_hinge, notes);
    return rods;
  }
} // namespace rodnet
