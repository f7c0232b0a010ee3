#ifndef RODNET_CORE_DR_MODEL_H
#define RODNET_CORE_DR_MODEL_H

#include <deal.II/lac/vector.h>

#include <core/dead_loads.h>
#include <core/rod_network.h>
#include <elements/dr_beam_kernel.h>
#include <materials/linear_elastic_rod.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace rodnet
{
  /// State, residual and mass vectors of a DrModel. Dynamic relaxation is
  /// explicit and matrix free: a plain serial vector is all it needs.
  using DrVector = dealii::Vector<double>;

  /// A named set of fixed DoFs of a DrModel whose reaction can be probed.
  struct DrSupport
  {
    std::string               name;
    std::vector<unsigned int> vertices;
    /// Fixed position components per vertex (same order as vertices).
    std::vector<std::array<bool, 3>> fixed;
    /// Whether the frames (n_x, n_y, n_r) of the vertices are fixed too.
    bool clamped = false;
  };

  /**
   * A rod network discretized by the bending-active beam element of Sakai,
   * Ohsaki & Adriaenssens (2020) (elements/dr_beam_kernel.h), for dynamic
   * relaxation: the counterpart of RodModel, built from the same inputs.
   *
   * Every network vertex is a node with a position X (3 DoFs) and a frame:
   * the x and y components of a unit normal and a rotation n_r about it
   * (3 DoFs). The rod ends at a junction share the position; welded,
   * clamped and welded-and-pinned junctions share one frame as well, while
   * at a pinned junction every rod end keeps its own frame (the ends turn
   * independently about the common point). A clamped junction fixes the
   * position and the frame, a welded-and-pinned one the position.
   *
   * The DoF vector u holds the change from the initial configuration: node
   * displacements and the changes of (n_x, n_y, n_r). u = 0 is the initial,
   * stress-free state: the element's rest angles are those of the initial
   * geometry. Rods must be straight at rest (between their junctions):
   * the element cannot bend a curved rod of NaturalShape::straight, and
   * gives wrong answers for a curved one stress free as built (see
   * doc/dynamic_relaxation.md), so curved rods are refused.
   *
   * Initial normals are the rods' directors d1 at the vertices (the rod's
   * director hint made orthogonal to the vertex tangent, the normalized sum
   * of the unit tangents of the rod's segments there), flipped where their
   * z component is negative: the element stores n_z = +sqrt(1 - n_x^2 -
   * n_y^2). A normal with n_z below 1e-3 (nearly in the xy plane) is refused,
   * since the parametrization is singular there.
   *
   * Reference elements: the in-plane rotation of a node is measured from
   * the direction to the far end of its reference element, the first
   * element (in the order of the rods, then along each rod) that the node's
   * frame belongs to, and the node's normal comes from that element's rod.
   * The frame of a clamped node is measured instead from a fixed anchor
   * point at the initial position of that far end (3 DoFs, always fixed):
   * with a moving far end, fixing n_r would not hold the rotation of the
   * chord about the normal.
   *
   * Usage: construct, add supports and loads, finalize(), then evaluate
   * (see DynamicRelaxation).
   */
  class DrModel
  {
  public:
    /**
     * Nodes, frames and elements of @p network (which must outlive the
     * model) with the rigidities @p stiffness_per_rod of each rod. Throws
     * std::invalid_argument for a stiffness count that does not match the
     * rods, a rigidity that is not positive and finite, a rod that is not
     * straight at rest, or an initial normal that the element cannot
     * represent (naming rod and vertex).
     */
    DrModel(const RodNetwork         &network,
            std::vector<RodStiffness> stiffness_per_rod);

    /// @name Supports (before finalize())
    /// @{
    /// Fixes the position and the frame of the first (or last) vertex of
    /// rod @p rod; the frame is measured from a fixed anchor (see above).
    void
    clamp_end(const std::string &name, unsigned int rod, bool at_start);

    /// Fixes the masked position components of @p vertex; their value
    /// moves with the load factor to @p displacement (at load factor 1).
    void
    fix_components(const std::string         &name,
                   unsigned int               vertex,
                   const std::array<bool, 3> &mask,
                   const Vector3             &displacement = Vector3::Zero());
    /// @}

    /// @name Dead loads at load factor 1 (before finalize())
    /// @{
    void
    add_point_force(unsigned int vertex, const Vector3 &force);

    /// Force per unit undeformed length on rod @p rod, lumped to the nodes
    /// with half of each adjacent element.
    void
    add_distributed_force(unsigned int rod, const Vector3 &force_per_length);

    /// Weight of rod @p rod: the distributed force @p mass_per_length
    /// (kg/m) times @p acceleration (m/s^2).
    void
    add_gravity(unsigned int   rod,
                double         mass_per_length,
                const Vector3 &acceleration);
    /// @}

    /// Builds the anchors, element stencils, rest data, fixed-DoF mask and
    /// the external force vector. Call once, after supports and loads.
    void
    finalize();

    unsigned int
    n_dofs() const
    {
      return initial.size();
    }

    /// Number of elements (one per rod segment).
    unsigned int
    n_elements() const
    {
      return elements.size();
    }

    /// A zero vector of n_dofs() entries.
    DrVector
    create_vector() const
    {
      return DrVector(n_dofs());
    }

    /**
     * Internal minus external forces at @p u and load factor
     * @p load_factor: the gradient of energy(). Not constrained: at fixed
     * DoFs it holds the reaction forces.
     */
    void
    residual(const DrVector &u, double load_factor, DrVector &r) const;

    /// Elastic energy minus the work of the dead loads, lambda f . u.
    double
    energy(const DrVector &u, double load_factor) const;

    /// Sets the fixed DoFs of @p u to their values at @p load_factor.
    void
    apply_boundary_values(DrVector &u, double load_factor) const;

    /**
     * Lumped fictitious masses for a unit pseudo-time step (Barnes):
     * m_i = (1/2) @p mass_scaling S_i, with S_i a bound of the Gershgorin
     * row sum sum_j |K_ij| of the stiffness at @p u. Central differences
     * with step dt are stable when dt^2 < 4 m_i / S_i for every DoF, so
     * these masses allow dt up to sqrt(2 mass_scaling).
     *
     * S_i sums over the elements |J|^T |C| |J| 1, the row sums of the
     * element's material stiffness J^T C J with the absolute values taken
     * entry by entry (J: derivatives of the six strains with respect to
     * the 18 local DoFs, C: second derivatives of the energy with respect
     * to the strains), plus the geometric stiffness 2 |N| / L of the axial
     * force N on the translations of both ends. For a straight element
     * with n = e_z this is EA/L0 + 24 EI/L0^3 + 12 EI/L0^2 (+ 2|N|/L) on a
     * translation and 12 EI/L0^2 + 6 EI/L0 (+ 2 GJ/L0) on a rotation, the
     * classic bound; the strain Jacobian brings the factor 1/n_z of n_x
     * and n_y for tilted normals and the far nodes of reference elements.
     * The three translations of a node get the largest of their row sums,
     * and so do n_x and n_y, so that the bound survives the rotation of the
     * elements during the relaxation.
     */
    void
    fictitious_masses(const DrVector &u,
                      double          mass_scaling,
                      DrVector       &masses) const;

    /// Current position of vertex @p vertex.
    Vector3
    position(const DrVector &u, unsigned int vertex) const;

    /// Current unit normal of the frame of vertex @p vertex (at a pinned
    /// junction, that of the vertex's own rod end).
    Vector3
    normal(const DrVector &u, unsigned int vertex) const;

    /// Reaction force of support @p s at @p u: the residual summed over
    /// its fixed position DoFs and, for a clamp, its anchor.
    Vector3
    reaction(const DrSupport &s, const DrVector &u, double load_factor) const;

    /// The same from a residual @p r that residual() computed.
    Vector3
    support_force(const DrSupport &s, const DrVector &r) const;

    const DrSupport &
    support(const std::string &name) const;

    const std::vector<DrSupport> &
    supports() const
    {
      return support_list;
    }

    /// Per DoF: held by a support (or an anchor).
    const std::vector<bool> &
    fixed_dof_mask() const
    {
      return fixed_mask;
    }

    /// External force vector at load factor 1.
    const DrVector &
    external_force() const
    {
      return f_ext;
    }

    /// Diagonal of the bounding box of the undeformed network (m).
    double
    length_scale() const
    {
      return length;
    }

    const RodNetwork &
    network() const
    {
      return *network_;
    }

    /// Global index of component @p c of the position of vertex @p vertex.
    unsigned int
    position_dof(unsigned int vertex, unsigned int c) const
    {
      return position_dofs[position_node[vertex]] + c;
    }

    /// Global index of frame component @p c (n_x, n_y, n_r) of the frame
    /// of vertex @p vertex.
    unsigned int
    frame_dof(unsigned int vertex, unsigned int c) const
    {
      return frame_dofs[frame_node[vertex]] + c;
    }

  private:
    /// One element: a rod segment with its stencil and rest data.
    struct Element
    {
      unsigned int                                rod;
      unsigned int                                segment;
      std::array<unsigned int, 2>                 vertices;
      std::array<unsigned int, n_dr_element_dofs> dofs;
      DrBeamReference                             reference;
    };

    /// Local DoFs of element @p e at @p u (initial values plus change).
    DrElementVector
    local_dofs(const Element &e, const DrVector &u) const;

    void
    check_not_finalized(const char *what) const;

    /// Fixes the position and frame of @p vertex for support @p name.
    void
    clamp_vertex(const std::string &name, unsigned int vertex);

    const RodNetwork         *network_;
    std::vector<RodStiffness> stiffness;
    /// Per vertex: its position node and its frame node.
    std::vector<unsigned int> position_node;
    std::vector<unsigned int> frame_node;
    /// First DoF of each position node (3 DoFs) and frame node (3 DoFs).
    std::vector<unsigned int> position_dofs;
    std::vector<unsigned int> frame_dofs;
    /// Per frame node: the vertex at the other end of its reference
    /// element.
    std::vector<unsigned int> far_vertex;
    /// Per frame node: fixed by a clamp (measured from an anchor).
    std::vector<bool> frame_clamped;
    /// Initial value of every DoF: positions, (n_x, n_y, 0), anchors.
    std::vector<double>    initial;
    std::vector<Element>   elements;
    std::vector<DrSupport> support_list;
    /// Per frame node: the first DoF of its anchor (clamped frames only).
    std::vector<unsigned int> anchor_dofs;
    /// Fixed DoF -> prescribed change at load factor 1.
    std::map<unsigned int, double> fixed_dofs;
    std::vector<bool>              fixed_mask;
    DeadLoads                      loads;
    DrVector                       f_ext;
    double                         length    = 0;
    bool                           finalized = false;
  };
} // namespace rodnet

#endif
