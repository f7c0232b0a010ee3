#include <deal.II/grid/tria.h>

#include <core/rod_network.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  RodNetwork::RodNetwork() = default;

  namespace
  {
    /// Rod @p rod has enough vertices for a rod @p closed or not, each
    /// finite.
    void
    check_rod_vertices(const std::vector<Vector3> &rod_points,
                       const bool                  closed,
                       const unsigned int          rod)
    {
      const unsigned int n = rod_points.size();
      if (n < (closed ? 3u : 2u))
        throw std::invalid_argument(
          "rod " + std::to_string(rod) + " has " + std::to_string(n) +
          " vertices; an open rod needs at least 2, a closed one at least 3");
      for (const Vector3 &p : rod_points)
        if (!p.allFinite())
          throw std::invalid_argument("rod " + std::to_string(rod) +
                                      " has a non-finite vertex " +
                                      describe_point(p));
    }

    /// The distance within which two vertices of @p rod_points coincide:
    /// 1e-12 of the rod's size (its bounding sphere about its first).
    double
    rod_point_tolerance(const std::vector<Vector3> &rod_points)
    {
      double extent = 0;
      for (const Vector3 &p : rod_points)
        extent = std::max(extent, (p - rod_points[0]).norm());
      return 1e-12 * std::max(extent, 1e-300);
    }

    /// No segment of rod @p rod is @p tolerance long or shorter.
    void
    check_rod_segments(const std::vector<Vector3> &rod_points,
                       const bool                  closed,
                       const unsigned int          rod,
                       const double                tolerance)
    {
      const unsigned int n          = rod_points.size();
      const unsigned int n_segments = closed ? n : n - 1;
      for (unsigned int j = 0; j < n_segments; ++j)
        if ((rod_points[(j + 1) % n] - rod_points[j]).norm() <= tolerance)
          throw std::invalid_argument(
            "rod " + std::to_string(rod) + ": zero-length segment " +
            std::to_string(j) + " between vertices " + std::to_string(j) +
            " and " + std::to_string((j + 1) % n) + " at " +
            describe_point(rod_points[j]));
    }

    /// The axis (0, 1, 2) along which @p rod_points spread the most.
    unsigned int
    largest_spread_axis(const std::vector<Vector3> &rod_points)
    {
      Vector3 low = rod_points[0], high = rod_points[0];
      for (const Vector3 &p : rod_points)
        {
          low  = low.cwiseMin(p);
          high = high.cwiseMax(p);
        }
      const Vector3 spread(high - low);
      unsigned int  axis = 0;
      spread.maxCoeff(&axis);
      return axis;
    }

    /// No two vertices of rod @p rod within @p tolerance, but neighbours
    /// and the pairs that close a rod.
    void
    check_distinct_rod_vertices(const std::vector<Vector3> &rod_points,
                                const bool                  closed,
                                const unsigned int          rod,
                                const double                tolerance)
    {
      // Coincident but not consecutive vertices would make two segments
      // meet at a point that the mesh does not know as shared. Sorting
      // along the axis of largest spread keeps the search near O(n log n).
      const unsigned int n    = rod_points.size();
      const unsigned int axis = largest_spread_axis(rod_points);
      // An open rod whose last segment lies on its first one, (x_{n-2},
      // x_{n-1}) = (x_0, x_1), is closed through them (the clamped closure
      // of Korner et al. section 5(d)): those two pairs may coincide.
      const bool end_segments_overlap =
        !closed && n >= 5 &&
        (rod_points[0] - rod_points[n - 2]).norm() <= tolerance &&
        (rod_points[1] - rod_points[n - 1]).norm() <= tolerance;
      const auto overlap_pair = [&](const unsigned int i,
                                    const unsigned int k) {
        return end_segments_overlap &&
               ((i == 0 && k == n - 2) || (i == 1 && k == n - 1));
      };
      std::vector<unsigned int> order(n);
      std::iota(order.begin(), order.end(), 0u);
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int a, unsigned int b) {
                  return rod_points[a][axis] < rod_points[b][axis];
                });
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = a + 1;
             b < n && rod_points[order[b]][axis] - rod_points[order[a]][axis] <=
                        tolerance;
             ++b)
          {
            const unsigned int i = std::min(order[a], order[b]);
            const unsigned int k = std::max(order[a], order[b]);
            if (k > i + 1 && !(closed && i == 0 && k == n - 1) &&
                !overlap_pair(i, k) &&
                (rod_points[i] - rod_points[k]).norm() <= tolerance)
              throw std::invalid_argument(
                "rod " + std::to_string(rod) + ": vertices " +
                std::to_string(i) + " and " + std::to_string(k) +
                " coincide at " + describe_point(rod_points[i]));
          }
    }

    /// "start of rod 2".
    std::string
    describe_rod_end(const RodEnd &e)
    {
      return std::string(e.at_start ? "start" : "end") + " of rod " +
             std::to_string(e.rod);
    }

    /// End @p i of @p ends, of the junction @p where, is an end of a rod of
    /// @p network, listed once and in no other junction.
    void
    check_junction_end(const RodNetwork          &network,
                       const std::string         &where,
                       const std::vector<RodEnd> &ends,
                       const unsigned int         i)
    {
      const RodEnd &e = ends[i];
      if (e.rod >= network.rods().size())
        throw std::invalid_argument(where + ": there is no rod " +
                                    std::to_string(e.rod));
      if (network.rods()[e.rod].closed)
        throw std::invalid_argument(where + ": rod " + std::to_string(e.rod) +
                                    " is closed and has no ends");
      for (unsigned int k = 0; k < i; ++k)
        if (ends[k].rod == e.rod && ends[k].at_start == e.at_start)
          throw std::invalid_argument(where + " lists the " +
                                      describe_rod_end(e) + " twice");
      // A rod end's vertex belongs to a junction only as one of its ends.
      if (const auto j = network.junction_at(network.end_vertex(e)))
        throw std::invalid_argument(where + ": the " + describe_rod_end(e) +
                                    " is already in junction \"" +
                                    network.junctions()[*j].name + "\"");
    }

    /// The ends @p ends of the junction @p where meet: within round-off
    /// of @p size, the diagonal of @p network's bounding box.
    void
    check_junction_ends_meet(const RodNetwork          &network,
                             const std::string         &where,
                             const std::vector<RodEnd> &ends,
                             const double               size)
    {
      const double  tolerance = 1e-9 * std::max(size, 1e-300);
      const Vector3 position  = network.vertex(network.end_vertex(ends[0]));
      for (const RodEnd &e : ends)
        {
          const Vector3 end = network.vertex(network.end_vertex(e));
          const double  gap = (end - position).norm();
          if (gap > tolerance)
            throw std::invalid_argument(
              where + ": the rods do not meet; the " + describe_rod_end(e) +
              " at " + describe_point(end) + " is " + std::to_string(gap) +
              " m from the " + describe_rod_end(ends[0]) + " at " +
              describe_point(position));
        }
    }
  } // namespace

  std::string
  describe_point(const Vector3 &p)
  {
    std::ostringstream s;
    s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    return s.str();
  }

  void
  RodNetwork::set_frame_half_turns(const unsigned int rod,
                                   const unsigned int half_turns)
  {
    if (rod >= rod_list.size())
      throw std::invalid_argument("set_frame_half_turns: no rod " +
                                  std::to_string(rod) + " in a network of " +
                                  std::to_string(rod_list.size()) + " rods");
    if (half_turns != 0 && !rod_list[rod].closed)
      throw std::invalid_argument(
        "rod " + std::to_string(rod) +
        " is open: only a closed rod (a ring) has its material frame turned "
        "around it");
    rod_list[rod].frame_half_turns = half_turns;
  }


  void
  RodNetwork::set_closure_coupling(const unsigned int rod,
                                   const double       coupling)
  {
    if (rod >= rod_list.size())
      throw std::invalid_argument("set_closure_coupling: no rod " +
                                  std::to_string(rod) + " in a network of " +
                                  std::to_string(rod_list.size()) + " rods");
    if (!rod_list[rod].closed)
      throw std::invalid_argument("rod " + std::to_string(rod) +
                                  " is open: only a closed rod has a closure "
                                  "to couple eta' across");
    if (!(coupling >= 0 && coupling <= 1))
      throw std::invalid_argument(
        "rod " + std::to_string(rod) + ": the closure coupling " +
        std::to_string(coupling) + " is outside [0, 1]");
    rod_list[rod].closure_coupling = coupling;
  }


  void
  RodNetwork::set_inextensible(const unsigned int rod, const bool inextensible)
  {
    if (rod >= rod_list.size())
      throw std::invalid_argument("set_inextensible: no rod " +
                                  std::to_string(rod) + " in a network of " +
                                  std::to_string(rod_list.size()) + " rods");
    rod_list[rod].inextensible = inextensible;
  }


  void
  RodNetwork::set_developable(const unsigned int rod, const bool developable)
  {
    if (rod >= rod_list.size())
      throw std::invalid_argument("set_developable: no rod " +
                                  std::to_string(rod) + " in a network of " +
                                  std::to_string(rod_list.size()) + " rods");
    rod_list[rod].developable = developable;
    if (developable)
      rod_list[rod].inextensible = true;
  }


  void
  RodNetwork::add_rod(const std::vector<Vector3> &rod_points,
                      const bool                  closed,
                      const Vector3              &director_hint,
                      const std::string          &hinge_kernel,
                      const NaturalShape          natural_shape)
  {
    const unsigned int rod_index = rod_list.size();
    check_rod_vertices(rod_points, closed, rod_index);
    const double tolerance = rod_point_tolerance(rod_points);
    check_rod_segments(rod_points, closed, rod_index, tolerance);
    check_distinct_rod_vertices(rod_points, closed, rod_index, tolerance);

    Rod rod;
    rod.closed        = closed;
    rod.director_hint = director_hint;
    rod.hinge_kernel  = hinge_kernel;
    rod.natural_shape = natural_shape;
    if (points.empty())
      low = high = rod_points[0];
    for (const Vector3 &p : rod_points)
      {
        rod.vertices.push_back(points.size());
        points.push_back(p);
        low  = low.cwiseMin(p);
        high = high.cwiseMax(p);
      }
    rod_list.push_back(rod);
  }

  std::string
  to_string(const JunctionKind kind)
  {
    switch (kind)
      {
        case JunctionKind::welded:
          return "welded";
        case JunctionKind::pinned:
          return "pinned";
        case JunctionKind::clamped:
          return "clamped";
        case JunctionKind::welded_pinned:
          return "welded and pinned";
      }
    throw std::logic_error("unknown junction kind");
  }

  std::string
  to_string(const NaturalShape shape)
  {
    return shape == NaturalShape::initial_geometry ? "initial geometry" :
                                                     "straight";
  }

  NaturalShape
  natural_shape_from_string(const std::string &name)
  {
    for (const NaturalShape shape :
         {NaturalShape::initial_geometry, NaturalShape::straight})
      if (name == to_string(shape))
        return shape;
    throw std::invalid_argument("unknown natural shape \"" + name +
                                "\"; known: \"initial geometry\", "
                                "\"straight\"");
  }

  JunctionKind
  junction_kind_from_string(const std::string &name)
  {
    for (const JunctionKind kind : {JunctionKind::welded,
                                    JunctionKind::pinned,
                                    JunctionKind::clamped,
                                    JunctionKind::welded_pinned})
      if (name == to_string(kind))
        return kind;
    throw std::invalid_argument(
      "unknown junction kind \"" + name +
      "\"; known kinds: \"welded\", \"pinned\", \"clamped\", "
      "\"welded and pinned\"");
  }

  unsigned int
  RodNetwork::add_junction(const std::string         &name,
                           const JunctionKind         kind,
                           const std::vector<RodEnd> &ends)
  {
    const std::string where =
      "junction \"" + name + "\" (" + to_string(kind) + ")";
    if (junction_by_name.count(name) > 0)
      throw std::invalid_argument(where + ": the name is used twice");
    if (ends.empty())
      throw std::invalid_argument(where + " joins no rod end");
    // A welded junction on a single end is a rotation handle at a free
    // end (to apply a moment there); a pinned one would tie nothing.
    if (kind == JunctionKind::pinned && ends.size() < 2)
      throw std::invalid_argument(
        where + " joins a single rod end; a pinned junction joins at least "
                "two (to fix a single end's position use a pinned support)");

    for (unsigned int i = 0; i < ends.size(); ++i)
      check_junction_end(*this, where, ends, i);
    check_junction_ends_meet(*this, where, ends, (high - low).norm());

    name_vertex(name, end_vertex(ends[0]));
    Junction junction;
    junction.name   = name;
    junction.kind   = kind;
    junction.ends   = ends;
    junction.vertex = end_vertex(ends[0]);
    return record_junction(junction);
  }

  unsigned int
  RodNetwork::record_junction(const Junction &junction)
  {
    const unsigned int j = junction_list.size();
    junction_by_name.emplace(junction.name, j);
    junction_of_vertex.emplace(junction.vertex, j);
    for (const RodEnd &end : junction.ends)
      junction_of_vertex.emplace(end_vertex(end), j);
    junction_list.push_back(junction);
    return j;
  }

  void
  RodNetwork::name_vertex(const std::string &name, const unsigned int v)
  {
    if (v >= points.size())
      throw std::invalid_argument("cannot name vertex " + std::to_string(v) +
                                  " \"" + name + "\": it does not exist");
    const auto [it, inserted] = vertex_names.emplace(name, v);
    if (!inserted && it->second != v)
      throw std::invalid_argument("the vertex name \"" + name +
                                  "\" is used twice");
  }

  unsigned int
  RodNetwork::named_vertex(const std::string &name) const
  {
    const auto it = vertex_names.find(name);
    if (it == vertex_names.end())
      throw std::invalid_argument("there is no vertex or junction called \"" +
                                  name + "\"");
    return it->second;
  }

  std::vector<std::string>
  RodNetwork::vertex_name_list() const
  {
    std::vector<std::string> names;
    for (const auto &[name, v] : vertex_names)
      names.push_back(name);
    return names;
  }

  unsigned int
  RodNetwork::junction_index(const std::string &name) const
  {
    const auto it = junction_by_name.find(name);
    if (it == junction_by_name.end())
      throw std::invalid_argument("there is no junction \"" + name + "\"");
    return it->second;
  }

  namespace
  {
    /// The rod and position along it of vertex @p v (every vertex belongs
    /// to one rod; rods number their vertices consecutively).
    RodVertex
    locate(const std::vector<Rod> &rods, const unsigned int v)
    {
      // The first rod that starts after v, then the one before it.
      const auto after =
        std::upper_bound(rods.begin(),
                         rods.end(),
                         v,
                         [](const unsigned int w, const Rod &rod) {
                           return w < rod.vertices.front();
                         });
      if (after == rods.begin() || v > std::prev(after)->vertices.back())
        throw std::invalid_argument("vertex " + std::to_string(v) +
                                    " does not exist");
      const unsigned int r = std::distance(rods.begin(), after) - 1;
      return {r, v - rods[r].vertices.front()};
    }
  } // namespace

  std::string
  RodNetwork::describe_vertex(const unsigned int v) const
  {
    const RodVertex where = locate(rod_list, v);
    return "vertex " + std::to_string(where.index) + " of rod " +
           std::to_string(where.rod);
  }

  std::optional<unsigned int>
  RodNetwork::junction_at(const unsigned int v) const
  {
    const auto it = junction_of_vertex.find(v);
    if (it == junction_of_vertex.end())
      return std::nullopt;
    return it->second;
  }

  unsigned int
  RodNetwork::add_rotation_handle(const std::string &name, const unsigned int v)
  {
    const RodVertex where = locate(rod_list, v);
    if (const auto j = junction_at(v))
      throw std::invalid_argument(
        "rotation handle \"" + name + "\": " + describe_vertex(v) +
        " is already in junction \"" + junction_list[*j].name + "\"");
    const Rod &rod      = rod_list[where.rod];
    const bool at_start = where.index == 0;
    if (!rod.closed && (at_start || v == rod.vertices.back()))
      return add_junction(name, JunctionKind::welded, {{where.rod, at_start}});
    if (junction_by_name.count(name) > 0)
      throw std::invalid_argument("rotation handle \"" + name +
                                  "\": the name is used twice");
    name_vertex(name, v);
    Junction handle;
    handle.name     = name;
    handle.kind     = JunctionKind::welded;
    handle.interior = where;
    handle.vertex   = v;
    return record_junction(handle);
  }

  void
  RodNetwork::add_links(std::vector<dealii::CellData<1>> &cells) const
  {
    // Each open rod's end vertex is in one segment: with its link it is in
    // two cells, as deal.II allows in dimension 1. Closed rods stay pieces
    // of their own.
    const Rod *previous = nullptr;
    for (const Rod &rod : rod_list)
      if (!rod.closed)
        {
          if (previous != nullptr)
            {
              dealii::CellData<1> link;
              link.vertices = {previous->vertices.back(), rod.vertices.front()};
              link.material_id = link_material_id;
              cells.push_back(link);
            }
          previous = &rod;
        }
  }

  void
  RodNetwork::create_triangulation()
  {
    if (tria.n_cells() > 0)
      throw std::logic_error("RodNetwork::create_triangulation called twice");
    if (rod_list.empty())
      throw std::invalid_argument("the scene defines no rod");

    std::vector<dealii::Point<3>>    vertices(points.size());
    std::vector<dealii::CellData<1>> cells;
    for (unsigned int v = 0; v < points.size(); ++v)
      vertices[v] = dealii::Point<3>(points[v][0], points[v][1], points[v][2]);
    for (unsigned int r = 0; r < rod_list.size(); ++r)
      {
        Rod               &rod        = rod_list[r];
        const unsigned int n          = rod.vertices.size();
        const unsigned int n_segments = rod.closed ? n : n - 1;
        for (unsigned int j = 0; j < n_segments; ++j)
          {
            dealii::CellData<1> cell;
            cell.vertices = {rod.vertices[j], rod.vertices[(j + 1) % n]};
            // The rod is the cell's material: deal.II's loops over cells
            // (FEValues, DataOut) find each segment's rod and material there.
            cell.material_id = r;
            rod.segments.push_back(cells.size());
            cells.push_back(cell);
          }
      }
    segment_count = cells.size();
    add_links(cells);
    tria.create_triangulation(vertices, cells, dealii::SubCellData());

    // The kernels rely on cells running along their rod.
    for (const Rod &rod : rod_list)
      for (unsigned int j = 0; j < rod.segments.size(); ++j)
        {
          const dealii::TriaActiveIterator<dealii::CellAccessor<1, 3>>
            c(&tria, 0, rod.segments[j]);
          if (c->vertex_index(0) != rod.vertices[j] ||
              c->vertex_index(1) != rod.vertices[(j + 1) % rod.vertices.size()])
            throw std::logic_error(
              "internal error: the triangulation reordered the vertices of a "
              "segment");
        }
  }
} // namespace rodnet
