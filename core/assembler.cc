// Assembly of the total potential energy of a RodModel, its gradient and
// its Hessian: for every stencil, element kernel (strains and their
// derivatives) -> material (energy, stress, tangent) -> chain rule ->
// constraints -> global Trilinos objects.
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <core/rod_model.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <mutex>

namespace rodnet
{
  namespace
  {
    /**
     * Adds local contributions straight into the compressed rows of the
     * Trilinos matrix and the vector's storage. Valid on one process, where
     * row and column maps are the identity, for constraints that only fix
     * DoFs (rows and columns of fixed DoFs are skipped; their diagonal is
     * set by finish()). It replaces AffineConstraints::
     * distribute_local_to_global, whose per-entry global-to-local lookups
     * and searches cost more than the kernels (see doc/performance.md).
     */
    class DirectScatter
    {
    public:
      /// Whether the fast path applies to @p matrix (or to vectors alone) of
      /// a model on @p communicator.
      static bool
      applies(const MatrixType *matrix, const MPI_Comm communicator)
      {
        if (dealii::Utilities::MPI::n_mpi_processes(communicator) != 1)
          return false;
        if (matrix == nullptr)
          return true;
        const Epetra_CrsMatrix &m = matrix->trilinos_matrix();
        if (!(m.RowMap().LinearMap() && m.ColMap().LinearMap() &&
              m.ColMap().MinMyGID() == 0 && m.RowMap().MinMyGID() == 0 &&
              m.ColMap().NumMyElements() == m.RowMap().NumMyElements()))
          return false;
        // add() reads the compressed rows straight from Epetra's arrays,
        // which exist once the storage is optimized (as FillComplete
        // leaves it). Epetra sorts the column indices of each row when the
        // matrix is filled; the merge in add() relies on it, so check (as
        // cheap as zeroing the matrix).
        const CsrArrays csr(m);
        if (csr.offsets == nullptr)
          return false;
        for (int row = 0; row < m.NumMyRows(); ++row)
          if (!std::is_sorted(csr.columns + csr.offsets[row],
                              csr.columns + csr.offsets[row + 1]))
            return false;
        return true;
      }

      DirectScatter(MatrixType              *matrix,
                    VectorType              *vector,
                    const std::vector<bool> *fixed)
          : matrix(matrix == nullptr ?
                     nullptr :
                     &const_cast<Epetra_CrsMatrix &>(matrix->trilinos_matrix()))
          , csr(this->matrix)
          , values(vector == nullptr ? nullptr : vector->trilinos_vector()[0])
          , fixed(fixed)
      {
      }

      void
      add(const LocalContribution &copy) const
      {
        const unsigned int n = copy.dofs.size();
        // The stencil's DoFs in increasing order, so that each row is
        // merged with the sorted column indices of the matrix in one pass
        // (insertion sort: stencils are small, of any size). Scratch of
        // each thread: copiers of one color run at the same time.
        thread_local std::vector<unsigned int> order;
        order.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            unsigned int k = i;
            for (; k > 0 && copy.dofs[order[k - 1]] > copy.dofs[i]; --k)
              order[k] = order[k - 1];
            order[k] = i;
          }
        for (unsigned int a = 0; a < n; ++a)
          {
            const unsigned int i   = order[a];
            const int          row = copy.dofs[i];
            if (is_fixed(row))
              continue;
            if (values != nullptr)
              values[row] += copy.vector[i];
            if (matrix == nullptr)
              continue;
            double    *row_values = csr.values + csr.offsets[row];
            const int *columns    = csr.columns + csr.offsets[row];
            int        k          = 0;
            for (unsigned int b = 0; b < n; ++b)
              {
                const unsigned int j   = order[b];
                const int          col = copy.dofs[j];
                if (is_fixed(col))
                  continue;
                while (columns[k] < col)
                  ++k;
                row_values[k] += copy.matrix(i, j);
              }
          }
      }

      /// Puts the mean free diagonal on the rows of fixed DoFs, so that
      /// the Newton increment is zero there and the scale matches.
      void
      finish() const
      {
        if (matrix == nullptr || fixed == nullptr)
          return;
        double       sum    = 0;
        unsigned int n_free = 0;
        for (int row = 0; row < matrix->NumMyRows(); ++row)
          if (!(*fixed)[row])
            {
              sum += std::abs(diagonal(row));
              ++n_free;
            }
        const double value = n_free > 0 ? sum / n_free : 1.0;
        for (int row = 0; row < matrix->NumMyRows(); ++row)
          if ((*fixed)[row])
            diagonal(row) = value;
      }

    private:
      bool
      is_fixed(const int dof) const
      {
        return fixed != nullptr && (*fixed)[dof];
      }

      double &
      diagonal(const int row) const
      {
        const int *begin = csr.columns + csr.offsets[row];
        const int *end   = csr.columns + csr.offsets[row + 1];
        return csr.values[std::lower_bound(begin, end, row) - csr.columns];
      }

      /// Epetra's compressed rows of an optimized matrix: row r holds the
      /// columns and values [offsets[r], offsets[r + 1]); all null if the
      /// storage is not optimized (or there is no matrix).
      struct CsrArrays
      {
        explicit CsrArrays(const Epetra_CrsMatrix *m)
        {
          // Sets all three to null where the storage is not optimized.
          if (m != nullptr)
            m->ExtractCrsDataPointers(offsets, columns, values);
        }
        explicit CsrArrays(const Epetra_CrsMatrix &m)
            : CsrArrays(&m)
        {
        }
        int    *offsets = nullptr;
        int    *columns = nullptr;
        double *values  = nullptr;
      };

