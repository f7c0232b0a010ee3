#include <core/require_positive.h>
#include <geometry/network_generators.h>

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace rodnet
{
  namespace network_generators
  {
    namespace
    {
      void
      require_cells(const unsigned int nx, const unsigned int ny)
      {
        if (nx == 0 || ny == 0)
          throw std::invalid_argument(
            "a lattice needs at least one cell in each direction, got " +
            std::to_string(nx) + " by " + std::to_string(ny));
      }

      unsigned int
      add_node(RodGraph                          &graph,
               const std::string                 &name,
               const Vector3                     &position,
               const std::optional<JunctionKind> &kind = std::nullopt)
      {
        graph.nodes.push_back(RodGraph::Node{name, position, kind});
        return graph.nodes.size() - 1;
      }

      void
      add_beam(RodGraph                       &graph,
               const unsigned int              from,
               const unsigned int              to,
               const std::vector<std::string> &groups        = {},
               const Vector3                  &director_hint = Vector3::Zero())
      {
        RodGraph::Beam beam;
        beam.from          = from;
        beam.to            = to;
        beam.groups        = groups;
        beam.director_hint = director_hint;
        graph.beams.push_back(beam);
      }
    } // namespace

    RodGraph
    right_angle_frame(const double L)
    {
      require_positive(L, "frame beam length");
      RodGraph           graph;
      const unsigned int clamp =
        add_node(graph, "clamp", Vector3::Zero(), JunctionKind::clamped);
      const unsigned int corner = add_node(graph, "corner", Vector3(L, 0, 0));
      const unsigned int tip    = add_node(graph, "tip", Vector3(L, L, 0));
      add_beam(graph, clamp, corner);
      add_beam(graph, corner, tip);
      return graph;
    }

    RodGraph
    windmill(const double shaft_length)
    {
      require_positive(shaft_length, "windmill shaft length");
      const double       blade_length = shaft_length / 2;
      RodGraph           graph;
      const unsigned int hub = add_node(graph, "hub", Vector3::Zero());
      const unsigned int top = add_node(graph,
                                        "top",
                                        Vector3(0, 0, shaft_length),
                                        JunctionKind::clamped);
      // The default d1 = e_z is parallel to the shaft.
      add_beam(graph, hub, top, {"shaft"}, Vector3::UnitX());
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double       angle = (90. + 120. * k) * M_PI / 180;
          const unsigned int tip =
            add_node(graph,
                     "blade" + std::to_string(k + 1),
                     blade_length *
                       Vector3(std::cos(angle), std::sin(angle), 0));
          add_beam(graph, hub, tip, {"blades"});
        }
      return graph;
    }

    RodGraph
    square_lattice(const unsigned int nx, const unsigned int ny, const double a)
    {
      require_cells(nx, ny);
      require_positive(a, "square lattice spacing");
      RodGraph   graph;
      const auto node = [nx](const unsigned int i, const unsigned int j) {
        return j * (nx + 1) + i;
      };
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          add_node(graph,
                   "n_" + std::to_string(i) + "_" + std::to_string(j),
                   Vector3(i * a, j * a, 0));
      const auto place = [](const bool on_boundary) {
        return on_boundary ? "boundary" : "interior";
      };
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          add_beam(graph,
                   node(i, j),
                   node(i + 1, j),
                   {"x-beams", place(j == 0 || j == ny)});
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          add_beam(graph,
                   node(i, j),
                   node(i, j + 1),
                   {"y-beams", place(i == 0 || i == nx)});
      return graph;
    }

    RodGraph
    hexagonal_lattice(const unsigned int nx,
                      const unsigned int ny,
                      const double       a)
    {
      require_cells(nx, ny);
      require_positive(a, "hexagonal lattice side");
      // Corners on the integer grid (X, Y) make shared corners compare
      // exactly. Offsets of the corners from a cell centre, counterclockwise
      // from 30 degrees, in units (sqrt(3) a / 2, a / 2).
      const int corner_offsets[6][2] =
        {{1, 1}, {0, 2}, {-1, 1}, {-1, -1}, {0, -2}, {1, -1}};
      using GridPoint = std::pair<int, int>; // (Y, X): sorts rows first
      std::set<GridPoint> corners;
      // Each side with the number of cells it borders: one on the boundary.
      std::map<std::pair<GridPoint, GridPoint>, unsigned int> sides;
      for (unsigned int r = 0; r < ny; ++r)
        for (unsigned int c = 0; c < nx; ++c)
          {
            const int X = 2 * c + r % 2 + 1;
            const int Y = 3 * r + 2;
            for (unsigned int k = 0; k < 6; ++k)
              {
                const auto     &p = corner_offsets[k];
                const auto     &q = corner_offsets[(k + 1) % 6];
                const GridPoint start{Y + p[1], X + p[0]};
                const GridPoint end{Y + q[1], X + q[0]};
                corners.insert(start);
                ++sides[std::minmax(start, end)];
              }
          }

      RodGraph                          graph;
      std::map<GridPoint, unsigned int> index;
      for (const auto &[Y, X] : corners)
        {
          index[{Y, X}] =
            add_node(graph,
                     "n_" + std::to_string(X) + "_" + std::to_string(Y),
                     Vector3(X * std::sqrt(3.) * a / 2, Y * a / 2, 0));
        }
      // The (Y, X) order of the grid points is the node order, so sides
      // sorted by grid points are sorted by node indices too.
      for (const auto &[side, cells] : sides)
        add_beam(graph,
                 index.at(side.first),
                 index.at(side.second),
                 {cells == 1 ? "boundary" : "interior"});
      return graph;
    }
  } // namespace network_generators
} // namespace rodnet
