#ifndef RODNET_CORE_ROD_NETWORK_H
#define RODNET_CORE_ROD_NETWORK_H

#include <deal.II/grid/tria.h>

#include <elements/quaternion.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace rodnet
{
  /// "(x, y, z)": a point or direction as messages about the network name
  /// it.
  std::string
  describe_point(const Vector3 &p);

  /**
   * The stress-free shape of a rod's hinges (doc/theory.md, "Natural
   * shape"):
   * - initial_geometry: every hinge's natural strains are its strains in the
   *   undeformed configuration, so the rod is stress free where it was
   *   built (a helix stays a helix);
   * - straight: the natural strains are zero, so a curved rod starts
   *   prestressed, bent from a straight one.
   * A material's own natural curvature and twist act on top of either.
   */
  enum class NaturalShape
  {
    initial_geometry,
    straight
  };

  /// "initial geometry", "straight".
  std::string
  to_string(NaturalShape shape);

  /// Inverse of to_string(); throws std::invalid_argument listing the names.
  NaturalShape
  natural_shape_from_string(const std::string &name);

  /**
   * One rod of a network: an ordered chain of vertices of the triangulation,
   * its segments (cells) in the same order, and the direction that fixes the
   * orientation of its first director d1.
   */
  struct Rod
  {
    /// Vertex indices of the triangulation, in order along the rod. For a
    /// closed rod the first vertex is not repeated at the end.
    std::vector<unsigned int> vertices;
    /// Active cell indices of the segments: segment j joins vertices j, j+1.
    std::vector<unsigned int> segments;
    /// Whether the last vertex connects back to the first one.
    bool closed = false;
    /// d1 of the undeformed configuration is this vector made orthogonal
    /// to each segment's tangent.
    Vector3 director_hint = Vector3::UnitY();
    /// Name of the hinge kernel of the rod ("simple" or "classic").
    std::string hinge_kernel = "simple";
    /// Where the natural strains of the rod's hinges come from.
    NaturalShape natural_shape = NaturalShape::initial_geometry;
    /// Whether every segment keeps its length exactly (Korner et al.
    /// eq. 4.4): a Lagrange multiplier per segment instead of the stretching
    /// energy (families/inextensibility_family.h).
    bool inextensible = false;
    /// Whether the rod is an inextensible developable ribbon (its material
    /// has a RodMaterial::developable_ribbon()): a generatrix slope DoF and
    /// two constraint multipliers per hinge
    /// (families/developable_ribbon_family.h).
    bool developable = false;
    /// Of a closed rod: half turns of the undeformed material frame about
    /// the tangent once around the rod, spread evenly over its segments; an
    /// odd number closes it as a Möbius band (the closing hinge joins d1 to
    /// -d1 of the first segment).
    unsigned int frame_half_turns = 0;
    /// Of a closed developable ribbon: the weight of the central difference
    /// of eta' across the closure, at the two hinges beside it. 1 is the
    /// model; 0 takes one-sided differences there, as beside a clamp, and
    /// lets eta jump across the closure (the paper's clamped Möbius band).
    /// A homotopy from the one to the other (doc/ribbons.md).
    double closure_coupling = 1;
  };

  /**
   * How the rod ends meeting at a junction are tied (Lestringant & Kochmann
   * 2020, section 2.2):
   * - welded: shared position and one rigid rotation (a quaternion DoF) to
   *   which every end is tied through a junction element;
   * - pinned: shared position, each end rotates freely (no junction
   *   element, no quaternion);
   * - clamped: fixed position, rotation prescribed (identity unless the
   *   scene rotates it);
   * - welded_pinned: fixed position, one free rigid rotation (the lattice
   *   supports of L&K section 4.3).
   */
  enum class JunctionKind
  {
    welded,
    pinned,
    clamped,
    welded_pinned
  };

  /// "welded", "pinned", "clamped", "welded and pinned".
  std::string
  to_string(JunctionKind kind);

  /// Inverse of to_string(); throws std::invalid_argument listing the names.
  JunctionKind
  junction_kind_from_string(const std::string &name);

  /// One end of a rod: its first (at_start) or last vertex.
  struct RodEnd
  {
    unsigned int rod;
    bool         at_start;
  };

  /// A vertex of a rod by its position along the rod.
  struct RodVertex
  {
    unsigned int rod;
    unsigned int index; ///< into Rod::vertices
  };

  /**
   * Rod ends tied at one point, or a rotation handle inside a rod: a
   * junction whose rotation is welded to the two segments that meet at an
   * interior vertex (add_rotation_handle()), which then have no hinge
   * between them.
   */
  struct Junction
  {
    std::string  name;
    JunctionKind kind;
    /// Rod ends tied here; empty for a handle inside a rod.
    std::vector<RodEnd> ends;
    /// The interior vertex of a handle inside a rod.
    std::optional<RodVertex> interior;
    /// Triangulation vertex of the first end: the other ends' vertices
    /// share its position DoFs.
    unsigned int vertex;

    /// Whether the junction carries a rotation (quaternion DoFs).
    bool
    has_rotation() const
    {
      return kind != JunctionKind::pinned;
    }

    /// Whether the junction's position is held fixed.
    bool
    fixes_position() const
    {
      return kind == JunctionKind::clamped ||
             kind == JunctionKind::welded_pinned;
    }
  };

  /**
   * The undeformed geometry of a set of rods as a Triangulation<1,3>, with
   * each rod's vertex chain and the junctions that tie rod ends together. Every
   * cell belongs to exactly one rod; its vertex 0 -> vertex 1 direction follows
   * the rod.
   */
  class RodNetwork
  {
  public:
    RodNetwork();

    /**
     * Adds a rod through @p points (open, or closed when @p closed). Points
     * are checked: consecutive points closer than a relative tolerance are a
     * zero-length segment, other coincident points are reported too; the
     * error names the rod and the vertex indices. One exception: an open
     * rod whose last segment lies exactly on its first one closes through
     * them (clamp both, as Korner et al. close a Moebius band in section
     * 5(d)). @p natural_shape: see
     * NaturalShape (for a straight rod both choices agree).
     */
    void
    add_rod(const std::vector<Vector3> &points,
            bool                        closed,
            const Vector3              &director_hint,
            const std::string          &hinge_kernel,
            NaturalShape natural_shape = NaturalShape::initial_geometry);

    /**
     * Ties rod ends at a junction called @p name. Checks, naming the
     * junction: that rods exist and are open, that no end is in two
     * junctions, that the ends meet (within 1e-9 of the network's size),
     * that a pinned junction joins at least two ends. A welded junction of
     * a single end is a rotation handle at a free end, where a moment can
     * be applied (network inputs refuse it: there it is a missing beam).
     * Returns the junction's index.
     */
    unsigned int
    add_junction(const std::string         &name,
                 JunctionKind               kind,
                 const std::vector<RodEnd> &ends);

    const std::vector<Junction> &
    junctions() const
    {
      return junction_list;
    }

    /// Index of the junction called @p name; throws naming it if unknown.
    unsigned int
    junction_index(const std::string &name) const;

    /**
     * A welded junction called @p name at vertex @p v that only gives it a
     * rotation, where a moment or a prescribed rotation can act (Lestringant
     * & Kochmann appendix C) without a stub beam: at a free rod end a
     * junction of that end, at an interior vertex (or any vertex of a
     * closed rod) a junction welded to both segments that meet there, which
     * replaces the hinge between them. Throws naming the vertex where it is
     * already part of a junction. Returns the junction's index.
     */
    unsigned int
    add_rotation_handle(const std::string &name, unsigned int v);

    /// The junction that vertex @p v belongs to (as a rod end or as the
    /// vertex of a handle inside a rod), if any.
    std::optional<unsigned int>
    junction_at(unsigned int v) const;

    /// Where vertex @p v lies, for messages: "vertex 3 of rod 1".
    std::string
    describe_vertex(unsigned int v) const;

    /// Gives vertex @p v the name @p name (junctions name their vertex);
    /// scenes refer to it as "@name". Throws if the name is taken.
    void
    name_vertex(const std::string &name, unsigned int v);

    /// The vertex called @p name; throws naming it if unknown.
    unsigned int
    named_vertex(const std::string &name) const;

    /// The names of the named vertices (junctions, network nodes, rotation
    /// handles), sorted.
    std::vector<std::string>
    vertex_name_list() const;

    /// Triangulation vertex of a rod end.
    unsigned int
    end_vertex(const RodEnd &end) const
    {
      const Rod &rod = rod_list.at(end.rod);
      return end.at_start ? rod.vertices.front() : rod.vertices.back();
    }

    /**
     * Makes rod @p rod inextensible (Rod::inextensible) or extensible again;
     * before a model is built on the network, whose DoFs it changes.
     */
    void
    set_inextensible(unsigned int rod, bool inextensible = true);

    /**
     * Makes rod @p rod a developable ribbon (Rod::developable), which also
     * makes it inextensible; RodModel does it for the rods whose material
     * is one.
     */
    void
    set_developable(unsigned int rod, bool developable = true);

    /**
     * Gives closed rod @p rod @p half_turns half turns of its material
     * frame (Rod::frame_half_turns); before a model is built on the network.
     * Throws naming the rod if it is open.
     */
    void
    set_frame_half_turns(unsigned int rod, unsigned int half_turns);

    /**
     * Sets the coupling of eta' across the closure of closed rod @p rod
     * (Rod::closure_coupling), in [0, 1]; before a model is built on the
     * network. Throws naming the rod if it is open or @p coupling is
     * outside [0, 1].
     */
    void
    set_closure_coupling(unsigned int rod, double coupling);

    /**
     * Builds the triangulation from the rods added so far: one cell per
     * segment, whose material_id is the index of its rod, numbered rod by
     * rod (Rod::segments); then one link cell from the last vertex of each
     * open rod to the first vertex of the next, whose material_id is
     * link_material_id. Links tie the open rods into one connected mesh:
     * deal.II 9.4 orients the cells of a mesh of dimension 1 in space by a
     * sweep that starts again from the first cell for every connected
     * piece, which took 62 s for 24000 separate rods of 10 segments (and
     * 0.24 s linked). A link is no segment: it has no DoFs (DofLayout gives
     * it FE_Nothing), no energy and no output; loops over the cells of a
     * deal.II program take DofLayout::segment_cells() or test is_segment().
     * Call once.
     */
    void
    create_triangulation();

    /// The material_id of the link cells (create_triangulation()).
    static constexpr dealii::types::material_id link_material_id =
      dealii::numbers::invalid_material_id - 1;

    /// Number of segments: the first cells of the triangulation, before
    /// the links.
    unsigned int
    n_segments() const
    {
      return segment_count;
    }

    /// Whether @p cell is a segment (not a link of create_triangulation()).
    static bool
    is_segment(const dealii::CellAccessor<1, 3> &cell)
    {
      return cell.material_id() != link_material_id;
    }

    const dealii::Triangulation<1, 3> &
    triangulation() const
    {
      return tria;
    }

    const std::vector<Rod> &
    rods() const
    {
      return rod_list;
    }

    /// Whether the flag @p flag of Rod (&Rod::inextensible,
    /// &Rod::developable) is set on any rod.
    bool
    any_rod(const bool Rod::*flag) const
    {
      return std::any_of(rod_list.begin(),
                         rod_list.end(),
                         [flag](const Rod &rod) { return rod.*flag; });
    }

    /// Undeformed position of triangulation vertex @p v.
    Vector3
    vertex(unsigned int v) const
    {
      return points[v];
    }

    unsigned int
    n_vertices() const
    {
      return points.size();
    }

  private:
    dealii::Triangulation<1, 3>         tria;
    unsigned int                        segment_count = 0;
    std::vector<Vector3>                points;
    std::vector<Rod>                    rod_list;
    std::vector<Junction>               junction_list;
    std::map<std::string, unsigned int> vertex_names;
    /// The junctions by name, and by vertex (their own and their ends'):
    /// looked up once per junction, so that building a network of J
    /// junctions takes O(J log J), not O(J^2).
    std::map<std::string, unsigned int>            junction_by_name;
    std::unordered_map<unsigned int, unsigned int> junction_of_vertex;
    /// The bounding box of the vertices added so far, which the tolerance
    /// of a junction's meeting ends is a fraction of.
    Vector3 low  = Vector3::Zero();
    Vector3 high = Vector3::Zero();

    /// Appends to @p cells the links of create_triangulation().
    void
    add_links(std::vector<dealii::CellData<1>> &cells) const;

    /// Records junction @p junction under its name and vertices.
    unsigned int
    record_junction(const Junction &junction);
  };
} // namespace rodnet

#endif
