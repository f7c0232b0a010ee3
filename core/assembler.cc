// Assembly of the total potential energy of a RodModel, its gradient and
// its Hessian: for every stencil, element kernel (strains and their
// derivatives) -> material (energy, stress, tangent) -> chain rule ->
// constraints -> global Trilinos objects.
#include <deal.II/base/work_stream.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <core/rod_model.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
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
      /// Whether the fast path applies to @p matrix (or to vectors alone).
      static bool
      applies(const MatrixType *matrix)
      {
        if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 1)
          return false;
        if (matrix == nullptr)
          return true;
        const Epetra_CrsMatrix &m = matrix->trilinos_matrix();
        if (!(m.RowMap().LinearMap() && m.ColMap().LinearMap() &&
              m.ColMap().MinMyGID() == 0 && m.RowMap().MinMyGID() == 0 &&
              m.ColMap().NumMyElements() == m.RowMap().NumMyElements()))
          return false;
        // Epetra sorts the column indices of each row when the matrix is
        // filled; the merge in add() relies on it, so check (as cheap as
        // zeroing the matrix).
        for (int row = 0; row < m.NumMyRows(); ++row)
          {
            int     length;
            double *row_values;
            int    *columns;
            m.ExtractMyRowView(row, length, row_values, columns);
            if (!std::is_sorted(columns, columns + length))
              return false;
          }
        return true;
      }

      DirectScatter(MatrixType              *matrix,
                    VectorType              *vector,
                    const std::vector<bool> *fixed)
          : matrix(matrix == nullptr ?
                     nullptr :
                     &const_cast<Epetra_CrsMatrix &>(matrix->trilinos_matrix()))
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
        // (insertion sort: stencils are small, of any size).
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
            int     length;
            double *row_values;
            int    *columns;
            matrix->ExtractMyRowView(row, length, row_values, columns);
            int k = 0;
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
        int     length;
        double *row_values;
        int    *columns;
        matrix->ExtractMyRowView(row, length, row_values, columns);
        return row_values[std::lower_bound(columns, columns + length, row) -
                          columns];
      }

      Epetra_CrsMatrix        *matrix;
      double                  *values;
      const std::vector<bool> *fixed;
      /// Scratch of add(), which the (serial) copier calls.
      mutable std::vector<unsigned int> order;
    };
  } // namespace

  void
  RodModel::assemble_family(const ElementFamily &family,
                            const StencilState  &state,
                            const Derivatives    derivatives,
                            const std::function<void(const LocalContribution &)>
                              &copier) const
  {
    // Kernels throw, e.g., where a tangent flipped; the first exception is
    // rethrown after the loop so that the caller can cut the step.
    std::exception_ptr failure;
    std::mutex         failure_mutex;
    struct NoScratch
    {};
    dealii::WorkStream::run(
      0u,
      family.n_stencils(),
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
      },
      copier,
      NoScratch(),
      LocalContribution());
    if (failure)
      std::rethrow_exception(failure);
  }


  double
  RodModel::assemble(const VectorType &u,
                     const double      load_factor,
                     VectorType       *residual,
                     MatrixType       *tangent,
                     const bool        apply_constraints,
                     const VectorType *extra_force) const
  {
    const dealii::AffineConstraints<double> &constraints =
      apply_constraints ? homogeneous_constraints : no_constraints;
    if (residual != nullptr)
      *residual = 0;
    if (tangent != nullptr)
      *tangent = 0;
    const Derivatives derivatives =
      tangent != nullptr  ? Derivatives::hessian :
      residual != nullptr ? Derivatives::gradient :
                            Derivatives::energy;

    double              energy = 0;
    const bool          direct = DirectScatter::applies(tangent);
    const DirectScatter scatter(tangent,
                                residual,
                                apply_constraints ? &fixed_dof_mask : nullptr);
    const std::function<void(const LocalContribution &)> copier =
      [&](const LocalContribution &copy) {
        energy += copy.energy;
        if (copy.dofs.empty())
          return;
        if (direct)
          scatter.add(copy);
        else if (tangent != nullptr && residual != nullptr)
          constraints.distribute_local_to_global(
            copy.matrix, copy.vector, copy.dofs, *tangent, *residual);
        else if (tangent != nullptr)
          constraints.distribute_local_to_global(copy.matrix,
                                                 copy.dofs,
                                                 *tangent);
        else
          constraints.distribute_local_to_global(copy.vector,
                                                 copy.dofs,
                                                 *residual);
      };

    const StencilState state{
      u, *configuration_, history, step_length, load_factor};
    for (const auto &family : families)
      assemble_family(*family, state, derivatives, copier);

    // Unused DoFs of rod ends at junctions appear in no stencil; outside
    // the direct path, give their (constrained) rows a diagonal entry.
    if (!direct && tangent != nullptr && apply_constraints)
      for (const auto &unused : layout_->shared_copies())
        {
          LocalContribution copy;
          copy.matrix.reinit(1, 1);
          copy.matrix(0, 0) = 1.0;
          copy.vector.reinit(1);
          copy.dofs = {unused.first};
          copier(copy);
        }

    // Dead loads: potential -lambda f.x, with x = X + u; the constant
    // f.X does not change any derivative and is dropped.
    energy -= load_factor * (f_ext * u);
    if (extra_force != nullptr)
      energy -= *extra_force * u;
    if (residual != nullptr)
      {
        residual->compress(dealii::VectorOperation::add);
        residual->add(-load_factor, f_ext);
        if (extra_force != nullptr)
          residual->add(-1.0, *extra_force);
        constraints.set_zero(*residual);
      }
    if (tangent != nullptr)
      {
        if (direct)
          scatter.finish();
        tangent->compress(dealii::VectorOperation::add);
      }
    return energy;
  }

  double
  RodModel::elastic_energy(const VectorType &u) const
  {
    return assemble(u, 0.0, nullptr, nullptr);
  }
} // namespace rodnet
