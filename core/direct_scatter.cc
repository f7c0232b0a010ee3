#include <deal.II/base/mpi.h>
#include <deal.II/base/parallel.h>

#include <base/phase_times.h>
#include <core/direct_scatter.h>

#include <algorithm>
#include <cmath>

namespace rodnet
{
  CsrArrays
  DirectScatter::csr_of(const Epetra_CrsMatrix &m, const Numbering &numbering)
  {
    CsrArrays csr;
    m.ExtractCrsDataPointers(csr.offsets, csr.columns, csr.values);
    csr.n_rows       = m.NumMyRows();
    csr.first_row    = numbering.first;
    csr.local_column = numbering.local_column;
    return csr;
  }


  bool
  DirectScatter::applies(const MatrixType *matrix, const Numbering &numbering)
  {
    if (matrix == nullptr)
      return true;
    const Epetra_CrsMatrix &m = matrix->trilinos_matrix();
    // add() writes straight into Epetra's arrays, which exist once the
    // storage is optimized (as FillComplete leaves it).
    if (csr_of(m, numbering).offsets == nullptr || !m.RowMap().LinearMap() ||
        m.RowMap().NumMyElements() != static_cast<int>(numbering.n_owned) ||
        (numbering.n_owned > 0 &&
         m.RowMap().MinMyGID() != static_cast<int>(numbering.first)))
      return false;
    if (numbering.column_map != nullptr)
      return m.ColMap().SameAs(*numbering.column_map);
    return m.ColMap().LinearMap() && m.ColMap().MinMyGID() == 0 &&
           m.ColMap().NumMyElements() == m.RowMap().NumMyElements();
  }


  DirectScatter::DirectScatter(
    MatrixType                             *matrix,
    VectorType                             *vector,
    const std::vector<bool>                *fixed,
    std::shared_ptr<const ScatterPositions> positions,
    const Numbering                        &numbering)
      : csr(matrix == nullptr ? CsrArrays() :
                                csr_of(matrix->trilinos_matrix(), numbering))
      , values(vector == nullptr ? nullptr : vector->trilinos_vector()[0])
      , fixed(fixed)
      , positions(std::move(positions))
      , numbering(numbering)
      , foreign(numbering.share_starts == nullptr ?
                  nullptr :
                  std::make_unique<ForeignRows>(*numbering.share_starts,
                                                numbering.communicator))
  {
  }


  std::shared_ptr<const ScatterPositions>
  DirectScatter::positions_for(
    ScatterPositionsCache                             &cache,
    const std::vector<std::unique_ptr<ElementFamily>> &families,
    const MatrixType                                  &matrix,
    const std::vector<bool>                           *fixed,
    const Numbering                                   &numbering)
  {
    return cache.get(families,
                     csr_of(matrix.trilinos_matrix(), numbering),
                     fixed);
  }


  void
  DirectScatter::zero_matrix() const
  {
    if (csr.values == nullptr)
      return;
    double *const values = csr.values;
    dealii::parallel::apply_to_subranges(
      std::size_t(0),
      std::size_t(csr.offsets[csr.n_rows]),
      [values](const std::size_t begin, const std::size_t end) {
        std::fill(values + begin, values + end, 0.0);
      },
      std::size_t(1) << 16);
  }


  void
  DirectScatter::add_foreign_rows() const
  {
    if (foreign == nullptr)
      return;
    const phase_times::Scope phase(phase_times::Phase::exchange);
    foreign->exchange([this](const ForeignRows::Row &row) {
      if (values != nullptr)
        values[row.dof - numbering.first] += row.vector_value;
      if (csr.values == nullptr || row.n == 0)
        return;
      const int  r     = csr.row_of(row.dof);
      const int *begin = csr.columns + csr.offsets[r];
      const int *end   = csr.columns + csr.offsets[r + 1];
      for (unsigned int j = 0; j < row.n; ++j)
        {
          // The pattern holds every entry of every stencil.
          const int *at = std::find(begin, end, csr.column_of(row.columns[j]));
          Assert(at != end, dealii::ExcInternalError());
          csr.values[at - csr.columns] += row.values[j];
        }
    });
  }


  void
  DirectScatter::finish() const
  {
    if (csr.values == nullptr || fixed == nullptr)
      return;
    const std::vector<std::ptrdiff_t> &places = positions->diagonal();
    double                             sum    = 0;
    global_dof_index                   n_free = 0;
    for (int row = 0; row < csr.n_rows; ++row)
      if (!(*fixed)[numbering.first + row] && places[row] >= 0)
        {
          sum += std::abs(csr.values[places[row]]);
          ++n_free;
        }
    if (numbering.column_map != nullptr)
      {
        sum    = dealii::Utilities::MPI::sum(sum, numbering.communicator);
        n_free = dealii::Utilities::MPI::sum(n_free, numbering.communicator);
      }
    const double value = n_free > 0 ? sum / n_free : 1.0;
    for (int row = 0; row < csr.n_rows; ++row)
      if ((*fixed)[numbering.first + row] && places[row] >= 0)
        csr.values[places[row]] = value;
  }


  void
  DirectScatter::add_searching(const LocalContribution &copy) const
  {
    for (unsigned int i = 0; i < copy.dofs.size(); ++i)
      {
        const int row = csr.row_of(copy.dofs[i]);
        if (row < 0 || is_fixed(copy.dofs[i]))
          continue;
        const int *begin = csr.columns + csr.offsets[row];
        const int *end   = csr.columns + csr.offsets[row + 1];
        for (unsigned int j = 0; j < copy.dofs.size(); ++j)
          if (!is_fixed(copy.dofs[j]))
            csr.values[std::find(begin, end, csr.column_of(copy.dofs[j])) -
                       csr.columns] += copy.matrix(i, j);
      }
  }
} // namespace rodnet
