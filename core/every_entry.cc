#include <deal.II/base/mpi.h>

#include <core/every_entry.h>

#include <vector>

namespace rodnet
{
  namespace
  {
    /// The entries that each process of @p vector's communicator owns,
    /// each one contiguous range: the first and the number, per process;
    /// empty where one process's are not contiguous.
    std::vector<std::pair<int, int>>
    contiguous_ranges(const dealii::TrilinosWrappers::MPI::Vector &vector)
    {
      const dealii::IndexSet owned = vector.locally_owned_elements();
      const bool             plain =
        owned.is_contiguous() &&
        owned.n_elements() == static_cast<dealii::types::global_dof_index>(
                                vector.trilinos_vector().MyLength());
      const std::pair<int, int> mine(owned.n_elements() > 0 ?
                                       int(owned.nth_index_in_set(0)) :
                                       0,
                                     int(owned.n_elements()));
      const MPI_Comm communicator = vector.get_mpi_communicator();
      // Every process takes the same path.
      if (dealii::Utilities::MPI::min(plain ? 1 : 0, communicator) == 0)
        return {};
      return dealii::Utilities::MPI::all_gather(communicator, mine);
    }

    /// Gathers the entries of @p vector (without ghosts) into @p replica
    /// in one collective where every process owns one contiguous range (a
    /// model's share): no index lookups, no import to build. Returns
    /// whether it could.
    bool
    gather_contiguous(const dealii::TrilinosWrappers::MPI::Vector &vector,
                      double *const                                replica)
    {
      const std::vector<std::pair<int, int>> ranges = contiguous_ranges(vector);
      if (ranges.empty())
        return false;
      std::vector<int> counts, starts;
      for (const auto &[first, n] : ranges)
        {
          starts.push_back(first);
          counts.push_back(n);
        }
      const MPI_Comm communicator = vector.get_mpi_communicator();
      const int      error        = MPI_Allgatherv(
        vector.trilinos_vector()[0],
        counts[dealii::Utilities::MPI::this_mpi_process(communicator)],
        MPI_DOUBLE,
        replica,
        counts.data(),
        starts.data(),
        MPI_DOUBLE,
        communicator);
      AssertThrowMPI(error);
      return true;
    }

    /// The entries that this process owns of @p vector, without ghosts.
    dealii::TrilinosWrappers::MPI::Vector
    own_entries(const dealii::TrilinosWrappers::MPI::Vector &vector)
    {
      dealii::TrilinosWrappers::MPI::Vector own(vector.locally_owned_elements(),
                                                vector.get_mpi_communicator());
      for (const auto i : vector.locally_owned_elements())
        own[i] = vector[i];
      own.compress(dealii::VectorOperation::insert);
      return own;
    }
  } // namespace


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
    gathered.emplace(every_entry, MPI_COMM_SELF);
    entries = &*gathered;
    // On a replica on MPI_COMM_SELF, entry i is the i-th local value.
    double *const replica = gathered->trilinos_vector()[0];
    // A vector with ghosts: its own entries first (an import from a map
    // with ghosts would take them from any process).
    const dealii::TrilinosWrappers::MPI::Vector own_only =
      vector.has_ghost_elements() ? own_entries(vector) :
                                    dealii::TrilinosWrappers::MPI::Vector();
    const dealii::TrilinosWrappers::MPI::Vector &source =
      vector.has_ghost_elements() ? own_only : vector;
    if (!gather_contiguous(source, replica))
      {
        dealii::TrilinosWrappers::MPI::Vector with_every_ghost(
          source.locally_owned_elements(),
          every_entry,
          source.get_mpi_communicator());
        with_every_ghost = source;
        for (dealii::types::global_dof_index i = 0; i < source.size(); ++i)
          replica[i] = with_every_ghost[i];
      }
  }
} // namespace rodnet
