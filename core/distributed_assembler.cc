// Assembly of a RodModel whose DoFs are distributed over several
// processes: every process holds the whole network, evaluates the stencils
// that couple its own DoFs (own_stencils) at the state with its ghost
// entries, and adds the rows of its own DoFs only.
#include <base/first_problem.h>
#include <core/rod_model.h>

#include <Epetra_CrsMatrix.h>
#include <cmath>
#include <exception>

namespace rodnet
{
  namespace
  {
    /**
     * Adds local contributions into the rows a process owns, leaving out
     * the rows and columns of fixed DoFs (as the direct scatter of one
     * process does, whose results it reproduces up to the order of the
     * additions); the rows of other processes are theirs to add. No entry
     * crosses processes, so the matrix needs no off-process rows.
     */
    class OwnedRowsScatter
    {
    public:
      OwnedRowsScatter(MatrixType              *matrix,
                       VectorType              *vector,
                       const std::vector<bool> *fixed,
                       const dealii::IndexSet  &owned,
                       const MPI_Comm           communicator)
          : matrix(matrix)
          , vector(vector)
          , fixed(fixed)
          , owned(owned)
          , communicator(communicator)
      {
      }

      void
      add(const LocalContribution &copy)
      {
        const unsigned int n = copy.dofs.size();
        columns.clear();
        column_places.clear();
        for (unsigned int j = 0; j < n; ++j)
          if (!is_fixed(copy.dofs[j]))
            {
              columns.push_back(copy.dofs[j]);
              column_places.push_back(j);
            }
        for (unsigned int i = 0; i < n; ++i)
          {
            const global_dof_index row = copy.dofs[i];
            if (!owned.is_element(row) || is_fixed(row))
              continue;
            if (vector != nullptr)
              (*vector)(row) += copy.vector[i];
            if (matrix == nullptr)
              continue;
            row_values.resize(columns.size());
            for (unsigned int k = 0; k < columns.size(); ++k)
              row_values[k] = copy.matrix(i, column_places[k]);
            // Epetra's own addition into a row of this process: deal.II's
            // add() would copy the row and check for rows of others. (The
            // wrapper hands out its Epetra matrix as const only.)
            const_cast<Epetra_CrsMatrix &>(matrix->trilinos_matrix())
              .SumIntoGlobalValues(static_cast<int>(row),
                                   static_cast<int>(columns.size()),
                                   row_values.data(),
                                   columns.data());
          }
      }

      /// Compresses the matrix and puts the mean free diagonal (over all
      /// processes) on the rows of fixed DoFs, so that the Newton increment
      /// is zero there and the scale matches.
      void
      finish() const
      {
        if (matrix == nullptr)
          return;
        matrix->compress(dealii::VectorOperation::add);
        if (fixed == nullptr)
          return;
        double       sum    = 0;
        unsigned int n_free = 0;
        for (const global_dof_index row : owned)
          if (!(*fixed)[row])
            {
              sum += std::abs(matrix->diag_element(row));
              ++n_free;
            }
        sum                = dealii::Utilities::MPI::sum(sum, communicator);
        n_free             = dealii::Utilities::MPI::sum(n_free, communicator);
        const double value = n_free > 0 ? sum / n_free : 1.0;
        for (const global_dof_index row : owned)
          if ((*fixed)[row])
            matrix->set(row, row, value);
        matrix->compress(dealii::VectorOperation::insert);
      }

    private:
      bool
      is_fixed(const global_dof_index dof) const
      {
        return fixed != nullptr && (*fixed)[dof];
      }

      MatrixType               *matrix;
      VectorType               *vector;
      const std::vector<bool>  *fixed;
      const dealii::IndexSet   &owned;
      const MPI_Comm            communicator;
      std::vector<int>          columns;
      std::vector<unsigned int> column_places;
      std::vector<double>       row_values;
    };
  } // namespace


  const VectorType &
  RodModel::with_ghosts(const VectorType &u) const
  {
    ghosted_state = u;
    return ghosted_state;
  }


  double
  RodModel::energy_over_processes(
    const std::function<double()> &assemble_here) const
  {
    double      energy = 0;
    std::string failure;
    try
      {
        energy = assemble_here();
      }
    catch (const std::exception &e)
      {
        failure = e.what();
      }
    // A stencil that failed on one process fails the assembly on all.
    failure = first_problem(failure, mpi_communicator);
    if (!failure.empty())
      throw std::runtime_error(failure);
    return dealii::Utilities::MPI::sum(energy, mpi_communicator);
  }


  DirectScatter::Numbering
  RodModel::scatter_numbering() const
  {
    DirectScatter::Numbering numbering;
    numbering.first =
      owned_dofs.n_elements() > 0 ? owned_dofs.nth_index_in_set(0) : 0;
    numbering.n_owned      = owned_dofs.n_elements();
    numbering.communicator = mpi_communicator;
    if (!own_stencils.empty())
      {
        numbering.column_map   = &sparsity.trilinos_sparsity_pattern().ColMap();
        numbering.local_column = &local_columns;
      }
    return numbering;
  }


  VectorType
  RodModel::replica(const VectorType &u) const
  {
    const dealii::IndexSet every_dof =
      dealii::complete_index_set(layout_->n_dofs());
    VectorType with_every_ghost(owned_dofs, every_dof, mpi_communicator);
    with_every_ghost = u;
    VectorType result(every_dof, MPI_COMM_SELF);
    for (global_dof_index i = 0; i < every_dof.size(); ++i)
      result[i] = with_every_ghost[i];
    result.compress(dealii::VectorOperation::insert);
    return result;
  }


  double
  RodModel::assemble_distributed(const VectorType &u,
                                 const double      load_factor,
                                 VectorType       *residual,
                                 MatrixType       *tangent,
                                 const bool        apply_constraints,
                                 const VectorType *extra_force) const
  {
    if (tangent != nullptr)
      *tangent = 0;
    OwnedRowsScatter scatter(tangent,
                             residual,
                             apply_constraints ? &fixed_dof_mask : nullptr,
                             owned_dofs,
                             mpi_communicator);
    double           energy = energy_over_processes([&] {
      return assemble_families(with_ghosts(u),
                               load_factor,
                               derivatives_for(residual, tangent),
                               [&](const LocalContribution &copy) {
                                 scatter.add(copy);
                               });
    });
    add_dead_loads(u, load_factor, extra_force, nullptr, energy, residual);
    if (residual != nullptr && apply_constraints)
      homogeneous_constraints.set_zero(*residual);
    scatter.finish();
    return energy;
  }
} // namespace rodnet
