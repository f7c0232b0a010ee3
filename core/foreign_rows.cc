#include <deal.II/base/mpi.h>

#include <core/foreign_rows.h>

#include <algorithm>
#include <numeric>

namespace rodnet
{
  ForeignRows::ForeignRows(const std::vector<global_dof_index> &share_starts,
                           const MPI_Comm                       communicator)
      : share_starts(share_starts)
      , communicator(communicator)
      , rank(dealii::Utilities::MPI::this_mpi_process(communicator))
      , outgoing(share_starts.size() - 1)
  {
  }


  unsigned int
  ForeignRows::owner(const global_dof_index dof) const
  {
    return std::upper_bound(share_starts.begin(), share_starts.end(), dof) -
           share_starts.begin() - 1;
  }


  void
  ForeignRows::keep(const LocalContribution &copy,
                    const std::vector<bool> *fixed,
                    const bool               with_matrix,
                    const bool               with_vector)
  {
    const global_dof_index first    = share_starts[rank];
    const global_dof_index size     = share_starts[rank + 1] - first;
    const auto             is_fixed = [&](const global_dof_index dof) {
      return fixed != nullptr && (*fixed)[dof];
    };
    const unsigned int n = copy.dofs.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const global_dof_index row = copy.dofs[i];
        if (row - first < size || is_fixed(row))
          continue;
        std::vector<double> &out = outgoing[owner(row)];
        out.push_back(double(row));
        out.push_back(with_vector ? copy.vector[i] : 0.0);
        const std::size_t count_at = out.size();
        out.push_back(0);
        if (!with_matrix)
          continue;
        for (unsigned int j = 0; j < n; ++j)
          if (!is_fixed(copy.dofs[j]))
            {
              out.push_back(double(copy.dofs[j]));
              out.push_back(copy.matrix(i, j));
            }
        out[count_at] = double((out.size() - count_at - 1) / 2);
      }
  }


  void
  ForeignRows::exchange(const std::function<void(const Row &)> &add)
  {
    const unsigned int  n_processes = outgoing.size();
    std::vector<int>    send_counts(n_processes), send_starts(n_processes);
    std::vector<double> sent;
    for (unsigned int p = 0; p < n_processes; ++p)
      {
        send_starts[p] = sent.size();
        send_counts[p] = outgoing[p].size();
        sent.insert(sent.end(), outgoing[p].begin(), outgoing[p].end());
        outgoing[p].clear();
      }
    std::vector<int> receive_counts(n_processes), receive_starts(n_processes);
    int              error = MPI_Alltoall(send_counts.data(),
                             1,
                             MPI_INT,
                             receive_counts.data(),
                             1,
                             MPI_INT,
                             communicator);
    AssertThrowMPI(error);
    std::exclusive_scan(receive_counts.begin(),
                        receive_counts.end(),
                        receive_starts.begin(),
                        0);
    std::vector<double> received(receive_starts.back() + receive_counts.back());
    error = MPI_Alltoallv(sent.data(),
                          send_counts.data(),
                          send_starts.data(),
                          MPI_DOUBLE,
                          received.data(),
                          receive_counts.data(),
                          receive_starts.data(),
                          MPI_DOUBLE,
                          communicator);
    AssertThrowMPI(error);
    std::vector<global_dof_index> columns;
    std::vector<double>           values;
    for (std::size_t at = 0; at < received.size();)
      {
        Row row{global_dof_index(received[at]),
                received[at + 1],
                static_cast<unsigned int>(received[at + 2]),
                nullptr,
                nullptr};
        columns.resize(row.n);
        values.resize(row.n);
        for (unsigned int j = 0; j < row.n; ++j)
          {
            columns[j] = global_dof_index(received[at + 3 + 2 * j]);
            values[j]  = received[at + 4 + 2 * j];
          }
        row.columns = columns.data();
        row.values  = values.data();
        add(row);
        at += 3 + 2 * row.n;
      }
  }
} // namespace rodnet
