#ifndef RODNET_CORE_DIRECT_SCATTER_H
#define RODNET_CORE_DIRECT_SCATTER_H

#include <core/foreign_rows.h>
#include <core/scatter_positions.h>
#include <core/solvable_model.h>

#include <Epetra_BlockMap.h>
#include <Epetra_CrsMatrix.h>
#include <memory>
#include <mpi.h>
#include <vector>

namespace rodnet
{
  /**
   * Adds local contributions straight into the compressed rows of the
   * Trilinos matrix and the vector's storage, for constraints that only
   * fix DoFs (rows and columns of fixed DoFs are skipped; their diagonal is
   * set by finish()). It replaces AffineConstraints::
   * distribute_local_to_global, whose per-entry global-to-local lookups
   * and searches cost more than the kernels (see doc/performance.md).
   * Each matrix entry goes to the place ScatterPositions found for it
   * once per sparsity pattern, without searching its row.
   *
   * On several processes each adds the rows of its own contiguous share of
   * the DoFs, the matrix's columns numbered by the model's column map
   * (RodModel::finalize()); it keeps the rows of other processes' DoFs
   * (ForeignRows) until add_foreign_rows() sends them to their owners. The
   * caller then calls add() from one thread at a time.
   */
  class DirectScatter
  {
  public:
    /// What the scatter needs to know of the model's numbering.
    struct Numbering
    {
      /// The DoFs this process owns: first, ..., first + n_owned - 1.
      global_dof_index first   = 0;
      global_dof_index n_owned = 0;
      /// On several processes, the column map of the model's matrices and
      /// the column of each DoF in it (-1: none); null on one process.
      const Epetra_BlockMap  *column_map   = nullptr;
      const std::vector<int> *local_column = nullptr;
      MPI_Comm                communicator = MPI_COMM_SELF;
      /// On several processes, the first DoF of every process's share in
      /// rank order, then the number of DoFs; null on one process.
      const std::vector<global_dof_index> *share_starts = nullptr;
    };

    /// Epetra's compressed rows of @p m (null arrays where its storage
    /// is not optimized), numbered as @p numbering says.
    static CsrArrays
    csr_of(const Epetra_CrsMatrix &m, const Numbering &numbering);

    /// Whether the direct scatter applies to @p matrix (or to vectors
    /// alone, @p matrix null) of a model numbered as @p numbering: the
    /// matrix has the model's rows and columns and optimized storage.
    static bool
    applies(const MatrixType *matrix, const Numbering &numbering);

    /// @p positions: where the stencils' entries land in @p matrix's rows
    /// (needed if @p matrix is not null).
    DirectScatter(MatrixType                             *matrix,
                  VectorType                             *vector,
                  const std::vector<bool>                *fixed,
                  std::shared_ptr<const ScatterPositions> positions,
                  const Numbering                        &numbering);

    /// Adds @p copy's rows of this process, and keeps the others for
    /// add_foreign_rows().
    void
    add(const LocalContribution &copy) const
    {
      const unsigned int n = copy.dofs.size();
      if (foreign != nullptr)
        foreign->keep(copy, fixed, csr.values != nullptr, values != nullptr);
      if (values != nullptr)
        for (unsigned int i = 0; i < n; ++i)
          if (owns(copy.dofs[i]) && !is_fixed(copy.dofs[i]))
            values[copy.dofs[i] - numbering.first] += copy.vector[i];
      if (csr.values == nullptr)
        return;
      const std::uint8_t *at = positions->of(copy.family, copy.stencil);
      if (at == nullptr)
        return add_searching(copy);
      for (unsigned int i = 0; i < n; ++i, at += n)
        {
          const int row = csr.row_of(copy.dofs[i]);
          if (row < 0)
            continue;
          double       *row_values = csr.values + csr.offsets[row];
          const double *local      = &copy.matrix(i, 0);
          for (unsigned int j = 0; j < n; ++j)
            if (at[j] != ScatterPositions::skip())
              row_values[at[j]] += local[j];
        }
    }

    /// On several processes, sends the rows of other processes' DoFs kept
    /// by add() to them and adds the rows they sent; collective. Before
    /// finish().
    void
    add_foreign_rows() const;
    /// Zeroes the matrix's values (in pieces, on all threads: 64 MB
    /// for a rod of 1e5 vertices).
    void
    zero_matrix() const;

    /// Puts the mean free diagonal (over all processes) on the rows of
    /// fixed DoFs, so that the Newton increment is zero there and the
    /// scale matches.
    void
    finish() const;

    /// The positions of @p matrix's entries for @p families, found once
    /// per pattern and supports by @p cache.
    static std::shared_ptr<const ScatterPositions>
    positions_for(ScatterPositionsCache                             &cache,
                  const std::vector<std::unique_ptr<ElementFamily>> &families,
                  const MatrixType                                  &matrix,
                  const std::vector<bool>                           *fixed,
                  const Numbering                                   &numbering);

  private:
    bool
    owns(const global_dof_index dof) const
    {
      return dof - numbering.first < numbering.n_owned;
    }

    bool
    is_fixed(const global_dof_index dof) const
    {
      return fixed != nullptr && (*fixed)[dof];
    }

    /// add() for a stencil of a family without positions (rows too long
    /// for them): each entry searched in its row.
    void
    add_searching(const LocalContribution &copy) const;

    CsrArrays                               csr;
    double                                 *values;
    const std::vector<bool>                *fixed;
    std::shared_ptr<const ScatterPositions> positions;
    Numbering                               numbering;
    std::unique_ptr<ForeignRows>            foreign;
  };
} // namespace rodnet

#endif
