#ifndef RODNET_CORE_DR_MODEL_H
#define RODNET_CORE_DR_MODEL_H

#include <deal.II/base/array_view.h>

#include <deal.II/lac/vector.h>

#include <core/dead_loads.h>
#include <core/dr_process_share.h>
#include <core/model.h>
#include <core/rod_network.h>
#include <elements/dr_beam_kernel.h>
#include <materials/linear_elastic_rod.h>

#include <array>
#include <map>
#include <memory>
#include <mpi.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  /// State, residual and mass vectors of a DrModel. Dynamic relaxation is
  /// explicit and matrix free: a plain vector, the whole of it on every
  /// process (see DrModel, "Several processes").
  using DrVector = dealii::Vector<double>;

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
   * Several processes: every process of the model's communicator holds
   * the whole network and a whole copy of each vector, and evaluates its
   * share of the elements (DrProcessShare, process_share()). residual(),
   * energy(), elastic_energy() and fictitious_masses() are collective: a
   * residual and the masses come out right on the DoFs the process's
   * elements touch and on the fixed DoFs, and only those entries of a
   * state need to be: a solver updates the touched DoFs and counts its
   * sums on the DoFs it owns (DynamicRelaxation). The other entries of a
   * process's copy are stale until process_share().complete() fills them
   * in, which the outputs of a converged step need. The element work and
   * the update are split; the memory is not.
   *
   * Usage: construct, add supports and loads (Model::apply() or one by
   * one), finalize(), then evaluate (see DynamicRelaxation). The element
   * has no junction quaternions: prescribed rotations and moments are
   * refused, and so are probes of rotations, moments and eigenvalues.
   */
  class DrModel : public Model<DrVector>
  {
  public:
    /**
     * Nodes, frames and elements of @p network, which the model owns, with
     * the rigidities @p stiffness_per_rod of each rod. Throws
     * std::invalid_argument for a stiffness count that does not match the
     * rods, a rigidity that is not positive and finite, a rod that is not
     * straight at rest, or an initial normal that the element cannot
     * represent (naming rod and vertex). The processes of
     * @p communicator share the elements (see above).
     */
    DrModel(std::unique_ptr<RodNetwork> network,
            std::vector<RodStiffness>   stiffness_per_rod,
            MPI_Comm                    communicator = MPI_COMM_WORLD);

    /// @name Supports (before finalize())
    /// @{
    /// Fixes the position and the frame of the first (or last) vertex of
    /// rod @p rod; the frame is measured from a fixed anchor (see above).
    void
    clamp_end(const std::string &name,
              unsigned int       rod,
              bool               at_start) override;

    /// A junction is one node: it is held by clamping its first rod end.
    /// A pinned junction, where each end turns on its own, is refused.
    void
    clamp_junction(const std::string &name, unsigned int junction) override;

    /// Fixes the masked position components of @p vertex; their value
    /// moves with the load factor to @p displacement (at load factor 1).
    void
    fix_components(const std::string         &name,
                   unsigned int               vertex,
                   const std::array<bool, 3> &mask,
                   const Vector3 &displacement = Vector3::Zero()) override;

    /// Refuses any prescribed rotation or moment: they act on junction
    /// quaternions, which the element does not have.
    void
    add_rotational_loads(
      const std::vector<SupportsAndLoads::AxisLoad> &rotations,
      const std::vector<SupportsAndLoads::AxisLoad> &moments) override;
    /// @}

    /// @name Dead loads at load factor 1 (before finalize())
    /// @{
    void
    add_point_force(unsigned int vertex, const Vector3 &force) override;

    /// Refused: dynamic relaxation ramps all its loads with the load
    /// factor (its residual scale is the ramped load vector's).
    void
    add_held_point_force(unsigned int vertex, const Vector3 &force) override;

    /// Force per unit undeformed length on rod @p rod, lumped to the nodes
    /// with half of each adjacent element (DeadLoads::vertex_forces()).
    void
    add_distributed_force(unsigned int   rod,
                          const Vector3 &force_per_length) override;
    /// @}

    /// Builds the anchors, element stencils, rest data, fixed-DoF mask and
    /// the external force vector. Call once, after supports and loads.
    void
    finalize() override;

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
    create_vector() const override
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

    /// Elastic energy alone (no load potential) at @p u; the beams have no
    /// natural shape that a load factor ramps, so @p load_factor is unused.
    double
    elastic_energy(const DrVector &u, double load_factor) const override;

    /// Sets the fixed DoFs of @p u to their values at @p load_factor.
    void
    apply_boundary_values(DrVector &u, double load_factor) const override;

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
    position(const DrVector &u, unsigned int vertex) const override;

    /// Current unit normal of the frame of vertex @p vertex (at a pinned
    /// junction, that of the vertex's own rod end).
    Vector3
    normal(const DrVector &u, unsigned int vertex) const;

    /// Reaction force of support @p s at @p u: the residual summed over
    /// its fixed position DoFs and, for a clamp, its anchor.
    Vector3
    reaction(const Support  &s,
             const DrVector &u,
             double          load_factor) const override;

    /// The same from a residual @p r that residual() computed.
    Vector3
    support_force(const Support &s, const DrVector &r) const;

    /// @name Rotations: the element has none (has_rotation() is false);
    /// these throw std::logic_error.
    /// @{
    Vector3
    reaction_moment(const Support  &s,
                    const DrVector &u,
                    double          load_factor) const override;
    Vector3
    reaction_moment(unsigned int    junction,
                    const DrVector &u,
                    double          load_factor) const override;
    Quaternion
    junction_rotation(const DrVector &u, unsigned int junction) const override;
    /// @}

    bool
    has_junction_rotations() const override
    {
      return false;
    }

    bool
    has_rotation(unsigned int) const override
    {
      return false;
    }

    bool
    has_tangent() const override
    {
      return false;
    }

    /// The displacement and, per vertex, the unit "normal" of its frame.
    OutputFields
    output_fields(const DrVector &u) const override;

    const std::vector<Support> &
    supports() const override
    {
      return support_list;
    }

    /// This process's share of the elements and DoFs (after finalize()).
    const DrProcessShare &
    process_share() const
    {
      if (!share)
        throw std::logic_error("DrModel::process_share before finalize()");
      return *share;
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

    const RodNetwork &
    network() const override
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

    /// The elements this process evaluates: its share of the elements.
    dealii::ArrayView<const Element>
    own_elements() const;

    /// Local DoFs of element @p e at @p u (initial values plus change).
    DrElementVector
    local_dofs(const Element &e, const DrVector &u) const;

    /// Gives the three translations of every position node the largest of
    /// their @p row_sums, and n_x, n_y of every frame node theirs, so that
    /// the masses bound the stiffness in whatever direction the elements
    /// turn (fictitious_masses()).
    void
    equalize_node_row_sums(DrVector &row_sums) const;

    /// Throws unless every rigidity of every rod is positive and finite.
    void
    check_stiffness() const;

    /// Numbers the position and frame nodes along the rods (shared at
    /// junctions) with their initial positions.
    void
    number_nodes();

    /// One element per rod segment, with its vertices.
    void
    create_elements();

    /// The reference element and the initial normal of every frame.
    void
    initialize_frames();

    /// The initial normal of the frame at end @p end of element @p e:
    /// the rod's director d1 there, with n_z > 0.
    Vector3
    initial_normal(const Element &e, unsigned int end) const;

    /// Fixes the position and frame of @p vertex for support @p name.
    void
    clamp_vertex(const std::string &name, unsigned int vertex);

    /// The anchors of the clamped frames, fixed DoFs of their own.
    void
    add_anchors();

    /// The DoFs and rest data of every element (after add_anchors()).
    void
    build_element_stencils();

    std::unique_ptr<RodNetwork> network_;
    std::vector<RodStiffness>   stiffness;
    MPI_Comm                    communicator;
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
    std::vector<double>  initial;
    std::vector<Element> elements;
    std::vector<Support> support_list;
    /// Per frame node: the first DoF of its anchor (clamped frames only).
    std::vector<unsigned int> anchor_dofs;
    /// Fixed DoF -> prescribed change at load factor 1.
    std::map<unsigned int, double>  fixed_dofs;
    std::vector<bool>               fixed_mask;
    DeadLoads                       loads;
    DrVector                        f_ext;
    std::unique_ptr<DrProcessShare> share;
  };
} // namespace rodnet

#endif
