#ifndef RODNET_GEOMETRY_ROD_GRAPH_H
#define RODNET_GEOMETRY_ROD_GRAPH_H

#include <core/rod_network.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * A network of straight beams between named nodes, as network files,
   * Gmsh meshes and the generators describe it. build_rod_network() turns
   * every beam into one rod and every node where rods meet (or that is
   * declared a support) into a junction.
   */
  struct RodGraph
  {
    struct Node
    {
      std::string name;
      Vector3     position;
      /// How the beam ends at this node are tied. Unset: welded where two
      /// or more beams meet, a free end where one beam ends.
      std::optional<JunctionKind> kind;
    };

    struct Beam
    {
      unsigned int from; ///< node index; the rod runs from -> to
      unsigned int to;
      /// The named groups the beam belongs to (a lattice's "x-beams" and
      /// "boundary", a network file's "group <name>", a Gmsh physical
      /// line): scenes give materials, frames and segments per group.
      std::vector<std::string> groups;
      /// Segments of a beam without interior vertices; 0: the
      /// segments_per_beam of build_rod_network().
      unsigned int segments = 0;
      /// Orientation of d1 (made orthogonal to the beam). Zero: the graph's
      /// default_director, or, where that is parallel to the beam, the
      /// coordinate axis least aligned with the beam.
      Vector3 director_hint = Vector3::Zero();
      /// Interior vertices in order from -> to, as a mesh gives them. Empty:
      /// the beam is split into segments_per_beam equal segments.
      std::vector<Vector3> interior;
    };

    std::vector<Node> nodes;
    std::vector<Beam> beams;
    Vector3           default_director = Vector3::UnitZ();

    /// Index of the node called @p name; throws naming it if unknown.
    unsigned int
    node_index(const std::string &name) const;
  };

  /**
   * Nodes closer than this fraction of the diagonal of the bounding box are
   * one point: build_rod_network() refuses two such nodes of a graph, the
   * Gmsh readers merge such mesh nodes (read_gmsh_line_mesh()). It is the
   * tolerance Gmsh's "Coherence Mesh" merges nodes within (its default
   * Geometry.Tolerance, 1e-8, times the diagonal of the model's bounding
   * box): far above the round-off of coordinates computed twice, far below
   * any element of a mesh one would solve.
   */
  constexpr double coincident_node_tolerance = 1e-8;

  /// What build_rod_network() made of a graph.
  struct BuiltNetwork
  {
    std::unique_ptr<RodNetwork> network;
    /// Junction index of each node, or -1 where the node is a free end.
    std::vector<int> node_junction;
    /// Triangulation vertex of each node (the junction's shared vertex).
    std::vector<unsigned int> node_vertex;
  };

  /**
   * Builds the rods (beam b -> rod b, through its interior vertices or
   * split into its own segments, or @p segments_per_beam, equal segments;
   * hinge kernel
   * @p hinge_kernel, natural shape @p natural_shape, which matters for
   * beams with interior vertices off the chord) and the junctions (named
   * as the nodes) of @p graph, and creates the triangulation. Throws
   * std::invalid_argument naming the node or beam for: a beam whose ends
   * are the same node or coincide (zero length), a node index out of
   * range, two nodes at the same position (closer than
   * coincident_node_tolerance times the graph's size), a node no beam
   * touches, a duplicate or empty node name, a
   * welded or pinned node with a single beam end, a beam director hint
   * parallel to the beam, @p segments_per_beam == 0.
   *
   * Junction ends are listed in beam order, the start of a beam before its
   * end; the junction's vertex is that of its first end. Free-end nodes
   * name their vertex, so that scenes can refer to them as "@name".
   */
  BuiltNetwork
  build_rod_network(
    const RodGraph    &graph,
    unsigned int       segments_per_beam,
    const std::string &hinge_kernel,
    NaturalShape       natural_shape = NaturalShape::initial_geometry);
} // namespace rodnet

#endif
