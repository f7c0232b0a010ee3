#include <geometry/rod_generators.h>
#include <geometry/rod_graph.h>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  unsigned int
  RodGraph::node_index(const std::string &name) const
  {
    for (unsigned int n = 0; n < nodes.size(); ++n)
      if (nodes[n].name == name)
        return n;
    throw std::invalid_argument("the network has no node \"" + name + "\"");
  }

  namespace
  {
    std::string
    quoted(const std::string &name)
    {
      return "\"" + name + "\"";
    }

    std::string
    describe(const RodGraph &graph, const unsigned int b)
    {
      const RodGraph::Beam &beam = graph.beams[b];
      return "beam " + std::to_string(b) + " from node " +
             quoted(graph.nodes[beam.from].name) + " to node " +
             quoted(graph.nodes[beam.to].name);
    }

    /// "1e-10 apart, within 1e-08 m" for the messages about coincidence.
    std::string
    describe_distance(const double distance, const double tolerance)
    {
      std::ostringstream s;
      s << std::setprecision(3) << distance << " apart, within " << tolerance
        << " m";
      return s.str();
    }

    bool
    parallel(const Vector3 &hint, const Vector3 &tangent)
    {
      const Vector3 t = tangent.normalized();
      return !((hint - hint.dot(t) * t).norm() > 1e-8 * hint.norm());
    }

    /// Each node has a name of its own and a finite position.
    void
    check_node_names(const RodGraph &graph)
    {
      std::set<std::string> names;
      for (unsigned int n = 0; n < graph.nodes.size(); ++n)
        {
          const RodGraph::Node &node = graph.nodes[n];
          if (node.name.empty())
            throw std::invalid_argument("node " + std::to_string(n) +
                                        " has no name");
          if (!names.insert(node.name).second)
            throw std::invalid_argument("the node name " + quoted(node.name) +
                                        " is used twice");
          if (!node.position.allFinite())
            throw std::invalid_argument("node " + quoted(node.name) +
                                        " has a non-finite position " +
                                        describe_point(node.position));
        }
    }

    /// Beam @p b joins two distinct nodes of the graph, more than
    /// @p tolerance apart, and its director hint is not along its chord.
    void
    check_beam(const RodGraph    &graph,
               const unsigned int b,
               const double       tolerance)
    {
      const RodGraph::Beam &beam = graph.beams[b];
      if (beam.from >= graph.nodes.size() || beam.to >= graph.nodes.size())
        throw std::invalid_argument(
          "beam " + std::to_string(b) + " joins nodes " +
          std::to_string(beam.from) + " and " + std::to_string(beam.to) +
          " but the network has " + std::to_string(graph.nodes.size()) +
          " nodes");
      if (beam.from == beam.to)
        throw std::invalid_argument(
          describe(graph, b) +
          " starts and ends at the same node; a closed beam loop needs "
          "a second node");
      const Vector3 chord =
        graph.nodes[beam.to].position - graph.nodes[beam.from].position;
      if (chord.norm() <= tolerance)
        throw std::invalid_argument(
          describe(graph, b) + " has zero length (its ends " +
          describe_distance(chord.norm(), tolerance) + ")");
      if (beam.director_hint != Vector3::Zero() &&
          parallel(beam.director_hint, chord))
        throw std::invalid_argument(
          describe(graph, b) + ": its director hint " +
          describe_point(beam.director_hint) + " is parallel to the beam");
    }

    /// No two nodes within @p tolerance of each other.
    void
    check_coincident_nodes(const RodGraph &graph, const double tolerance)
    {
      // Distinct nodes at one point would be rod ends that look joined but
      // are not. Sorting along x keeps the search near O(n log n).
      std::vector<unsigned int> order(graph.nodes.size());
      std::iota(order.begin(), order.end(), 0u);
      const auto x = [&](const unsigned int n) {
        return graph.nodes[n].position[0];
      };
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int a, unsigned int b) { return x(a) < x(b); });
      for (unsigned int i = 0; i < order.size(); ++i)
        for (unsigned int k = i + 1;
             k < order.size() && x(order[k]) - x(order[i]) <= tolerance;
             ++k)
          {
            const RodGraph::Node &a        = graph.nodes[order[i]];
            const RodGraph::Node &b        = graph.nodes[order[k]];
            const double          distance = (a.position - b.position).norm();
            if (distance <= tolerance)
              throw std::invalid_argument(
                "nodes " + quoted(a.name) + " and " + quoted(b.name) +
                " coincide at " + describe_point(a.position) + " (" +
                describe_distance(distance, tolerance) +
                "): a joint is one node; let the beams that meet there name "
                "the same node");
          }
    }

    /// Node names, indices and positions: everything that does not need
    /// the beams' ends to be counted.
    void
    check_nodes_and_beams(const RodGraph &graph, const double tolerance)
    {
      check_node_names(graph);
      for (unsigned int b = 0; b < graph.beams.size(); ++b)
        check_beam(graph, b, tolerance);
      check_coincident_nodes(graph, tolerance);
    }

    /// d1 of beam @p b as the header documents it.
    Vector3
    director_hint(const RodGraph &graph, const unsigned int b)
    {
      const RodGraph::Beam &beam = graph.beams[b];
      if (beam.director_hint != Vector3::Zero())
        return beam.director_hint;
      const Vector3 chord =
        graph.nodes[beam.to].position - graph.nodes[beam.from].position;
      if (!parallel(graph.default_director, chord))
        return graph.default_director;
      unsigned int axis = 0;
      chord.cwiseAbs().minCoeff(&axis);
      return Vector3::Unit(axis);
    }

    /// The settings of @p graph that are not its nodes and beams.
    void
    check_graph_settings(const RodGraph    &graph,
                         const unsigned int segments_per_beam)
    {
      if (segments_per_beam == 0)
        throw std::invalid_argument(
          "the number of segments per beam must be at least 1");
      if (graph.nodes.empty() || graph.beams.empty())
        throw std::invalid_argument("the network has no beam");
      if (!graph.default_director.allFinite() ||
          graph.default_director == Vector3::Zero())
        throw std::invalid_argument("the network's default director " +
                                    describe_point(graph.default_director) +
                                    " is zero or not finite");
    }

    /// The distance (m) within which nodes of @p graph are one point:
    /// coincident_node_tolerance relative to the size of the whole graph.
    double
    coincidence_tolerance(const RodGraph &graph)
    {
      Vector3 low = graph.nodes.front().position, high = low;
      for (const RodGraph::Node &node : graph.nodes)
        {
          low  = low.cwiseMin(node.position);
          high = high.cwiseMax(node.position);
        }
      return coincident_node_tolerance * std::max((high - low).norm(), 1e-300);
    }

    /// The vertices of the rod of beam @p b: its interior points between
    /// its nodes, or a straight split into its segments.
    std::vector<Vector3>
    beam_points(const RodGraph    &graph,
                const unsigned int b,
                const unsigned int segments_per_beam)
    {
      const RodGraph::Beam &beam = graph.beams[b];
      const Vector3        &from = graph.nodes[beam.from].position;
      const Vector3        &to   = graph.nodes[beam.to].position;
      std::vector<Vector3>  points;
      if (beam.interior.empty())
        {
          points = generators::straight(from,
                                        to,
                                        beam.segments > 0 ? beam.segments :
                                                            segments_per_beam);
          // Rod ends sit exactly on their node, whatever the round-off
          // of the split.
          points.back() = to;
        }
      else
        {
          points.push_back(from);
          points.insert(points.end(),
                        beam.interior.begin(),
                        beam.interior.end());
          points.push_back(to);
        }
      return points;
    }

    /// Adds a rod to @p network for each beam of @p graph, rod b for beam
    /// b; returns the rod ends at each node.
    std::vector<std::vector<RodEnd>>
    add_beam_rods(const RodGraph    &graph,
                  const unsigned int segments_per_beam,
                  const std::string &hinge_kernel,
                  const NaturalShape natural_shape,
                  RodNetwork        &network)
    {
      std::vector<std::vector<RodEnd>> node_ends(graph.nodes.size());
      for (unsigned int b = 0; b < graph.beams.size(); ++b)
        {
          network.add_rod(beam_points(graph, b, segments_per_beam),
                          false,
                          director_hint(graph, b),
                          hinge_kernel,
                          natural_shape);
          node_ends[graph.beams[b].from].push_back(RodEnd{b, true});
          node_ends[graph.beams[b].to].push_back(RodEnd{b, false});
        }
      return node_ends;
    }

    /// Joins the rod ends @p node_ends at each node of @p graph in
    /// built.network: a junction of the node's kind, or the name of a
    /// free end; fills built.node_junction and built.node_vertex.
    void
    join_beam_ends(const RodGraph                         &graph,
                   const std::vector<std::vector<RodEnd>> &node_ends,
                   BuiltNetwork                           &built)
    {
      RodNetwork &network = *built.network;
      built.node_junction.assign(graph.nodes.size(), -1);
      built.node_vertex.resize(graph.nodes.size());
      for (unsigned int n = 0; n < graph.nodes.size(); ++n)
        {
          const RodGraph::Node      &node  = graph.nodes[n];
          const std::vector<RodEnd> &ends  = node_ends[n];
          const std::string          where = "node " + quoted(node.name);
          if (ends.empty())
            throw std::invalid_argument(where + " is not the end of any beam");
          built.node_vertex[n] = network.end_vertex(ends.front());
          if (ends.size() == 1 && !node.kind)
            {
              // A free end: scenes may still refer to it by the node's name.
              network.name_vertex(node.name, built.node_vertex[n]);
              continue;
            }
          // A welded or pinned "junction" of a single beam would most
          // likely be a beam missing from the input, so it is refused here
          // although RodNetwork accepts a welded one as a rotation handle.
          if (ends.size() == 1 && (*node.kind == JunctionKind::welded ||
                                   *node.kind == JunctionKind::pinned))
            throw std::invalid_argument(
              where + " is " + to_string(*node.kind) +
              " but only one beam ends there; a single beam end can be "
              "clamped, welded and pinned, or free (no kind)");
          built.node_junction[n] =
            network.add_junction(node.name,
                                 node.kind.value_or(JunctionKind::welded),
                                 ends);
        }
    }
  } // namespace

  BuiltNetwork
  build_rod_network(const RodGraph    &graph,
                    const unsigned int segments_per_beam,
                    const std::string &hinge_kernel,
                    const NaturalShape natural_shape)
  {
    check_graph_settings(graph, segments_per_beam);
    check_nodes_and_beams(graph, coincidence_tolerance(graph));

    BuiltNetwork built;
    built.network = std::make_unique<RodNetwork>();
    join_beam_ends(graph,
                   add_beam_rods(graph,
                                 segments_per_beam,
                                 hinge_kernel,
                                 natural_shape,
                                 *built.network),
                   built);
    built.network->create_triangulation();
    return built;
  }
} // namespace rodnet
