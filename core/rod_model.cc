#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <base/first_problem.h>
#include <core/built_in_families.h>
#include <core/every_entry.h>
#include <core/rod_model.h>
#include <core/stencil_coloring.h>

#include <Epetra_BlockMap.h>
#include <algorithm>
#include <map>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The pointers that @p owners hold, in their order.
    template <class T>
    std::vector<const T *>
    raw_pointers(const std::vector<std::unique_ptr<T>> &owners)
    {
      std::vector<const T *> pointers;
      for (const std::unique_ptr<T> &owner : owners)
        pointers.push_back(owner.get());
      return pointers;
    }
  } // namespace

  RodModel::RodModel(
    std::unique_ptr<RodNetwork>                     network,
    std::vector<std::shared_ptr<const RodMaterial>> rod_materials,
    const GhostSpin                                 ghost_spin,
    const MPI_Comm                                  communicator)
      : mpi_communicator(communicator)
      , network_(std::move(network))
      , materials(std::move(rod_materials))
  {
    if (network_->triangulation().n_active_cells() == 0)
      network_->create_triangulation();
    const auto &rods = network_->rods();
    if (materials.size() != rods.size())
      throw std::invalid_argument(
        "RodModel: " + std::to_string(rods.size()) + " rods but " +
        std::to_string(materials.size()) + " materials");
    // A rod whose material is a developable ribbon gets its DoFs.
    for (unsigned int r = 0; r < rods.size(); ++r)
      if (materials[r] != nullptr && materials[r]->developable_ribbon())
        network_->set_developable(r);
    create_kernels(ghost_spin);
    layout_ = std::make_unique<DofLayout>(*network_);
    // Every DoF until finalize() is told which this process owns: vectors
    // made before it (the reference frame of a clamp) must hold them all.
    owned_dofs = dealii::complete_index_set(layout_->n_dofs());
    configuration_ =
      std::make_unique<Configuration>(*network_,
                                      *layout_,
                                      raw_pointers(kernels),
                                      raw_pointers(junction_kernels));
    add_built_in_families();
    add_junction_supports();
  }

  void
  RodModel::add_built_in_families()
  {
    const ModelParts             parts{*layout_,
                           *network_,
                           *configuration_,
                           kernels,
                           junction_kernels,
                           materials};
    const BuiltInFamilyRegistry &registry = built_in_family_registry();
    for (const std::string &name : registry.names())
      if (std::unique_ptr<ElementFamily> family = registry.create(name, parts))
        add_element_family(std::move(family));
  }

  void
  RodModel::create_kernels(const GhostSpin ghost_spin)
  {
    for (const Rod &rod : network_->rods())
      {
        kernels.push_back(create_hinge_kernel(rod.hinge_kernel));
        junction_kernels.push_back(
          std::make_unique<JunctionKernel>(rod.hinge_kernel, ghost_spin));
      }
  }

  void
  RodModel::add_junction_supports()
  {
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
    // Every process keeps the whole configuration.
    configuration_->reset_reference(*EveryEntry(u));
    for (unsigned int j = 0; j < network_->junctions().size(); ++j)
      if (layout_->has_rotation_dofs(j))
        for (unsigned int c = 0; c < 4; ++c)
          if (owned_dofs.is_element(layout_->rotation_dof(j, c)))
            u[layout_->rotation_dof(j, c)] = 0.0;
    u.compress(dealii::VectorOperation::insert);
    // A converged state carries the junction vertices' positions at the
    // other rod ends too.
    layout_->junction_constraints().distribute(u);
  }

  void
  RodModel::add_point_force(const unsigned int vertex, const Vector3 &force)
  {
    require_not_finalized("RodModel::add_point_force at vertex " +
                          std::to_string(vertex));
    loads.add_point_force(*network_, vertex, force);
  }

  void
  RodModel::add_held_point_force(const unsigned int vertex,
                                 const Vector3     &force)
  {
    require_not_finalized("RodModel::add_held_point_force at vertex " +
                          std::to_string(vertex));
    held_loads.add_point_force(*network_, vertex, force);
  }

  void
  RodModel::add_rigid_body(const RigidBody &body)
  {
    require_not_finalized("RodModel::add_rigid_body " + body.where);
    check_rigid_body(*network_, body);
    bodies.push_back(body);
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
    return VectorType(owned_dofs, mpi_communicator);
  }

  void
  RodModel::initialize_matrix(MatrixType &matrix) const
  {
    // Before finalize() the pattern is empty, and a tangent assembled
    // into it would silently lose its entries.
    require_finalized("RodModel::initialize_matrix");
    matrix.reinit(sparsity);
  }

  void
  RodModel::add_element_family(std::unique_ptr<ElementFamily> family)
  {
    require_not_finalized("RodModel::add_element_family \"" + family->name() +
                          "\"");
    std::vector<DeclaredDof> own = family->own_dofs();
    if (!own.empty())
      {
        family->number_own_dofs(
          layout_->add_block(family->name(), std::move(own)));
        block_owners.push_back(family.get());
        owned_dofs = dealii::complete_index_set(layout_->n_dofs());
      }
    families.push_back(std::move(family));
    history = InternalVariables(families);
  }


  void
  RodModel::add_sparsity_pattern(dealii::DynamicSparsityPattern &pattern,
                                 const SystemBlock              &block) const
  {
    std::vector<global_dof_index> dofs;
    for (const auto &family : families)
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, dofs);
          block.map(dofs);
          // A row's columns in one sorted range, not entry by entry: the
          // pattern merges a range at once (and ignores rows it does not
          // keep, see make_sparsity_pattern()).
          std::sort(dofs.begin(), dofs.end());
          dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
          for (const global_dof_index i : dofs)
            pattern.add_entries(i, dofs.begin(), dofs.end(), true);
        }
    // DoFs that no stencil sees (the twist of a one-segment rod, the
    // junction copies) still need their diagonal entry.
    for (global_dof_index i = 0; i < block.size(); ++i)
      pattern.add(block.index(i), block.index(i));
  }


  void
  RodModel::make_sparsity_pattern()
  {
    // On several processes only the own rows are kept (the pattern ignores
    // entries of other rows): their sorted insertions were half of the
    // set-up of the welded lattice of 1.1e6 DoFs on each process.
    const global_dof_index         n = layout_->n_dofs();
    dealii::DynamicSparsityPattern pattern =
      owned_dofs.n_elements() == n ?
        dealii::DynamicSparsityPattern(n) :
        dealii::DynamicSparsityPattern(n, n, owned_dofs);
    add_sparsity_pattern(pattern, SystemBlock::at_offset(n, 0));
    // reinit() with the partition: copy_from() would make the pattern of
    // one process, every row on each.
    sparsity.reinit(owned_dofs, owned_dofs, pattern, mpi_communicator);

    std::vector<bool>             seen(layout_->n_dofs(), false);
    std::vector<global_dof_index> dofs;
    for (const auto &family : families)
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, dofs);
          for (const global_dof_index i : dofs)
            seen[i] = true;
        }
    unseen_dofs.clear();
    for (global_dof_index i = 0; i < seen.size(); ++i)
      if (!seen[i])
        unseen_dofs.push_back(i);
  }


  void
  RodModel::finalize()
  {
    finalize(balanced_share(
      families,
      layout_->n_dofs(),
      dealii::Utilities::MPI::n_mpi_processes(mpi_communicator),
      dealii::Utilities::MPI::this_mpi_process(mpi_communicator)));
  }


  void
  RodModel::finalize(const dealii::IndexSet &locally_owned_dofs)
  {
    if (finalized)
      throw std::logic_error("RodModel::finalize called twice");
    check_ownership(locally_owned_dofs);
    owned_dofs = locally_owned_dofs;
    length     = rodnet::length_scale(*network_);
    resolve_supports();

    // A segment twist that no hinge sees (a rod of one segment) has no
    // stiffness: fix it rather than leave the tangent singular.
    std::vector<bool> twist_seen(network_->n_segments());
    for (const HingeStencil &h : layout_->hinges())
      twist_seen[h.segment_prev] = twist_seen[h.segment_next] = true;
    for (const JunctionStencil &e : layout_->junctions())
      twist_seen[e.segment] = true;
    for (unsigned int cell = 0; cell < twist_seen.size(); ++cell)
      if (!twist_seen[cell])
        fixed_dofs.emplace(layout_->twist_dof(cell), 0.0);
    collect_declared_multipliers();
    make_constraints();

    make_sparsity_pattern();

    f_ext  = force_vector(loads);
    f_held = force_vector(held_loads);
    for (const auto &family : families)
      stencil_blocks.push_back(
        color_stencil_blocks(*family,
                             layout_->n_dofs(),
                             default_block_size(family->n_stencils())));
    if (dealii::Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
      {
        own_stencils = stencils_anchored(families, owned_dofs);
        share_starts =
          dealii::Utilities::MPI::all_gather(mpi_communicator,
                                             owned_dofs.nth_index_in_set(0));
        share_starts.push_back(layout_->n_dofs());
        const Epetra_BlockMap &columns =
          sparsity.trilinos_sparsity_pattern().ColMap();
        local_columns.assign(layout_->n_dofs(), -1);
        for (int c = 0; c < columns.NumMyElements(); ++c)
          local_columns[columns.GID(c)] = c;
        ghosted_state.reinit(owned_dofs,
                             dofs_read_by(families, own_stencils, owned_dofs),
                             mpi_communicator);
        ghost_import = std::make_unique<Epetra_Import>(
          ghosted_state.trilinos_vector().Map(),
          create_vector().trilinos_vector().Map());
        const Epetra_BlockMap &held = ghosted_state.trilinos_vector().Map();
        ghost_places.assign(layout_->n_dofs(), -1);
        for (int k = 0; k < held.NumMyElements(); ++k)
          ghost_places[held.GID64(k)] = k;
      }
    finalized = true;
  }


  VectorType
  RodModel::force_vector(const DeadLoads &dead_loads) const
  {
    // Distributed forces lumped by Voronoi lengths.
    VectorType                 f      = create_vector();
    const std::vector<Vector3> forces = dead_loads.vertex_forces(*network_);
    for (unsigned int v = 0; v < forces.size(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        if (owned_dofs.is_element(layout_->vertex_dof(v, c)))
          f[layout_->vertex_dof(v, c)] += forces[v][c];
    f.compress(dealii::VectorOperation::add);
    return f;
  }


  void
  RodModel::collect_declared_multipliers()
  {
    // A declared multiplier is free where a stencil couples it to a DoF
    // that is neither held nor declared; one that sees held DoFs only has
    // a zero row in the tangent.
    std::map<global_dof_index, bool> sees_free;
    std::vector<bool>                declared(layout_->n_dofs(), false);
    for (const DofBlock &block : layout_->declared_blocks())
      for (unsigned int i = 0; i < block.dofs.size(); ++i)
        {
          declared[block.first + i] = true;
          if (block.dofs[i].role == DofRole::multiplier)
            sees_free[block.first + i] = false;
        }
    if (sees_free.empty())
      return;
    std::vector<global_dof_index> dofs;
    for (const auto &family : families)
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, dofs);
          bool free = false;
          for (const global_dof_index d : dofs)
            free = free || (fixed_dofs.count(d) == 0 && !declared[d]);
          for (const global_dof_index d : dofs)
            if (free && sees_free.count(d) > 0)
              sees_free[d] = true;
        }
    hold_or_free_declared_multipliers(sees_free);
  }


  void
  RodModel::hold_or_free_declared_multipliers(
    const std::map<global_dof_index, bool> &sees_free)
  {
    const std::vector<DofBlock> &blocks = layout_->declared_blocks();
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const DofBlock   &block = blocks[b];
        std::vector<bool> held(block.dofs.size(), false);
        for (unsigned int i = 0; i < block.dofs.size(); ++i)
          {
            const global_dof_index d   = block.first + i;
            const DeclaredDof     &dof = block.dofs[i];
            if (dof.role != DofRole::multiplier)
              continue;
            if (sees_free.at(d))
              free_multipliers.push_back(d);
            else if (dof.held_where_supports_hold)
              {
                held[i]       = true;
                fixed_dofs[d] = 0.0;
              }
            else
              throw std::invalid_argument(
                block.owner + ": " + dof.label +
                " constrains DoFs that the supports hold already; remove "
                "the constraint or the support");
          }
        block_owners[b]->hold_own_dofs(held);
      }
    // The families that left out stencils keep no internal variables for
    // them.
    history = InternalVariables(families);
  }


  double
  RodModel::axial_force(const unsigned int cell, const VectorType &u) const
  {
    const StencilState state{u, *configuration_, history, 0.0, 0.0};
    for (const auto &family : families)
      if (const std::optional<double> force =
            family->segment_axial_force(cell, state))
        return *force;
    return 0.0;
  }


  void
  RodModel::check_ownership(const dealii::IndexSet &locally_owned_dofs) const
  {
    const global_dof_index n_dofs = layout_->n_dofs();
    const unsigned int     n_processes =
      dealii::Utilities::MPI::n_mpi_processes(mpi_communicator);
    std::string problem;
    if (locally_owned_dofs.size() != n_dofs)
      problem = "the locally owned DoFs are a subset of " +
                std::to_string(locally_owned_dofs.size()) +
                " indices, the model has " + std::to_string(n_dofs) + " DoFs";
    else if (!locally_owned_dofs.is_contiguous())
      problem = "the locally owned DoFs of a process must be one contiguous "
                "range";
    else if (locally_owned_dofs.n_elements() == 0)
      problem = "the network has " + std::to_string(n_dofs) + " DoFs for " +
                std::to_string(n_processes) +
                " processes, too few for each to own one (process " +
                std::to_string(
                  dealii::Utilities::MPI::this_mpi_process(mpi_communicator)) +
                " would own none); run on fewer processes";
    // Collective from here on: every process reaches the same verdict.
    problem = first_problem(problem, mpi_communicator);
    if (problem.empty() &&
        (dealii::Utilities::MPI::sum(locally_owned_dofs.n_elements(),
                                     mpi_communicator) != n_dofs ||
         !locally_owned_dofs.is_ascending_and_one_to_one(mpi_communicator)))
      problem = "the locally owned DoFs of the " + std::to_string(n_processes) +
                " process(es) are not a partition of all " +
                std::to_string(n_dofs) + " DoFs in rank order";
    if (!problem.empty())
      throw std::invalid_argument("RodModel::finalize: " + problem);
  }


  void
  RodModel::make_constraints()
  {
    // The supports' fixed DoFs, homogeneous (Newton increments are zero
    // there), and the identity constraints of the junction copies.
    // Every process keeps every line: the network is on every process.
    homogeneous_constraints.reinit(
      dealii::complete_index_set(layout_->n_dofs()));
    for (const auto &[dof, value] : fixed_dofs)
      homogeneous_constraints.add_line(dof);
    for (const auto &line : layout_->junction_constraints().get_lines())
      {
        homogeneous_constraints.add_line(line.index);
        homogeneous_constraints.add_entries(line.index, line.entries);
      }
    homogeneous_constraints.close();
    fixed_dof_mask.assign(layout_->n_dofs(), false);
    for (const auto &line : homogeneous_constraints.get_lines())
      fixed_dof_mask[line.index] = true;
    no_constraints.reinit(dealii::complete_index_set(layout_->n_dofs()));
    no_constraints.close();
  }

} // namespace rodnet
