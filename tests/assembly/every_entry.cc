// EveryEntry: a replica of every entry of a Trilinos vector on each
// process, gathered in one collective where every process owns one
// contiguous range (a model's share), and through ghost entries otherwise
// (a vector with ghosts, ownership in strides). The reference is the value
// each entry was given, known to every process. DofValues reads every entry
// a process holds (its share and its ghosts) and refuses one it does not
// hold. Runs on 1, 2 and 3 processes
// (tests/CMakeLists.txt, RODNET_MPI_TESTS).
#include <deal.II/base/mpi.h>

#include <core/dof_values.h>
#include <core/every_entry.h>
#include <core/stencil_ownership.h>

#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;
  using dealii::TrilinosWrappers::MPI::Vector;

  constexpr dealii::types::global_dof_index n_entries = 17;

  /// The value given to entry @p i.
  double
  value(const dealii::types::global_dof_index i)
  {
    return 1.0 + 0.25 * double(i * i);
  }

  /// A vector of @p owned entries (ghosts @p ghosts) holding value().
  Vector
  filled(const dealii::IndexSet &owned, const dealii::IndexSet &ghosts)
  {
    Vector plain(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      plain[i] = value(i);
    plain.compress(dealii::VectorOperation::insert);
    if (ghosts.n_elements() == 0)
      return plain;
    Vector with_ghosts(owned, ghosts, MPI_COMM_WORLD);
    with_ghosts = plain;
    return with_ghosts;
  }

  /// Every entry of the replica of @p vector is value().
  void
  expect_every_value(const Vector &vector, const char *what)
  {
    const EveryEntry every(vector);
    ASSERT_EQ((*every).size(), n_entries) << what;
    for (dealii::types::global_dof_index i = 0; i < n_entries; ++i)
      EXPECT_EQ((*every)[i], value(i)) << what << ", entry " << i;
  }

  /// This process's contiguous share of the entries, and the number of
  /// processes and this one's rank.
  struct Share
  {
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const dealii::IndexSet entries =
      contiguous_share(n_entries, n_processes, rank);
  };

  TEST(EveryEntry, GathersEveryEntryOfAnyPartition)
  {
    const Share            own;
    const dealii::IndexSet none(n_entries);
    expect_every_value(filled(own.entries, none), "contiguous shares");

    dealii::IndexSet ghosts(n_entries);
    ghosts.add_index(0);
    ghosts.add_index(n_entries - 1);
    expect_every_value(filled(own.entries, ghosts), "shares with ghosts");

    dealii::IndexSet strided(n_entries);
    for (dealii::types::global_dof_index i = own.rank; i < n_entries;
         i += own.n_processes)
      strided.add_index(i);
    expect_every_value(filled(strided, none), "ownership in strides");
  }

  TEST(DofValues, ReadsTheShareAndTheGhostsAndRefusesTheRest)
  {
    const dealii::IndexSet share = Share().entries;
    // Ghosts below and above every share but the first's and last's.
    dealii::IndexSet ghosts(n_entries);
    ghosts.add_index(0);
    ghosts.add_index(n_entries - 1);
    const Vector    vector = filled(share, ghosts);
    const DofValues values(vector);
    for (dealii::types::global_dof_index i = 0; i < n_entries; ++i)
      if (share.is_element(i) || ghosts.is_element(i))
        EXPECT_EQ(values[i], value(i)) << "entry " << i;
      else
        EXPECT_THROW(values[i], std::logic_error) << "entry " << i;
  }
} // namespace
