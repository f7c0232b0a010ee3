#ifndef RODNET_SOLVERS_NEWTON_HOST_GATHER_H
#define RODNET_SOLVERS_NEWTON_HOST_GATHER_H

#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Map.h>
#include <mpi.h>
#include <vector>

namespace rodnet
{
  /**
   * The values of a vector distributed over the processes of a
   * communicator, each owning the rows a map gives it, gathered onto the
   * host (rank 0) in global order, and scattered back: the right-hand
   * sides and solutions of a direct solver that takes them centralized
   * (MumpsFactorization). Any ownership works, contiguous or not: the host
   * keeps where each process's rows go.
   */
  class HostGather
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// For vectors whose rows are owned as @p map says, over
    /// @p communicator (@p map's). Collective.
    HostGather(const Epetra_Map &map, MPI_Comm communicator);

    /// Whether this process is the host, which holds the gathered values.
    bool
    is_host() const;

    /// Writes @p v's values into column @p column of @p columns on the host
    /// (n rows a column, @p columns grown there as needed); elsewhere
    /// @p columns stays as it is. Collective; std::invalid_argument on
    /// every process where @p v's rows are not owned as the map's are.
    void
    gather(const VectorType    &v,
           std::vector<double> &columns,
           unsigned int         column) const;

    /// Writes column @p column of the host's @p columns into the rows of
    /// @p v that this process owns (@p v owned as the map is). Collective.
    void
    scatter(const std::vector<double> &columns,
            unsigned int               column,
            VectorType                &v) const;

  private:
    /// Throws std::invalid_argument on every process unless @p v is owned
    /// as the map is on every process.
    void
    check_ownership(const VectorType &v) const;

    MPI_Comm communicator;
    bool     host;
    /// The global indices of this process's rows, in the map's order.
    std::vector<int> own_rows;
    /// The host's: how many rows each process owns, where its rows start
    /// in the gathered order, and each gathered row's global index.
    std::vector<int> counts, starts, global_rows;
    /// The host's gathered values, in the processes' order.
    mutable std::vector<double> buffer;
  };
} // namespace rodnet

#endif
