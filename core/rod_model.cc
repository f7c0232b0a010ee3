#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <core/rod_model.h>

#include <stdexcept>

namespace rodnet
{
  RodModel::RodModel(
    std::unique_ptr<RodNetwork>                     network,
    std::vector<std::shared_ptr<const RodMaterial>> rod_materials)
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
    std::vector<const HingeKernel *> rod_kernels;
    for (const Rod &rod : rods)
      {
        kernels.push_back(create_hinge_kernel(rod.hinge_kernel));
        rod_kernels.push_back(kernels.back().get());
      }
    layout_ = std::make_unique<DofLayout>(*network_);
    configuration_ =
      std::make_unique<Configuration>(*network_, *layout_, rod_kernels);
  }

  void
  RodModel::clamp_end(const std::string &name,
                      const unsigned int rod_index,
                      const bool         at_start)
  {
    const Rod &rod = network_->rods().at(rod_index);
    if (rod.closed)
      throw std::invalid_argument("support \"" + name + "\": rod " +
                                  std::to_string(rod_index) +
                                  " is closed and has no end to clamp");
    const unsigned int n = rod.vertices.size();
    Support            s;
    s.name = name;
    s.vertices =
      at_start ?
        std::vector<unsigned int>{rod.vertices[0], rod.vertices[1]} :
        std::vector<unsigned int>{rod.vertices[n - 2], rod.vertices[n - 1]};
    s.fixed.assign(2, {{true, true, true}});
    for (const unsigned int v : s.vertices)
      for (unsigned int c = 0; c < 3; ++c)
        fixed_dofs[layout_->vertex_dof(v, c)] = 0.0;
    const unsigned int end_segment =
      at_start ? rod.segments.front() : rod.segments.back();
    fixed_dofs[layout_->twist_dof(end_segment)] = 0.0;
    support_list.push_back(s);
  }

  void
  RodModel::fix_components(const std::string         &name,
                           const unsigned int         vertex,
                           const std::array<bool, 3> &mask,
                           const Vector3             &displacement)
  {
    if (vertex >= network_->n_vertices())
      throw std::invalid_argument("support \"" + name + "\": vertex " +
                                  std::to_string(vertex) + " does not exist");
    Support s;
    s.name     = name;
    s.vertices = {vertex};
    s.fixed    = {mask};
    for (unsigned int c = 0; c < 3; ++c)
      if (mask[c])
        fixed_dofs[layout_->vertex_dof(vertex, c)] = displacement[c];
    support_list.push_back(s);
  }

  void
  RodModel::add_point_force(const unsigned int vertex, const Vector3 &force)
  {
    if (vertex >= network_->n_vertices())
      throw std::invalid_argument("point force at vertex " +
                                  std::to_string(vertex) +
                                  ", which does not exist");
    point_forces.emplace_back(vertex, force);
  }

  void
  RodModel::add_distributed_force(const unsigned int rod,
                                  const Vector3     &force_per_length)
  {
    if (rod >= network_->rods().size())
      throw std::invalid_argument("distributed force on rod " +
                                  std::to_string(rod) +
                                  ", which does not exist");
    distributed_forces.emplace_back(rod, force_per_length);
  }

  const Support &
  RodModel::support(const std::string &name) const
  {
    for (const Support &s : support_list)
      if (s.name == name)
        return s;
    throw std::invalid_argument("no support named \"" + name + "\"");
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
  RodModel::finalize()
  {
    if (finalized)
      throw std::logic_error("RodModel::finalize called twice");
    const dealii::IndexSet all = dealii::complete_index_set(layout_->n_dofs());

    // A segment twist that no hinge sees (a rod of one segment) has no
    // stiffness: fix it rather than leave the tangent singular.
    std::vector<bool> twist_seen(network_->triangulation().n_active_cells());
    for (const HingeStencil &h : layout_->hinges())
      twist_seen[h.segment_prev] = twist_seen[h.segment_next] = true;
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

    dealii::DynamicSparsityPattern dsp(layout_->n_dofs());
    layout_->make_sparsity_pattern(dsp, no_constraints);
    sparsity.reinit(all, MPI_COMM_WORLD);
    sparsity.copy_from(dsp);
    sparsity.compress();

    // Dead loads: point forces, and distributed forces lumped with the
    // undeformed Voronoi lengths (half of each adjacent segment).
    f_ext = create_vector();
    for (const auto &[vertex, force] : point_forces)
      for (unsigned int c = 0; c < 3; ++c)
        f_ext[layout_->vertex_dof(vertex, c)] += force[c];
    for (const auto &[rod_index, q] : distributed_forces)
      for (const SegmentStencil &s : layout_->segments())
        if (s.rod == rod_index)
          {
            const double half = 0.5 * configuration_->rest_length(s.cell);
            for (unsigned int c = 0; c < 3; ++c)
              {
                f_ext[s.dofs[c]] += half * q[c];
                f_ext[s.dofs[3 + c]] += half * q[c];
              }
          }
    f_ext.compress(dealii::VectorOperation::add);

    Vector3 low = network_->vertex(0), high = low;
    for (unsigned int v = 0; v < network_->n_vertices(); ++v)
      {
        low  = low.cwiseMin(network_->vertex(v));
        high = high.cwiseMax(network_->vertex(v));
      }
    length    = (high - low).norm();
    finalized = true;
  }

  void
  RodModel::apply_boundary_values(VectorType &u, const double load_factor) const
  {
    for (const auto &[dof, value] : fixed_dofs)
      u[dof] = load_factor * value;
    u.compress(dealii::VectorOperation::insert);
  }

  Vector3
  RodModel::reaction(const Support    &s,
                     const VectorType &u,
                     const double      load_factor) const
  {
    VectorType r = create_vector();
    assemble(u, load_factor, &r, nullptr, false);
    // At a fixed DoF the support force F balances the residual:
    // dPhi/du - F = 0, so F is the residual there.
    Vector3 total = Vector3::Zero();
    for (unsigned int k = 0; k < s.vertices.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        if (s.fixed[k][c])
          total[c] += r[layout_->vertex_dof(s.vertices[k], c)];
    return total;
  }
} // namespace rodnet
