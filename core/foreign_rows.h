#ifndef RODNET_CORE_FOREIGN_ROWS_H
#define RODNET_CORE_FOREIGN_ROWS_H

#include <core/element_family.h>

#include <functional>
#include <mpi.h>
#include <vector>

namespace rodnet
{
  /**
   * The rows of other processes' DoFs that the stencils a process evaluates
   * add to, on a model distributed over several processes: each stencil is
   * evaluated once, by the owner of its anchor (stencils_anchored()), which
   * adds its own rows directly and keeps the others here; exchange() sends
   * them to their owners, which add them. Rows and columns of fixed DoFs
   * are left out, as the direct scatter leaves them.
   */
  class ForeignRows
  {
  public:
    /// One row received: its DoF, its vector entry and its matrix entries
    /// (n columns and values).
    struct Row
    {
      global_dof_index        dof;
      double                  vector_value;
      unsigned int            n;
      const global_dof_index *columns;
      const double           *values;
    };

    /// @p share_starts: the first DoF of the share of every process of
    /// @p communicator, in rank order, then the number of DoFs.
    ForeignRows(const std::vector<global_dof_index> &share_starts,
                MPI_Comm                             communicator);

    /// Keeps the rows of @p copy that another process owns and that
    /// @p fixed does not fix: their matrix entries if @p with_matrix, their
    /// vector entries if @p with_vector.
    void
    keep(const LocalContribution &copy,
         const std::vector<bool> *fixed,
         bool                     with_matrix,
         bool                     with_vector);

    /// Sends the rows kept to their owners and calls @p add on each row
    /// received, in the order of the sending processes; collective.
    void
    exchange(const std::function<void(const Row &)> &add);

  private:
    /// The process that owns @p dof.
    unsigned int
    owner(global_dof_index dof) const;

    const std::vector<global_dof_index> &share_starts;
    MPI_Comm                             communicator;
    unsigned int                         rank;
    /// Per process, the rows for it: DoF, vector entry, n, then n
    /// (column, value) pairs; DoFs in doubles, exact below 2^53.
    std::vector<std::vector<double>> outgoing;
  };
} // namespace rodnet

#endif