      Epetra_CrsMatrix        *matrix;
      CsrArrays                csr;
      double                  *values;
      const std::vector<bool> *fixed;
    };
  } // namespace

  void
  RodModel::assemble_family(
    const ElementFamily                                  &family,
    const StencilState                                   &state,
    const Derivatives                                     derivatives,
    const std::function<void(const LocalContribution &)> &copier,
    const std::vector<std::vector<unsigned int>>         *colors,
    double                                               &energy) const
  {
    // Kernels throw, e.g., where a tangent flipped; the first exception is
    // rethrown after the loop so that the caller can cut the step.
    std::exception_ptr failure;
    std::mutex         failure_mutex;
    // Each stencil's energy in its own slot, summed in order afterwards:
    // the same sum with one thread or several.
    std::vector<double> energies(family.n_stencils(), 0.0);
    struct NoScratch
    {
    };
    const auto worker =
      [&](const unsigned int s, NoScratch &, LocalContribution &copy) {
        copy.dofs.clear();
        copy.energy = 0;
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
        energies[s] = copy.energy;
      };
    const auto add = [&](const LocalContribution &copy) {
      if (!copy.dofs.empty())
        copier(copy);
    };
    if (colors != nullptr)
      dealii::WorkStream::run(*colors,
                              worker,
                              add,
                              NoScratch(),
                              LocalContribution());
    else
      dealii::WorkStream::run(0u,
                              family.n_stencils(),
                              worker,
                              add,
                              NoScratch(),
                              LocalContribution());
    if (failure)
      std::rethrow_exception(failure);
    for (const double e : energies)
      energy += e;
  }


  double
  RodModel::assemble_families(
    const VectorType                                     &u,
    const double                                          load_factor,
    const Derivatives                                     derivatives,
    const std::function<void(const LocalContribution &)> &copier,
    const bool concurrent_copier) const
  {
    // One thread: the serial loop (stencil order, as always). Several:
    // colors one after the other, the stencils of a color in parallel,
    // copier included (a color's stencils share no row).
    const bool in_colors = concurrent_copier &&
                           dealii::MultithreadInfo::n_threads() > 1 &&
                           stencil_colors.size() == families.size();
    const StencilState state{u,
                             *configuration_,
                             history,
                             step_length,
                             load_factor};
    double             energy = 0;
    for (unsigned int f = 0; f < families.size(); ++f)
      assemble_family(*families[f],
                      state,
                      derivatives,
                      copier,
                      in_colors && !stencil_colors[f].empty() ?
                        &stencil_colors[f] :
                        nullptr,
                      energy);
    return energy;
  }


  void
  RodModel::add_dead_loads(const VectorType  &u,
                           const double       load_factor,
                           const VectorType  *extra_force,
                           const SystemBlock *block,
                           double            &energy,
                           VectorType        *residual) const
  {
    // Potential -lambda f.x, with x = X + u; the constant f.X does not
    // change any derivative and is dropped.
    energy -= load_factor * (f_ext * u);
    if (extra_force != nullptr)
      energy -= *extra_force * u;
    if (residual == nullptr)
      return;
    residual->compress(dealii::VectorOperation::add);
    if (block == nullptr)
      {
        residual->add(-load_factor, f_ext);
        if (extra_force != nullptr)
          residual->add(-1.0, *extra_force);
        return;
      }
    std::vector<global_dof_index> rows;
    std::vector<double>           values;
    for (const global_dof_index i : owned_dofs)
      {
        const double f = load_factor * f_ext[i] +
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


  namespace
  {
    Derivatives
    derivatives_for(const VectorType *residual, const MatrixType *tangent)
    {
      return tangent != nullptr  ? Derivatives::hessian :
             residual != nullptr ? Derivatives::gradient :
                                   Derivatives::energy;
    }
  } // namespace


  double
  RodModel::assemble(const VectorType &u,
                     const double      load_factor,
                     VectorType       *residual,
                     MatrixType       *tangent,
                     const bool        apply_constraints,
                     const VectorType *extra_force) const
  {
    if (residual != nullptr)
      *residual = 0;
    if (tangent != nullptr)
      *tangent = 0;
    if (!DirectScatter::applies(tangent, mpi_communicator))
      return assemble_mapped(u,
                             load_factor,
                             SystemBlock::at_offset(layout_->n_dofs(), 0),
                             residual,
                             tangent,
                             apply_constraints,
                             extra_force);

    const DirectScatter scatter(tangent,
                                residual,
                                apply_constraints ? &fixed_dof_mask : nullptr);
    double              energy = assemble_families(
      u,
      load_factor,
      derivatives_for(residual, tangent),
      [&](const LocalContribution &copy) { scatter.add(copy); },
      true);
    add_dead_loads(u, load_factor, extra_force, nullptr, energy, residual);
    if (residual != nullptr && apply_constraints)
      homogeneous_constraints.set_zero(*residual);
    if (tangent != nullptr)
      {
        scatter.finish();
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

    // Constrained DoFs that no stencil sees (junction copies, the twist of
    // a one-segment rod) get the mean diagonal of the free DoFs, so that
    // their Newton increment is zero at the scale of the others.
    if (tangent != nullptr && apply_constraints)
      {
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
            tangent->add(block.index(i),
                         block.index(i),
                         n_free > 0 ? sum / n_free : 1.0);
      }
    add_dead_loads(u, load_factor, extra_force, &block, energy, residual);
    if (residual != nullptr)
      constraints.set_zero(*residual);
    if (tangent != nullptr)
      tangent->compress(dealii::VectorOperation::add);
    return energy;
  }


  double
  RodModel::elastic_energy(const VectorType &u) const
  {
    return assemble(u, 0.0, nullptr, nullptr);
  }
} // namespace rodnet
