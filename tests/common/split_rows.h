#ifndef RODNET_TESTS_SPLIT_ROWS_H
#define RODNET_TESTS_SPLIT_ROWS_H

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <Epetra_CrsMatrix.h>
#include <limits>
#include <vector>

// A matrix built whole on every process (on MPI_COMM_SELF), its rows split
// over the processes of MPI_COMM_WORLD: the distributed tangents of
// tests/solvers/mumps_distributed.cc and bench/mumps_processes.cc, before
// there is a distributed model to assemble them.
namespace rodnet::testing
{
  /// The rows of @p n that this process of MPI_COMM_WORLD owns, a
  /// contiguous range: process r of P takes n / P of them where @p even,
  /// (r + 1) / (1 + ... + P) of them otherwise.
  inline dealii::IndexSet
  contiguous_rows(const unsigned int n, const bool even)
  {
    const unsigned int r =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int p =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const auto start = [&](const std::size_t k) {
      return even ? n * k / p : n * (k * (k + 1) / 2) / (p * (p + 1) / 2);
    };
    dealii::IndexSet owned(n);
    owned.add_range(start(r), start(r + 1));
    return owned;
  }

  /// The rows @p owned of @p serial in @p distributed, a matrix over
  /// MPI_COMM_WORLD of the same pattern and values, except that the row
  /// and column of @p zeroed (if any) are zero. Read through Epetra's row
  /// views: deal.II's iterators clear a vector of all columns at each row.
  inline void
  copy_own_rows(
    const dealii::TrilinosWrappers::SparseMatrix &serial,
    const dealii::IndexSet                       &owned,
    dealii::TrilinosWrappers::SparseMatrix       &distributed,
    const unsigned int zeroed = std::numeric_limits<unsigned int>::max())
  {
    using size_type = dealii::TrilinosWrappers::SparseMatrix::size_type;
    const Epetra_CrsMatrix &m = serial.trilinos_matrix();
    std::vector<size_type>  columns;
    std::vector<double>     values;
    const auto              read_row = [&](const size_type row) {
      int     n;
      double *v;
      int    *c;
      m.ExtractMyRowView(m.LRID(int(row)), n, v, c);
      columns.resize(n);
      values.assign(v, v + n);
      for (int k = 0; k < n; ++k)
        {
          columns[k] = m.GCID(c[k]);
          if (row == zeroed || columns[k] == zeroed)
            values[k] = 0;
        }
    };
    dealii::TrilinosWrappers::SparsityPattern pattern(owned, MPI_COMM_WORLD);
    for (const size_type row : owned)
      {
        read_row(row);
        pattern.add_entries(row, columns.begin(), columns.end());
      }
    pattern.compress();
    distributed.reinit(pattern);
    for (const size_type row : owned)
      {
        read_row(row);
        distributed.set(row, columns.size(), columns.data(), values.data());
      }
    distributed.compress(dealii::VectorOperation::insert);
  }
} // namespace rodnet::testing

#endif
