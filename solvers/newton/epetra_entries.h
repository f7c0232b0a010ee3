#ifndef RODNET_SOLVERS_NEWTON_EPETRA_ENTRIES_H
#define RODNET_SOLVERS_NEWTON_EPETRA_ENTRIES_H

#include <Epetra_CrsMatrix.h>

namespace rodnet
{
  /// Calls @p f(row, column, value) for every stored entry of @p m, row by
  /// row in the order of its compressed rows (one process: local rows and
  /// global columns are the same numbers).
  template <class Function>
  void
  for_each_entry(const Epetra_CrsMatrix &m, const Function &f)
  {
    for (int row = 0; row < m.NumMyRows(); ++row)
      {
        int     n;
        int    *columns;
        double *values;
        m.ExtractMyRowView(row, n, values, columns);
        for (int k = 0; k < n; ++k)
          f(row, m.GCID(columns[k]), values[k]);
      }
  }
} // namespace rodnet

#endif
