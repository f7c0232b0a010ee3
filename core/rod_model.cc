#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <core/rod_model.h>
#include <elements/junction_moment.h>

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

    std::vector<std::vector<unsigned int>> sizes(3);
    for (const HingeStencil &h : layout_->hinges())
      sizes[0].push_back(materials[h.rod]->n_hinge_internal_variables());
    for (const JunctionStencil &e : layout_->junctions())
      sizes[1].push_back(materials[e.rod]->n_hinge_internal_variables());
    for (const SegmentStencil &s : layout_->segments())
      sizes[2].push_back(materials[s.rod]->n_segment_internal_variables());
    history = InternalVariables(sizes);

    // Supports that junctions imply, and the gauge of their quaternions:
    // the real part of every increment stays 1 (stored as 0).
    const auto &junctions = network_->junctions();
    for (unsigned int j = 0; j < junctions.size(); ++j)
      {
        if (junctions[j].fixes_position())
          fix_components(junctions[j].name,
                         junctions[j].vertex,
                         {{true, true, true}});
        if (!layout_->has_rotation_dofs(j))
          continue;
        fixed_dofs[layout_->rotation_dof(j, 0)] = 0.0;
        if (junctions[j].kind == JunctionKind::clamped)
          for (unsigned int c = 1; c < 4; ++c)
            fixed_dofs[layout_->rotation_dof(j, c)] = 0.0;
      }
  }

  void
  RodModel::add_moment(const unsigned int junction,
                       const Vector3     &axis,
                       const double       moment)
  {
    if (junction >= network_->junctions().size())
      throw std::invalid_argument("moment at junction " +
                                  std::to_string(junction) +
                                  ", which does not exist");
    const Junction &j = network_->junctions()[junction];
    if (!j.has_rotation() || j.kind == JunctionKind::clamped)
      throw std::invalid_argument("moment at junction \"" + j.name + "\": a " +
                                  to_string(j.kind) +
                                  " junction has no free rotation to load");
    if (!(std::abs(axis.norm() - 1.0) < 1e-9))
      throw std::invalid_argument("moment at junction \"" + j.name +
                                  "\": the axis must be a unit vector");
    moments.push_back({junction, axis, moment});
  }

  void
  RodModel::prescribe_rotation(const unsigned int junction,
                               const Vector3     &axis,
                               const double       angle)
  {
    if (junction >= network_->junctions().size())
      throw std::invalid_argument("prescribed rotation of junction " +
                                  std::to_string(junction) +
                                  ", which does not exist");
    const Junction &j = network_->junctions()[junction];
    if (j.kind != JunctionKind::clamped)
      throw std::invalid_argument(
        "prescribed rotation of junction \"" + j.name +
        "\": only clamped "
        "junctions have a prescribed rotation; this one is " +
        to_string(j.kind));
    if (!(std::abs(axis.norm() - 1.0) < 1e-9))
      throw std::invalid_argument("prescribed rotation of junction \"" +
                                  j.name +
                                  "\": the axis must be a unit vector");
    prescribed_rotations.push_back({junction, axis, angle});
  }

  void
  RodModel::prescribe_rotation(const unsigned int junction,
                               const Quaternion  &rotation)
  {
    if (!(std::abs(rotation.norm() - 1.0) < 1e-9))
      throw std::invalid_argument("prescribed rotation of junction " +
                                  std::to_string(junction) +
                                  ": the quaternion has norm " +
                                  std::to_string(rotation.norm()) + ", not 1");
    const Eigen::AngleAxisd angle_axis(rotation);
    prescribe_rotation(junction, angle_axis.axis(), angle_axis.angle());
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

  Vector3
  RodModel::reaction_moment(const unsigned int junction,
                            const VectorType  &u,
                            const double       load_factor) const
  {
    if (junction >= network_->junctions().size() ||
        !layout_->has_rotation_dofs(junction))
      throw std::invalid_argument("reaction moment: junction " +
                                  std::to_string(junction) +
                                  " does not exist or has no rotation");
    VectorType r = create_vector();
    assemble(u, load_factor, &r, nullptr, false);
    Eigen::Vector4d q, gradient;
    for (unsigned int c = 0; c < 4; ++c)
      {
        q[c]        = u[layout_->rotation_dof(junction, c)] + (c == 0);
        gradient[c] = r[layout_->rotation_dof(junction, c)];
      }
    return spatial_moment(q, gradient);
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
    loads.add_point_force(*network_, vertex, force);
  }

  void
  RodModel::add_distributed_force(const unsigned int rod,
                                  const Vector3     &force_per_length)
  {
    loads.add_distributed_force(*network_, rod, force_per_length);
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

    dealii::DynamicSparsityPattern dsp(layout_->n_dofs());
    layout_->make_sparsity_pattern(dsp, no_constraints);
    sparsity.reinit(all, MPI_COMM_WORLD);
    sparsity.copy_from(dsp);
    sparsity.compress();

    // Dead loads: point forces, and distributed forces lumped with the
    // undeformed Voronoi lengths (half of each adjacent segment).
    f_ext = create_vector();
    for (const auto &[vertex, force] : loads.point_forces)
      for (unsigned int c = 0; c < 3; ++c)
        f_ext[layout_->vertex_dof(vertex, c)] += force[c];
    for (const auto &[rod_index, q] : loads.distributed_forces)
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
    // A prescribed rotation is reached from the reference rotation by an
    // increment (1, v) in the gauge of the quaternion DoFs.
    for (const AxisLoad &p : prescribed_rotations)
      {
        Quaternion increment =
          rotation_about(p.axis, load_factor * p.value) *
          configuration_->reference_rotation(p.junction).conjugate();
        if (increment.w() < 0)
          increment.coeffs() *= -1.0;
        if (!(increment.w() > 1e-3))
          throw std::runtime_error(
            "the prescribed rotation of junction \"" +
            network_->junctions()[p.junction].name +
            "\" turns by nearly 180 degrees or more within one step; use "
            "more load steps");
        u[layout_->rotation_dof(p.junction, 0)] = 0.0;
        for (unsigned int c = 1; c < 4; ++c)
          u[layout_->rotation_dof(p.junction, c)] =
            increment.vec()[c - 1] / increment.w();
      }
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
