#ifndef RODNET_CORE_DOF_LAYOUT_H
#define RODNET_CORE_DOF_LAYOUT_H

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <core/rod_network.h>
#include <elements/hinge_kernel.h>
#include <elements/stretch_kernel.h>

#include <array>
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
   * The degrees of freedom of a rod network: a DoFHandler<1,3> with
   * FESystem(FE_Q<1,3>(1)^3, FE_DGQ<1,3>(0)), i.e. the displacement of
   * every vertex and one twist angle per segment, and the stencils that
   * the assembler loops over. Index maps come from here only; kernels see
   * local vectors in their documented order.
   */
  class DofLayout
  {
  public:
    explicit DofLayout(const RodNetwork &network);

    const dealii::DoFHandler<1, 3> &
    dof_handler() const
    {
      return handler;
    }

    global_dof_index
    n_dofs() const
    {
      return handler.n_dofs();
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

    /// Sparsity of the tangent: every pair of DoFs of a common stencil.
    void
    make_sparsity_pattern(
      dealii::DynamicSparsityPattern          &dsp,
      const dealii::AffineConstraints<double> &constraints) const;

  private:
    dealii::FESystem<1, 3>                       fe;
    dealii::DoFHandler<1, 3>                     handler;
    std::vector<std::array<global_dof_index, 3>> vertex_dofs;
    std::vector<global_dof_index>                twist_dofs;
    std::vector<HingeStencil>                    hinge_list;
    std::vector<SegmentStencil>                  segment_list;
  };
} // namespace rodnet

#endif
