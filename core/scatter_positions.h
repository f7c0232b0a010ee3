#ifndef RODNET_CORE_SCATTER_POSITIONS_H
#define RODNET_CORE_SCATTER_POSITIONS_H

#include <core/element_family.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace rodnet
{
  /**
   * Epetra's compressed rows of an optimized matrix on one process: row r
   * holds the columns and values [offsets[r], offsets[r + 1]). All null if
   * the storage is not optimized (or there is no matrix).
   */
  struct CsrArrays
  {
    int    *offsets = nullptr;
    int    *columns = nullptr;
    double *values  = nullptr;
    int     n_rows  = 0;
    /// The global DoF of row 0: the rows are the DoFs first_row ..
    /// first_row + n_rows - 1 (a process's contiguous share).
    global_dof_index first_row = 0;
    /// Per global DoF, its index among the matrix's columns (-1: none); null
    /// where the columns are numbered as the DoFs (one process).
    const std::vector<int> *local_column = nullptr;

    /// The row of global DoF @p dof, or -1 where another process has it.
    int
    row_of(const global_dof_index dof) const
    {
      return dof >= first_row && dof < first_row + n_rows ?
               static_cast<int>(dof - first_row) :
               -1;
    }

    /// The column index of global DoF @p dof.
    int
    column_of(const global_dof_index dof) const
    {
      return local_column == nullptr ? static_cast<int>(dof) :
                                       (*local_column)[dof];
    }
  };

  /**
   * Where each entry of each stencil's local matrix lands in the compressed
   * rows of the tangent: per stencil and local entry (i, j), the position
   * of column dofs[j] within row dofs[i], one byte each (121 bytes for an
   * 11-DoF hinge), or skip() where the row or the column is a fixed DoF.
   * Found once per sparsity pattern, so that each assembly adds every
   * entry without searching its row (doc/performance.md, "The scatter").
   * A family with a row longer than skip() entries (a junction of a great
   * many rods) has no positions; the scatter searches its rows instead.
   */
  class ScatterPositions
  {
  public:
    /// Marks an entry that is not added (fixed row or column).
    static constexpr std::uint8_t
    skip()
    {
      return 255;
    }

    /**
     * Positions of the stencils of @p families in the rows @p csr, whose
     * fingerprint() is @p fingerprint; entries in the rows or columns of
     * DoFs that @p fixed marks (if not null) are skipped. Throws
     * std::logic_error if a stencil couples DoFs the rows do not hold.
     */
    ScatterPositions(
      const std::vector<std::unique_ptr<ElementFamily>> &families,
      const CsrArrays                                   &csr,
      const std::vector<bool>                           *fixed,
      std::uint64_t                                      fingerprint);

    /// A hash of the row offsets and column indices of @p csr and of the
    /// DoFs @p fixed marks: equal for the same pattern and supports. Taken
    /// at every assembly, over fixed-size pieces of the columns hashed in
    /// parallel, so that its value does not depend on the threads.
    static std::uint64_t
    fingerprint(const CsrArrays &csr, const std::vector<bool> *fixed);

    /// Per row, the place of its diagonal entry in the values of the
    /// compressed rows (what finish() of the scatter writes), or -1 where
    /// the pattern has none.
    const std::vector<std::ptrdiff_t> &
    diagonal() const
    {
      return diagonal_places;
    }

    /// The fingerprint these positions were found for.
    std::uint64_t
    pattern() const
    {
      return pattern_fingerprint;
    }

    /// The n x n positions (row-major) of stencil @p s of family @p f, or
    /// null if the family has none (its rows are searched).
    const std::uint8_t *
    of(const unsigned int f, const unsigned int s) const
    {
      const Family &family = families[f];
      return family.starts.empty() ? nullptr :
                                     family.entries.data() + family.starts[s];
    }

  private:
    struct Family
    {
      /// Per stencil, the first of its entries (n_stencils + 1 values);
      /// empty if the family has no positions.
      std::vector<std::size_t>  starts;
      std::vector<std::uint8_t> entries;
    };

    /// The positions of @p family, or none if a row is too long.
    static Family
    find(const ElementFamily     &family,
         const CsrArrays         &csr,
         const std::vector<bool> *fixed);

    std::vector<Family>         families;
    std::vector<std::ptrdiff_t> diagonal_places;
    std::uint64_t               pattern_fingerprint;
  };

  /**
   * A model's ScatterPositions for the pattern it was last assembled into,
   * found again when the pattern or the supports change. Assemblies from
   * several threads at once each get positions that match their matrix.
   */
  class ScatterPositionsCache
  {
  public:
    /// Positions for @p csr and @p fixed, found now if the cached ones are
    /// for another pattern.
    std::shared_ptr<const ScatterPositions>
    get(const std::vector<std::unique_ptr<ElementFamily>> &families,
        const CsrArrays                                   &csr,
        const std::vector<bool>                           *fixed);

  private:
    std::mutex                              mutex;
    std::shared_ptr<const ScatterPositions> positions;
  };
} // namespace rodnet

#endif
