#ifndef RODNET_CORE_DOF_LAYOUT_H
#define RODNET_CORE_DOF_LAYOUT_H

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>

#include <core/dof_block.h>
#include <core/rod_network.h>
#include <elements/hinge_kernel.h>
#include <elements/stretch_kernel.h>

#include <array>
#include <unordered_map>
#include <vector>

namespace rodnet
{
  using dealii::types::global_dof_index;

  /// Global DoF indices of a hinge stencil in the kernel's local order
  /// (x_{i-1}, phi^{i-1}, x_i, phi^i, x_{i+1}) and the data to evaluate it.
  struct HingeStencil
  {
    std::array<global_dof_index, n_hinge_dofs> dofs;
    unsigned int                               rod;
    /// Triangulation vertices (i-1, i, i+1); the hinge sits at the middle one.
    std::array<unsigned int, 3> vertices;
    unsigned int segment_prev; ///< active cell index of segment i-1
    unsigned int segment_next; ///< active cell index of segment i
  };

  /// Global DoF indices (x_j, x_{j+1}) of a segment and its cell.
  struct SegmentStencil
  {
    std::array<global_dof_index, n_segment_dofs> dofs;
    std::array<unsigned int, 2>                  vertices;
    unsigned int                                 rod;
    unsigned int                                 cell;
  };

  /**
   * Global DoF indices of a junction element (Lestringant & Kochmann eq. 4)
   * in the junction kernel's local order (x_a, x_b, phi, q): the physical
   * segment from x_a to x_b along its rod, its twist, and the junction's
   * quaternion. The ghost segment sits at x_a when the rod starts at the
   * junction (ghost_first), else at x_b.
   */
  struct JunctionStencil
  {
    std::array<global_dof_index, n_hinge_dofs> dofs;
    unsigned int                               rod;
    unsigned int                               junction;
    std::array<unsigned int, 2>                vertices; ///< (a, b)
    unsigned int                               segment;  ///< cell
    bool                                       ghost_first;
  };

  /**
   * The degrees of freedom of a rod network: a DoFHandler<1,3> with
   * FESystem(FE_Q<1,3>(1)^3, FE_DGQ<1,3>(0)) on the segments, i.e. the
   * displacement of every vertex and one twist angle per segment (and
   * nothing on the links of RodNetwork::create_triangulation()), followed by
   * the blocks that element families declare for themselves; and the stencils
   * that the assembler loops over. Index maps come from here only; kernels see
   * local vectors in their documented order.
   *
   * Rod ends tied at a junction keep their own triangulation vertices:
   * deal.II's meshes of dimension 1 do not allow three or more cells at a
   * vertex, so a junction cannot be one shared vertex. Instead the position
   * DoFs of every other end are identity-constrained to those of the
   * junction's vertex (junction_constraints(): x_end = x_junction, deal.II's
   * AffineConstraints). The stencils are built condensed: vertex_dof()
   * returns the junction vertex's DoFs for every end, exactly what
   * AffineConstraints::distribute_local_to_global would make of the ends'
   * own DoFs, without its cost per entry in the assembly. The constrained
   * DoFs take their values from junction_constraints().distribute(), as in
   * any deal.II program; loops over cells (FEValues, DataOut) see them.
   * A rotation handle inside a rod has a junction element on each of the
   * two segments that meet at its vertex and no hinge there.
   *
   * The blocks that element families declare for themselves (add_block(),
   * ElementFamily::own_dofs()) follow the DoFHandler's DoFs, in the order
   * the families are added: the junctions' quaternions
   * (families/junction_family.h; DofRole::rotation, stored as
   * q - (1, 0, 0, 0) so that the zero vector is the reference
   * configuration), the multipliers of inextensible rods
   * (families/inextensibility_family.h), the developable ribbons' slopes
   * and multipliers (families/developable_ribbon_family.h), a user's
   * bonding constraints (families/bonding_constraint.h). The layout reads
   * the rotation DoFs of a declared block to complete the junction stencils
   * and to answer rotation_dof().
   */
  class DofLayout
  {
  public:
    explicit DofLayout(const RodNetwork &network);

    /// The DoFHandler of the positions and twists: the segments' element
    /// (active FE index 0) and FE_Nothing on the links that tie the rods
    /// into one mesh (index 1, RodNetwork::create_triangulation()).
    const dealii::DoFHandler<1, 3> &
    dof_handler() const
    {
      return handler;
    }

    /// The segments' finite element, FESystem(FE_Q<1,3>(1)^3,
    /// FE_DGQ<1,3>(0)), for FEValues on segment_cells().
    const dealii::FiniteElement<1, 3> &
    segment_fe() const
    {
      return fe_collection[0];
    }

    /// The DoFHandler's cells that are segments, without the links: what a
    /// loop with FEValues over the rods takes.
    auto
    segment_cells() const
    {
      return dealii::filter_iterators(
        handler.active_cell_iterators(),
        dealii::IteratorFilters::ActiveFEIndexEqualTo(0));
    }

