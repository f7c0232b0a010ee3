// Our band LU (solvers/newton/band_lu.h) against LAPACK's dgbtrf/dgbtrs on
// the same band matrix, in one run, taking turns: factorization and solve,
// median (min-max) of the repeats, and the largest difference of the two
// solutions relative to their largest entry. The matrix has the half-widths
// of a rod's tangent (11 for a rod of 4e5 DoFs), random entries and a small
// diagonal entry every fifth row, so that rows are exchanged. Which LAPACK
// and BLAS run is the system's (update-alternatives) or LD_LIBRARY_PATH's:
//   LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/blas:/usr/lib/x86_64-linux-gnu/lapack
// loads Debian's reference ones where OpenBLAS is installed.
//
// Usage: band_lu [--rows n] [--width k] [--repeats r]
//        (defaults 400000, 11 and 9).
#include <solvers/newton/band_lu.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <cmath>
#include <cstdio>
#include <random>

extern "C"
{
  void
  dgbtrf_(const int *m,
          const int *n,
          const int *kl,
          const int *ku,
          double    *ab,
          const int *ldab,
          int       *ipiv,
          int       *info);
  void
  dgbtrs_(const char   *trans,
          const int    *n,
          const int    *kl,
          const int    *ku,
          const int    *nrhs,
          const double *ab,
          const int    *ldab,
          const int    *ipiv,
          double       *b,
          const int    *ldb,
          int          *info);
}

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads = 1;
    unsigned int rows    = 400000;
    unsigned int width   = 11;
    unsigned int repeats = 9;

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--rows", rows, 1),
              bench::number("--width", width, 0),
              bench::number("--repeats", repeats, 3)};
    }
  };

  /// The matrix of the header in @p lu's storage.
  std::vector<double>
  test_matrix(const BandLU &lu, const int n, const int width)
  {
    std::mt19937                           generator(1);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<double>                    band(lu.size(), 0.0);
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - width); i <= std::min(n - 1, j + width); ++i)
        band[lu.entry(i, j)] =
          i != j ? uniform(generator) : (j % 5 == 0 ? 0.01 : 4.0);
    return band;
  }

  /// The right-hand side of every solve.
  std::vector<double>
  right_hand_side(const int n)
  {
    std::vector<double> b(n);
    for (int i = 0; i < n; ++i)
      b[i] = 1.0 + i % 7;
    return b;
  }

  /// max |x - y| / max |y|.
  double
  largest_difference(const std::vector<double> &x, const std::vector<double> &y)
  {
    double difference = 0, largest = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      {
        difference = std::max(difference, std::abs(x[i] - y[i]));
        largest    = std::max(largest, std::abs(y[i]));
      }
    return difference / largest;
  }

  /// The table of the header: @p times are ours and LAPACK's factorize,
  /// then ours and LAPACK's solve.
  void
  print_comparison(const Options                          &options,
                   const std::vector<std::vector<double>> &times,
                   const double                            difference)
  {
    std::printf("%u rows, half-widths %u, %u repeats\n",
                options.rows,
                options.width,
                options.repeats);
    bench::print_time("ours: factorize", times[0]);
    bench::print_time("LAPACK: factorize", times[1]);
    bench::print_time("ours: solve", times[2]);
    bench::print_time("LAPACK: solve", times[3]);
    std::printf("median factorize ours / LAPACK %.3f, solve %.3f\n",
                bench::statistics(times[0]).median /
                  bench::statistics(times[1]).median,
                bench::statistics(times[2]).median /
                  bench::statistics(times[3]).median);
    std::printf("solutions differ by %.3g of their largest entry\n",
                difference);
  }

  void
  band_lu(const Options &options)
  {
    const int           n = options.rows, w = options.width;
    BandLU              lu(n, w, w);
    const auto          matrix = test_matrix(lu, n, w);
    std::vector<double> lapack(matrix.size()), x, y;
    std::vector<int>    pivots(n);
    const int           leading = 3 * w + 1, one = 1;
    int                 info = 0;
    std::vector<double> ours_factor, ours_solve, lapack_factor, lapack_solve;
    for (unsigned int r = 0; r < options.repeats; ++r)
      {
        lu.storage() = matrix;
        ours_factor.push_back(bench::timed_together([&] { lu.factorize(); }));
        x = right_hand_side(n);
        ours_solve.push_back(
          bench::timed_together([&] { lu.solve(x.data()); }));

        lapack = matrix;
        lapack_factor.push_back(bench::timed_together([&] {
          dgbtrf_(&n,
                  &n,
                  &w,
                  &w,
                  lapack.data(),
                  &leading,
                  pivots.data(),
                  &info);
        }));
        y = right_hand_side(n);
        lapack_solve.push_back(bench::timed_together([&] {
          dgbtrs_("N",
                  &n,
                  &w,
                  &w,
                  &one,
                  lapack.data(),
                  &leading,
                  pivots.data(),
                  y.data(),
                  &n,
                  &info);
        }));
      }
    print_comparison(options,
                     {ours_factor, lapack_factor, ours_solve, lapack_solve},
                     largest_difference(x, y));
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("band_lu", argc, argv, band_lu);
}
