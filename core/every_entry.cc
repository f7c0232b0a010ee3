#include <deal.II/base/mpi.h>

#include <core/every_entry.h>

namespace rodnet
{
  bool
  EveryEntry::distributed(const dealii::TrilinosWrappers::MPI::Vector &vector)
  {
    // The map of a ghosted vector counts its ghost entries too.
    return static_cast<dealii::types::global_dof_index>(
             vector.trilinos_vector().Map().NumMyElements()) < vector.size();
  }


  EveryEntry::EveryEntry(const dealii::TrilinosWrappers::MPI::Vector &vector)
      : entries(&vector)
  {
    if (!distributed(vector))
      return;
    const dealii::IndexSet every_entry =
      dealii::complete_index_set(vector.size());
    dealii::TrilinosWrappers::MPI::Vector with_every_ghost(
      vector.locally_owned_elements(),
      every_entry,
      vector.get_mpi_communicator());
    with_every_ghost = vector;
    gathered.emplace(every_entry, MPI_COMM_SELF);
    for (dealii::types::global_dof_index i = 0; i < vector.size(); ++i)
      (*gathered)[i] = with_every_ghost[i];
    gathered->compress(dealii::VectorOperation::insert);
    entries = &*gathered;
  }
} // namespace rodnet
