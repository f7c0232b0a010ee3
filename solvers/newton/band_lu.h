#ifndef RODNET_SOLVERS_NEWTON_BAND_LU_H
#define RODNET_SOLVERS_NEWTON_BAND_LU_H

#include <cstddef>
#include <vector>

namespace rodnet
{
  /**
   * LU factorization with partial pivoting of an n x n matrix whose entries
   * lie within @p kl diagonals below and @p ku above the main one: the
   * algorithm of LAPACK's unblocked dgbtf2/dgbtrs (Golub & Van Loan,
   * "Matrix Computations", 4th ed., Alg. 4.3.5 with row exchanges), in
   * LAPACK's band storage, so that the factors are LAPACK's to round-off.
   *
   * It is written here rather than called from LAPACK so that the band LU of
   * a rod does not depend on which BLAS the system serves: the rows of a
   * rod's band are 11-32 entries long, where a BLAS call per column costs
   * more than the column's arithmetic, and OpenBLAS, which MUMPS needs for
   * its dense fronts, made LAPACK's band factorization 1.7 times slower
   * (bench/band_lu; doc/performance.md, "OpenBLAS and our own band LU").
   *
   * The matrix is stored column by column, 2 kl + ku + 1 entries each: entry
   * (i, j) at entry(i, j); the first kl rows of the storage take the fill of
   * the row exchanges.
   */
  class BandLU
  {
  public:
    /// An all-zero n x n band matrix of half-widths @p kl and @p ku.
    BandLU(int n, int kl, int ku);

    /// Where entry (@p row, @p column) of the matrix is in storage();
    /// |row - column| must be within the band.
    std::size_t
    entry(const int row, const int column) const
    {
      return std::size_t(kl + ku + row - column) +
             std::size_t(column) * std::size_t(leading);
    }

    /// The band storage, to be filled through entry() before factorize().
    std::vector<double> &
    storage()
    {
      return band;
    }

    /// The number of stored entries, the fill of the row exchanges included.
    std::size_t
    size() const
    {
      return band.size();
    }

    /// Sets every entry to zero, for a matrix of the same band.
    void
    clear();

    /**
     * Overwrites the matrix by its factors L U = P A. Returns 0, or the
     * 1-based number of the first column with no nonzero pivot (then the
     * factors are unusable).
     */
    int
    factorize();

    /// Overwrites @p x (n entries) by the solution of A x = x.
    void
    solve(double *x) const;

  private:
    /// Exchanges rows @p j and @p p of columns j to @p last, eliminates
    /// column j below its pivot and updates columns j + 1 to @p last.
    void
    eliminate(int j, int p, int last);

    const int           n, kl, ku, leading;
    std::vector<double> band;
    /// The row exchanged with row j at step j.
    std::vector<int> pivots;
  };
} // namespace rodnet

#endif
