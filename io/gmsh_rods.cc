#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <io/gmsh_rods.h>
#include <io/scene.h>

#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

namespace rodnet
{
  std::vector<RodChain>
  read_gmsh_rods(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw std::invalid_argument("cannot open the mesh file \"" + path + "\"");
    dealii::Triangulation<1, 3> tria;
    dealii::GridIn<1, 3>        grid_in;
    grid_in.attach_triangulation(tria);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        // deal.II's reader refuses what a rod mesh cannot be, such as
        // several tags on one entity; its text without the stack trace.
        throw std::invalid_argument(
          "cannot read the Gmsh file \"" + path +
          "\" as rods: " + error_message(e) +
          "; if it is a network of beams meeting at junctions, use "
          "\"Generator = gmsh network\"");
      }

    // Per tag: each vertex's neighbours along the tag's segments.
    std::map<unsigned int, std::map<unsigned int, std::vector<unsigned int>>>
                                                   neighbours;
    std::map<unsigned int, std::set<unsigned int>> first_vertices;
    for (const auto &cell : tria.active_cell_iterators())
      {
        first_vertices[cell->material_id()].insert(cell->vertex_index(0));
        auto &graph = neighbours[cell->material_id()];
        graph[cell->vertex_index(0)].push_back(cell->vertex_index(1));
        graph[cell->vertex_index(1)].push_back(cell->vertex_index(0));
      }

    const std::vector<dealii::Point<3>> &vertices = tria.get_vertices();
    std::vector<RodChain>                rods;
    for (const auto &[tag, graph] : neighbours)
      {
        const std::string where =
          "mesh \"" + path + "\", physical tag " + std::to_string(tag);
        // An open chain runs along its line elements: it starts at the end
        // that is the first vertex of its segment (the lower index if the
        // elements disagree). A closed one starts anywhere.
        unsigned int start  = dealii::numbers::invalid_unsigned_int;
        unsigned int n_ends = 0;
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
                if (start == dealii::numbers::invalid_unsigned_int ||
                    (leads && first_vertices[tag].count(start) == 0))
                  start = v;
                ++n_ends;
              }
          }
        if (n_ends != 0 && n_ends != 2)
          throw std::invalid_argument(where + ": the segments form " +
                                      std::to_string(n_ends / 2) +
                                      " separate chains; use one tag per "
                                      "rod, or \"Generator = gmsh network\" "
                                      "for a network");
        if (n_ends == 0)
          start = graph.begin()->first;

        RodChain chain;
        chain.tag             = tag;
        chain.closed          = n_ends == 0;
        unsigned int previous = dealii::numbers::invalid_unsigned_int;
        unsigned int current  = start;
        while (true)
          {
            const dealii::Point<3> &p = vertices[current];
            chain.points.emplace_back(p[0], p[1], p[2]);
            const auto  &next = graph.at(current);
            unsigned int step = dealii::numbers::invalid_unsigned_int;
            for (const unsigned int candidate : next)
              if (candidate != previous)
                step = candidate;
            if (step == dealii::numbers::invalid_unsigned_int || step == start)
              break;
            previous = current;
            current  = step;
          }
        if (chain.points.size() != graph.size())
          throw std::invalid_argument(where + ": the segments form more than "
                                              "one chain; use one tag per rod");
        rods.push_back(chain);
      }
    return rods;
  }
} // namespace rodnet
