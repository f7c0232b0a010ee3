// What the assembly of a RodModel whose DoFs are distributed over several
// processes needs besides the direct scatter: every process holds the whole
// network, evaluates the stencils it anchors (own_stencils) at the state
// with its ghost entries (with_ghosts()), adds the rows of its own DoFs and
// sends the others to their owners (ForeignRows); the energies are summed
// over the processes.
#include <base/first_problem.h>
#include <base/phase_times.h>
#include <core/every_entry.h>
#include <core/rod_model.h>

#include <cmath>
#include <exception>

namespace rodnet
{
  const VectorType &
  RodModel::with_ghosts(const VectorType &u) const
  {
    // A state with every entry (a replica) holds the ghosts already.
    if (!EveryEntry::distributed(u))
      return u;
    const phase_times::Scope phase(phase_times::Phase::exchange);
    if (!u.trilinos_vector().Map().SameAs(ghost_import->SourceMap()))
      ghosted_state = u; // another partition: deal.II imports it
    else if (ghosted_state.trilinos_vector().Import(u.trilinos_vector(),
                                                    *ghost_import,
                                                    Insert) != 0)
      throw std::runtime_error("the import of the ghost entries of the "
                               "state failed (Epetra_Import)");
    return ghosted_state;
  }


  DofValues
  RodModel::values_of(const VectorType &u) const
  {
    return &u == &ghosted_state ? DofValues(u, ghost_places) : DofValues(u);
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
    const phase_times::Scope phase(phase_times::Phase::exchange);
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
        numbering.share_starts = &share_starts;
      }
    return numbering;
  }


  VectorType
  RodModel::replica(const VectorType &u) const
  {
    return *EveryEntry(u);
  }
} // namespace rodnet
