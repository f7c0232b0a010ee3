// Assembly of the total potential energy of a RodModel, its gradient and
// its Hessian: for every stencil, element kernel (strains and their
// derivatives) -> material (energy, stress, tangent) -> chain rule ->
// constraints -> global Trilinos objects.
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <base/phase_times.h>
#include <core/direct_scatter.h>
#include <core/every_entry.h>
#include <core/rod_model.h>
#include <core/scatter_positions.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The scratch data of the stencil loops: none, the kernels keep
    /// theirs on the stack.
    struct NoAssemblyScratch
    {
    };

    /**
     * Calls @p worker (stencil, scratch, copy) and then @p add (copy) on
     * every stencil of @p blocks: the colors one after the other, the
     * blocks of a color in parallel, @p add included (a color's blocks
     * share no row). Templates rather than std::function, so that both
     * calls stay inlined in the stencil loop.
     */
    template <typename Worker, typename Add>
    void
    run_in_colors(const StencilBlocks &blocks,
                  const Worker        &worker,
                  const Add           &add)
    {
      for (const std::vector<unsigned int> &color : blocks.colors)
        dealii::parallel::apply_to_subranges(
          std::size_t(0),
          color.size(),
          [&](const std::size_t begin, const std::size_t end) {
            NoAssemblyScratch scratch;
            LocalContribution copy;
            for (std::size_t k = begin; k < end; ++k)
              for (unsigned int s = blocks.first[color[k]];
                   s < blocks.first[color[k] + 1];
                   ++s)
                {
                  worker(s, scratch, copy);
                  add(copy);
                }
          },
          1);
    }

    /// The phase of base/phase_times.h an assembly of @p derivatives is
    /// charged to.
    phase_times::Phase
    assembly_phase(const Derivatives derivatives)
    {
      switch (derivatives)
        {
          case Derivatives::hessian:
            return phase_times::Phase::hessian_assembly;
          case Derivatives::gradient:
            return phase_times::Phase::gradient_assembly;
          default:
            return phase_times::Phase::energy_assembly;
        }
    }
  } // namespace

  void
  RodModel::assemble_family(
    const unsigned int                                    f,
    const StencilState                                   &state,
    const Derivatives                                     derivatives,
    const std::function<void(const LocalContribution &)> &copier,
    const StencilBlocks                                  *blocks,
    double                                               &energy) const
  {
    // Kernels throw, e.g., where a tangent flipped; the first exception is
    // rethrown after the loop so that the caller can cut the step.
    std::exception_ptr failure;
    std::mutex         failure_mutex;
    // On several processes the stencils this process anchors.
    const ElementFamily &family = *families[f];
    const OwnedStencils *subset =
      own_stencils.empty() ? nullptr : &own_stencils[f];
    const unsigned int n =
      subset != nullptr ? subset->stencils.size() : family.n_stencils();
    // Each stencil's energy in its own slot, summed in order afterwards:
    // the same sum with one thread or several.
    std::vector<double> energies(n, 0.0);
    const auto          worker =
      [&](const unsigned int k, NoAssemblyScratch &, LocalContribution &copy) {
        const unsigned int s = subset != nullptr ? subset->stencils[k] : k;
        copy.dofs.clear();
        copy.energy  = 0;
        copy.family  = f;
        copy.stencil = s;
        try
          {
            family.evaluate(s, state, derivatives, copy);
            if (derivatives != Derivatives::energy)
              family.get_dofs(s, copy.dofs);
          }
        catch (...)
          {
            copy.dofs.clear();
            std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure)
              failure = std::current_exception();
          }
        energies[k] = copy.energy;
      };
    const auto add = [&](const LocalContribution &copy) {
      if (!copy.dofs.empty())
        copier(copy);
    };
    if (blocks != nullptr && subset == nullptr)
      run_in_colors(*blocks, worker, add);
    else
      dealii::WorkStream::run(0u,
                              n,
                              worker,
                              add,
                              NoAssemblyScratch(),
                              LocalContribution());
    if (failure)
      std::rethrow_exception(failure);
    energy = std::accumulate(energies.begin(), energies.end(), energy);
  }


  double
  RodModel::assemble_families(
    const VectorType                                     &u,
    const double                                          load_factor,
    const Derivatives                                     derivatives,
    const std::function<void(const LocalContribution &)> &copier,
    const bool concurrent_copier) const
  {
    follow_natural_shape(load_factor);
    // One thread: the serial loop (stencil order, as always). Several:
    // colors one after the other, the blocks of a color in parallel,
    // copier included (a color's blocks share no row).
    const bool in_colors = concurrent_copier &&
                           dealii::MultithreadInfo::n_threads() > 1 &&
                           stencil_blocks.size() == families.size();
    const StencilState state{values_of(u),
                             *configuration_,
                             history,
                             step_length,
                             applied_load_factor(load_factor)};
    double             energy = 0;
    for (unsigned int f = 0; f < families.size(); ++f)
      assemble_family(f,
                      state,
                      derivatives,
                      copier,
                      in_colors && !stencil_blocks[f].empty() ?
                        &stencil_blocks[f] :
                        nullptr,
                      energy);
    return energy;
  }


  double
  RodModel::work(const VectorType &force, const VectorType &u)
  {
    if (!EveryEntry::distributed(force) || EveryEntry::distributed(u))
      return force * u;
    // A state with every entry (a replica) against a distributed force.
    double here = 0;
    for (const global_dof_index i : force.locally_owned_elements())
      here += force[i] * u[i];
    return dealii::Utilities::MPI::sum(here, force.get_mpi_communicator());
  }


  void
  RodModel::add_dead_loads(const VectorType  &u,
                           const double       ramp,
                           const VectorType  *extra_force,
                           const SystemBlock *block,
                           double            &energy,
                           VectorType        *residual) const
  {
    const double load_factor = applied_load_factor(ramp);
    // Potential -(lambda f + f_held).x, with x = X + u; the constant f.X
    // does not change any derivative and is dropped.
    energy -= load_factor * work(f_ext, u) + work(f_held, u);
    if (extra_force != nullptr)
      energy -= work(*extra_force, u);
    if (residual == nullptr)
      return;
    residual->compress(dealii::VectorOperation::add);
    if (block == nullptr)
      {
        residual->add(-load_factor, f_ext, -1.0, f_held);
        if (extra_force != nullptr)
          residual->add(-1.0, *extra_force);
        return;
      }
    std::vector<global_dof_index> rows;
    std::vector<double>           values;
    for (const global_dof_index i : owned_dofs)
      {
        const double f = load_factor * f_ext[i] + f_held[i] +
                         (extra_force != nullptr ? (*extra_force)[i] : 0.0);
        if (f != 0)
          {
            rows.push_back(block->index(i));
            values.push_back(-f);
          }
      }
    residual->add(rows, values);
    residual->compress(dealii::VectorOperation::add);
  }


  Derivatives
  RodModel::derivatives_for(const VectorType *residual,
                            const MatrixType *tangent)
  {
    return tangent != nullptr  ? Derivatives::hessian :
           residual != nullptr ? Derivatives::gradient :
                                 Derivatives::energy;
  }


  double
  RodModel::assemble_foreign_tangent(const VectorType &u,
                                     const double      load_factor,
                                     VectorType       *residual,
                                     MatrixType       *tangent,
                                     const bool        apply_constraints,
                                     const VectorType *extra_force) const
  {
    if (!own_stencils.empty())
      throw std::invalid_argument(
        "RodModel::assemble: on several processes the tangent must be "
        "a matrix of the model's pattern (initialize_matrix())");
    if (tangent != nullptr)
      *tangent = 0;
    return assemble_mapped(u,
                           load_factor,
                           SystemBlock::at_offset(layout_->n_dofs(), 0),
                           residual,
                           tangent,
                           apply_constraints,
                           extra_force);
  }


  double
  RodModel::assemble(const VectorType &u,
                     const double      load_factor,
                     VectorType       *residual,
                     MatrixType       *tangent,
                     const bool        apply_constraints,
                     const VectorType *extra_force) const
  {
    const phase_times::Scope phase(
      assembly_phase(derivatives_for(residual, tangent)));
    if (residual != nullptr)
      *residual = 0;
    const DirectScatter::Numbering numbering   = scatter_numbering();
    const bool                     distributed = !own_stencils.empty();
    if (!DirectScatter::applies(tangent, numbering))
      return assemble_foreign_tangent(u,
                                      load_factor,
                                      residual,
                                      tangent,
                                      apply_constraints,
                                      extra_force);

    const std::vector<bool> *fixed =
      apply_constraints ? &fixed_dof_mask : nullptr;
    const DirectScatter scatter(
      tangent,
      residual,
      fixed,
      tangent == nullptr ? nullptr :
                           DirectScatter::positions_for(*scatter_positions,
                                                        families,
                                                        *tangent,
                                                        fixed,
                                                        numbering),
      numbering);
    scatter.zero_matrix();
    const auto assemble_here = [&] {
      return assemble_families(
        distributed ? with_ghosts(u) : u,
        load_factor,
        derivatives_for(residual, tangent),
        [&](const LocalContribution &copy) { scatter.add(copy); },
        true);
    };
    double energy =
      distributed ? energy_over_processes(assemble_here) : assemble_here();
    // Every process has assembled without failure: the rows of other
    // processes' DoFs go to them.
    scatter.add_foreign_rows();
    add_dead_loads(u, load_factor, extra_force, nullptr, energy, residual);
    if (residual != nullptr && apply_constraints)
      homogeneous_constraints.set_zero(*residual);
    if (tangent != nullptr)
      {
        scatter.finish();
        const phase_times::Scope phase(phase_times::Phase::exchange);
        tangent->compress(dealii::VectorOperation::add);
      }
    return energy;
  }


  double
  RodModel::assemble_into(const VectorType  &u,
                          const double       load_factor,
                          const SystemBlock &block,
                          VectorType        *residual,
                          MatrixType        *tangent,
                          const bool         apply_constraints) const
  {
    if (!own_stencils.empty())
      throw std::invalid_argument(
        "RodModel::assemble_into: a model on several processes assembles "
        "into its own system only (assemble()); coupled systems on several "
        "processes are not there yet");
    if (block.size() != layout_->n_dofs())
      throw std::invalid_argument(
        "RodModel::assemble_into: the system block places " +
        std::to_string(block.size()) + " DoFs, the model has " +
        std::to_string(layout_->n_dofs()));
    return assemble_mapped(u,
                           load_factor,
                           block,
                           residual,
                           tangent,
                           apply_constraints,
                           nullptr);
  }


  void
  RodModel::add_unseen_diagonal(const std::vector<double> &diagonal,
                                const SystemBlock         &block,
                                MatrixType                &tangent) const
  {
    // Constrained DoFs that no stencil sees (junction copies, the twist of
    // a one-segment rod) get the mean diagonal of the free DoFs, so that
    // their Newton increment is zero at the scale of the others.
    double       sum    = 0;
    unsigned int n_free = 0;
    for (global_dof_index i = 0; i < diagonal.size(); ++i)
      if (!fixed_dof_mask[i])
        {
          sum += std::abs(diagonal[i]);
          ++n_free;
        }
    for (const global_dof_index i : unseen_dofs)
      if (fixed_dof_mask[i])
        tangent.add(block.index(i),
                    block.index(i),
                    n_free > 0 ? sum / n_free : 1.0);
  }


  double
  RodModel::assemble_mapped(const VectorType  &u,
                            const double       load_factor,
                            const SystemBlock &block,
                            VectorType        *residual,
                            MatrixType        *tangent,
                            const bool         apply_constraints,
                            const VectorType  *extra_force) const
  {
    // deal.II's way: the model's constraints renamed to the block's rows
    // eliminate the fixed DoFs as every local contribution is added.
    const dealii::AffineConstraints<double> constraints =
      block.map(apply_constraints ? homogeneous_constraints : no_constraints);
    std::vector<double>           diagonal(layout_->n_dofs(), 0.0);
    std::vector<global_dof_index> rows;
    double                        energy = assemble_families(
      u,
      load_factor,
      derivatives_for(residual, tangent),
      [&](const LocalContribution &copy) {
        rows = copy.dofs;
        block.map(rows);
        if (tangent != nullptr)
          for (unsigned int i = 0; i < copy.dofs.size(); ++i)
            diagonal[copy.dofs[i]] += copy.matrix(i, i);
        if (tangent != nullptr && residual != nullptr)
          constraints.distribute_local_to_global(copy.matrix,
                                                 copy.vector,
                                                 rows,
                                                 *tangent,
                                                 *residual);
        else if (tangent != nullptr)
          constraints.distribute_local_to_global(copy.matrix, rows, *tangent);
        else
          constraints.distribute_local_to_global(copy.vector, rows, *residual);
      });

    if (tangent != nullptr && apply_constraints)
      add_unseen_diagonal(diagonal, block, *tangent);
    add_dead_loads(u, load_factor, extra_force, &block, energy, residual);
    if (residual != nullptr)
      constraints.set_zero(*residual);
    if (tangent != nullptr)
      tangent->compress(dealii::VectorOperation::add);
    return energy;
  }


  double
  RodModel::elastic_energy(const VectorType &u, const double load_factor) const
  {
    // The natural shape at the load factor, the loads off: the families'
    // energy at a stencil load factor 0 (no applied-moment potential, even
    // for fixed loads) and without add_dead_loads().
    const phase_times::Scope phase(phase_times::Phase::energy_assembly);
    follow_natural_shape(load_factor);
    const StencilState state{values_of(own_stencils.empty() ? u :
                                                              with_ghosts(u)),
                             *configuration_,
                             history,
                             step_length,
                             0.0};
    double             energy = 0;
    for (unsigned int f = 0; f < families.size(); ++f)
      assemble_family(
        f,
        state,
        Derivatives::energy,
        [](const LocalContribution &) {},
        nullptr,
        energy);
    return own_stencils.empty() ?
             energy :
             dealii::Utilities::MPI::sum(energy, mpi_communicator);
  }
} // namespace rodnet