    /// All DoFs: the DoFHandler's and the families' declared blocks.
    global_dof_index
    n_dofs() const
    {
      return handler.n_dofs() + n_declared_dofs;
    }

    /**
     * Numbers the DoFs @p dofs that family @p owner declares for itself
     * after all others and returns the first. The junction identities grow
     * to the new number of DoFs. Rotation DoFs (DofRole::rotation) complete
     * the junction stencils of their junction; a rotation whose vertex is
     * no junction's, or declared twice, or with fewer than four components,
     * is a programming error (std::logic_error).
     */
    global_dof_index
    add_block(const std::string &owner, std::vector<DeclaredDof> dofs);

    /// The blocks that families declared (add_block()), in their order.
    const std::vector<DofBlock> &
    declared_blocks() const
    {
      return blocks;
    }

    /// DoFs of the DoFHandler (positions and twists) alone.
    global_dof_index
    n_field_dofs() const
    {
      return handler.n_dofs();
    }

    /// DoF of quaternion component @p c (w, x, y, z) of junction @p j,
    /// whose rotation a family must have declared.
    global_dof_index
    rotation_dof(unsigned int j, unsigned int c) const
    {
      return rotation_dofs[j] + c;
    }

    /// Whether junction @p j carries quaternion DoFs (declared ones).
    bool
    has_rotation_dofs(unsigned int j) const
    {
      return rotation_dofs[j] != dealii::numbers::invalid_dof_index;
    }

    /**
     * The identity constraints of the rod ends at junctions: each position
     * DoF of an end's own vertex equals the DoF of the junction's vertex
     * (closed, over all DoFs). distribute() fills a vector's constrained
     * DoFs; the kernels never read them.
     */
    const dealii::AffineConstraints<double> &
    junction_constraints() const
    {
      return junction_identities;
    }

    const std::vector<JunctionStencil> &
    junctions() const
    {
      return junction_list;
    }

    /// DoF of displacement component @p c of triangulation vertex @p v.
    global_dof_index
    vertex_dof(unsigned int v, unsigned int c) const
    {
      return vertex_dofs[v][c];
    }

    /// Twist DoF of the segment on active cell @p cell.
    global_dof_index
    twist_dof(unsigned int cell) const
    {
      return twist_dofs[cell];
    }

    const std::vector<HingeStencil> &
    hinges() const
    {
      return hinge_list;
    }

    const std::vector<SegmentStencil> &
    segments() const
    {
      return segment_list;
    }

  private:
    /// Distributes the DoFHandler's DoFs and reads each vertex's position
    /// DoFs and each segment's twist DoF from it.
    void
    number_field_dofs(const RodNetwork &network);

    /// Constrains the position DoFs of the rod ends at each junction to
    /// those of its vertex, which the stencils use.
    void
    share_junction_vertices(const RodNetwork &network);

    /// The segment stencils of rod @p r.
    void
    add_segment_stencils(unsigned int r, const Rod &rod);

    /// The hinge stencils of rod @p r, but at the vertices where
    /// @p handle_inside holds a rotation handle.
    void
    add_hinge_stencils(unsigned int             r,
                       const Rod               &rod,
                       const std::vector<bool> &handle_inside);

    /// The junction elements of every junction with a rotation (their
    /// quaternion DoFs come with its declared block: number_rotations()).
    void
    add_junction_stencils(const RodNetwork &network);

    /// Adds the junction element of junction @p junction on segment
    /// @p segment (index along rod @p rod_index, which is @p rod), with
    /// the ghost before (@p ghost_first) or after it.
    void
    add_junction_stencil(unsigned int junction,
                         unsigned int rod_index,
                         const Rod   &rod,
                         unsigned int segment,
                         bool         ghost_first);

    /// Records the rotation DoFs of the newly numbered @p block and
    /// completes the junction stencils with them.
    void
    number_rotations(const DofBlock &block);

    dealii::hp::FECollection<1, 3>               fe_collection;
    dealii::DoFHandler<1, 3>                     handler;
    std::vector<std::array<global_dof_index, 3>> vertex_dofs;
    std::vector<global_dof_index>                twist_dofs;
    std::vector<HingeStencil>                    hinge_list;
    std::vector<SegmentStencil>                  segment_list;
    std::vector<JunctionStencil>                 junction_list;
    /// First quaternion DoF per junction, invalid where it has none.
    std::vector<global_dof_index> rotation_dofs;
    /// The junction at each junction vertex.
    std::unordered_map<unsigned int, unsigned int> junction_of_vertex;
    std::vector<DofBlock>                          blocks;
    global_dof_index                               n_declared_dofs = 0;
    dealii::AffineConstraints<double>              junction_identities;
  };
} // namespace rodnet

#endif
