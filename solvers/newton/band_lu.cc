#include <solvers/newton/band_lu.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rodnet
{
  BandLU::BandLU(const int n, const int kl, const int ku)
      : n(n)
      , kl(kl)
      , ku(ku)
      , leading(2 * kl + ku + 1)
      , band(std::size_t(leading) * std::size_t(n), 0.0)
      , pivots(n, 0)
  {
  }


  void
  BandLU::clear()
  {
    std::fill(band.begin(), band.end(), 0.0);
  }


  int
  BandLU::factorize()
  {
    // The last column that row j of U reaches: it grows by the row
    // exchanges, to at most kl + ku columns past the diagonal.
    int last = 0;
    for (int j = 0; j < n; ++j)
      {
        const int     below  = std::min(kl, n - 1 - j);
        const double *column = &band[entry(j, j)];
        // The first entry of largest magnitude, as LAPACK's idamax.
        int    p       = 0;
        double largest = std::abs(column[0]);
        for (int i = 1; i <= below; ++i)
          if (std::abs(column[i]) > largest)
            {
              p       = i;
              largest = std::abs(column[i]);
            }
        pivots[j] = j + p;
        if (largest == 0.0)
          return j + 1;
        last = std::max(last, std::min(j + ku + p, n - 1));
        eliminate(j, j + p, last);
      }
    return 0;
  }


  void
  BandLU::eliminate(const int j, const int p, const int last)
  {
    // Along a row the storage steps by leading - 1 from column to column.
    const std::size_t step = std::size_t(leading - 1);
    if (p != j)
      for (std::size_t a = entry(j, j), b = entry(p, j), c = j;
           c <= std::size_t(last);
           ++c, a += step, b += step)
        std::swap(band[a], band[b]);
    const int below            = std::min(kl, n - 1 - j);
    double *const __restrict l = &band[entry(j, j)] + 1;
    const double inverse       = 1.0 / l[-1];
    for (int i = 0; i < below; ++i)
      l[i] *= inverse;
    // The rank-one update of the columns j + 1 to last, rows j + 1 to
    // j + below: column c's row j is entry(j, c), its rows below follow.
    for (int c = j + 1; c <= last; ++c)
      {
        double *const __restrict u = &band[entry(j, c)];
        const double pivot         = u[0];
        if (pivot != 0.0)
          for (int i = 0; i < below; ++i)
            u[i + 1] -= l[i] * pivot;
      }
  }


  void
  BandLU::solve(double *const __restrict x) const
  {
    // L y = P b, with the exchanges in the order they were made.
    for (int j = 0; j < n - 1; ++j)
      {
        if (pivots[j] != j)
          std::swap(x[j], x[pivots[j]]);
        const int     below = std::min(kl, n - 1 - j);
        const double *l     = &band[entry(j, j)] + 1;
        const double  xj    = x[j];
        if (xj != 0.0)
          for (int i = 0; i < below; ++i)
            x[j + 1 + i] -= l[i] * xj;
      }
    // U x = y, column by column from the last; U has kl + ku diagonals
    // above its main one.
    for (int j = n - 1; j >= 0; --j)
      {
        const double *u = &band[entry(j, j)];
        x[j] /= u[0];
        const double xj  = x[j];
        const int    top = std::max(0, j - kl - ku);
        if (xj != 0.0)
          for (int i = top; i < j; ++i)
            x[i] -= u[i - j] * xj;
      }
  }
} // namespace rodnet
