#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <core/rod_model.h>
#include <families/axis_moment_family.h>
#include <families/hinge_family.h>
#include <families/junction_family.h>
#include <families/stretch_family.h>

#include <stdexcept>

namespace rodnet
{
  RodModel::RodModel(
    std::unique_ptr<RodNetwork>                     network,
    std::vector<std::shared_ptr<const RodMaterial>> rod_materials,
    const GhostSpin                                 ghost_spin)
      : network_(std::move(network))
      , materials(std::move(rod_materials))
  {
    if (network_->triangulation().n_active_cells() == 0)
      network_->create_triangulation();
    const auto &rods = network_->rods();
    if (materials.size() != rods.size())
      throw std::invalid_argument(
        "RodModel: " + std::to_string(rods.size()) + " rods but " +
        std::to_string(materials.size()) + " materials");
    std::vector<const HingeKernel *>    rod_kernels;
    std::vector<const JunctionKernel *> rod_junction_kernels;
    for (const Rod &rod : rods)
      {
        kernels.push_back(create_hinge_kernel(rod.hinge_kernel));
        rod_kernels.push_back(kernels.back().get());
        junction_kernels.push_back(
          std::make_unique<JunctionKernel>(rod.hinge_kernel, ghost_spin));
        rod_junction_kernels.push_back(junction_kernels.back().get());
      }
    layout_        = std::make_unique<DofLayout>(*network_);
    configuration_ = std::make_unique<Configuration>(*network_,
                                                     *layout_,
                                                     rod_kernels,
                                                     rod_junction_kernels);
    families.push_back(
      std::make_unique<HingeFamily>(*layout_, kernels, materials));
    families.push_back(
      std::make_unique<JunctionFamily>(*layout_, junction_kernels, materials));
    families.push_back(std::make_unique<StretchFamily>(*layout_, materials));

    history = InternalVariables(families);

    // Supports that junctions imply; a prescribed displacement at their
    // vertex moves them.
    const auto &junctions = network_->junctions();
    rotation_held.assign(junctions.size(), false);
    for (unsigned int j = 0; j < junctions.size(); ++j)
      {
        if (junctions[j].fixes_position())
          {
            add_position_support(junctions[j].name,
                                 junctions[j].vertex,
                                 {{true, true, true}},
                                 Vector3::Zero(),
                                 true);
            support_list.back().clamped =
              junctions[j].kind == JunctionKind::clamped;
          }
        rotation_held[j] = junctions[j].kind == JunctionKind::clamped;
      }
  }

  void
  RodModel::reset_reference(VectorType &u)
  {
    configuration_->reset_reference(u);
    for (unsigned int j = 0; j < network_->junctions().size(); ++j)
      if (layout_->has_rotation_dofs(j))
        for (unsigned int c = 0; c < 4; ++c)
          u[layout_->rotation_dof(j, c)] = 0.0;
    u.compress(dealii::VectorOperation::insert);
  }

  void
  RodModel::add_point_force(const unsigned int vertex, const Vector3 &force)
  {
    require_not_finalized("RodModel::add_point_force at vertex " +
                          std::to_string(vertex));
    loads.add_point_force(*network_, vertex, force);
  }

  void
  RodModel::add_distributed_force(const unsigned int rod,
                                  const Vector3     &force_per_length)
  {
    require_not_finalized("RodModel::add_distributed_force on rod " +
                          std::to_string(rod));
    loads.add_distributed_force(*network_, rod, force_per_length);
  }

  VectorType
  RodModel::create_vector() const
  {
    return VectorType(dealii::complete_index_set(layout_->n_dofs()),
                      MPI_COMM_WORLD);
  }

  void
  RodModel::initialize_matrix(MatrixType &matrix) const
  {
    matrix.reinit(sparsity);
  }

  void
  RodModel::add_element_family(std::unique_ptr<ElementFamily> family)
  {
    require_not_finalized("RodModel::add_element_family \"" +
                          family->name() + "\"");
    families.push_back(std::move(family));
    history = InternalVariables(families);
  }


  void
  RodModel::make_sparsity_pattern()
  {
    dealii::DynamicSparsityPattern dsp(layout_->n_dofs());
    std::vector<global_dof_index>  dofs;
    for (const auto &family : families)
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, dofs);
          for (const global_dof_index i : dofs)
            for (const global_dof_index j : dofs)
              dsp.add(i, j);
        }
    // DoFs that no stencil sees (the twist of a one-segment rod, unused
    // copies of shared vertices) still need their diagonal entry.
    for (global_dof_index i = 0; i < layout_->n_dofs(); ++i)
      dsp.add(i, i);
    sparsity.reinit(dealii::complete_index_set(layout_->n_dofs()),
                    MPI_COMM_WORLD);
    sparsity.copy_from(dsp);
    sparsity.compress();
  }


  void
  RodModel::finalize()
  {
    if (finalized)
      throw std::logic_error("RodModel::finalize called twice");
    const dealii::IndexSet all = dealii::complete_index_set(layout_->n_dofs());
    length                     = rodnet::length_scale(*network_);
    resolve_supports();

    // A segment twist that no hinge sees (a rod of one segment) has no
    // stiffness: fix it rather than leave the tangent singular.
    std::vector<bool> twist_seen(network_->triangulation().n_active_cells());
    for (const HingeStencil &h : layout_->hinges())
      twist_seen[h.segment_prev] = twist_seen[h.segment_next] = true;
    for (const JunctionStencil &e : layout_->junctions())
      twist_seen[e.segment] = true;
    // Position DoFs of rod ends that share a junction vertex are unused.
    for (const auto &copy : layout_->shared_copies())
      fixed_dofs.emplace(copy.first, 0.0);
    for (unsigned int cell = 0; cell < twist_seen.size(); ++cell)
      if (!twist_seen[cell])
        fixed_dofs.emplace(layout_->twist_dof(cell), 0.0);

    homogeneous_constraints.reinit(all);
    fixed_dof_mask.assign(layout_->n_dofs(), false);
    for (const auto &[dof, value] : fixed_dofs)
      {
        homogeneous_constraints.add_line(dof);
        fixed_dof_mask[dof] = true;
      }
    homogeneous_constraints.close();
    no_constraints.reinit(all);
    no_constraints.close();

    std::vector<AxisMoment> axis_moments;
    for (const AxisLoad &m : moments)
      axis_moments.push_back({m.junction, m.axis, m.value});
    if (!axis_moments.empty())
      families.push_back(
        std::make_unique<AxisMomentFamily>(*layout_, std::move(axis_moments)));
    make_sparsity_pattern();

    // Dead loads, distributed ones lumped by Voronoi lengths.
    f_ext                              = create_vector();
    const std::vector<Vector3> forces = loads.vertex_forces(*network_);
    for (unsigned int v = 0; v < forces.size(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        f_ext[layout_->vertex_dof(v, c)] += forces[v][c];
    f_ext.compress(dealii::VectorOperation::add);
    finalized = true;
  }

} // namespace rodnet
