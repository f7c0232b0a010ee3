#include <deal.II/base/mpi.h>

#include <solvers/newton/host_gather.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace rodnet
{
  HostGather::HostGather(const Epetra_Map &map, const MPI_Comm communicator)
      : communicator(communicator)
      , host(dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      , own_rows(map.MyGlobalElements(),
                 map.MyGlobalElements() + map.NumMyElements())
  {
    const int n_own = own_rows.size();
    if (host)
      counts.resize(dealii::Utilities::MPI::n_mpi_processes(communicator));
    MPI_Gather(&n_own, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, communicator);
    if (host)
      {
        starts.resize(counts.size());
        std::exclusive_scan(counts.begin(), counts.end(), starts.begin(), 0);
        global_rows.resize(starts.back() + counts.back());
        buffer.resize(global_rows.size());
      }
    MPI_Gatherv(own_rows.data(),
                n_own,
                MPI_INT,
                global_rows.data(),
                counts.data(),
                starts.data(),
                MPI_INT,
                0,
                communicator);
  }


  bool
  HostGather::is_host() const
  {
    return host;
  }


  void
  HostGather::check_ownership(const VectorType &v) const
  {
    const Epetra_BlockMap &owned = v.trilinos_vector().Map();
    const bool             same =
      owned.NumMyElements() == int(own_rows.size()) &&
      std::equal(own_rows.begin(), own_rows.end(), owned.MyGlobalElements());
    if (dealii::Utilities::MPI::logical_or(!same, communicator))
      throw std::invalid_argument(
        "a vector given to the direct solver is not distributed over the "
        "processes as the tangent's rows are");
  }


  void
  HostGather::gather(const VectorType    &v,
                     std::vector<double> &columns,
                     const unsigned int   column) const
  {
    check_ownership(v);
    MPI_Gatherv(v.trilinos_vector()[0],
                own_rows.size(),
                MPI_DOUBLE,
                buffer.data(),
                counts.data(),
                starts.data(),
                MPI_DOUBLE,
                0,
                communicator);
    if (!host)
      return;
    const std::size_t n = global_rows.size();
    columns.resize(std::max(columns.size(), (column + 1) * n));
    double *to = columns.data() + column * n;
    for (std::size_t k = 0; k < n; ++k)
      to[global_rows[k]] = buffer[k];
  }


  void
  HostGather::scatter(const std::vector<double> &columns,
                      const unsigned int         column,
                      VectorType                &v) const
  {
    if (host)
      {
        const double *from = columns.data() + column * global_rows.size();
        for (std::size_t k = 0; k < global_rows.size(); ++k)
          buffer[k] = from[global_rows[k]];
      }
    MPI_Scatterv(buffer.data(),
                 counts.data(),
                 starts.data(),
                 MPI_DOUBLE,
                 v.trilinos_vector()[0],
                 own_rows.size(),
                 MPI_DOUBLE,
                 0,
                 communicator);
  }
} // namespace rodnet
