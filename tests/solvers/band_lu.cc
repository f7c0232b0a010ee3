// BandLU, the band LU with partial pivoting of a rod's tangent: on band
// matrices whose diagonal holds zeros, so that rows must be exchanged, its
// solutions equal those of Eigen's dense LU with partial pivoting to
// round-off and leave a backward error of round-off; the widths at the
// edges (no diagonal below, none above, one row) work; a matrix with a zero
// column is reported at that column.

#include <solvers/newton/band_lu.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <random>

using namespace rodnet;

namespace
{
  /// A random n x n matrix of half-widths @p kl and @p ku, every third
  /// diagonal entry zero, as a dense matrix.
  Eigen::MatrixXd
  random_band(const int n, const int kl, const int ku, const unsigned seed)
  {
    std::mt19937                           generator(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::MatrixXd                        a = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i)
        a(i, j) = (i == j && j % 3 == 0) ? 0.0 : uniform(generator);
    return a;
  }

  /// @p a's entries within its band, in BandLU's storage.
  BandLU
  band_of(const Eigen::MatrixXd &a, const int kl, const int ku)
  {
    const int n = int(a.rows());
    BandLU    lu(n, kl, ku);
    for (int j = 0; j < n; ++j)
      for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i)
        lu.storage()[lu.entry(i, j)] = a(i, j);
    return lu;
  }

  /// |x - x_dense| / |x_dense| for A x = b, b = (1, 2, ..., n), and the
  /// backward error |A x - b| / (|A| |x|).
  std::pair<double, double>
  errors_against_dense_lu(const int n, const int kl, const int ku)
  {
    const Eigen::MatrixXd a  = random_band(n, kl, ku, 7u + unsigned(n + kl));
    const Eigen::VectorXd b  = Eigen::VectorXd::LinSpaced(n, 1.0, n);
    BandLU                lu = band_of(a, kl, ku);
    EXPECT_EQ(lu.factorize(), 0);
    Eigen::VectorXd x = b;
    lu.solve(x.data());
    const Eigen::VectorXd dense = a.partialPivLu().solve(b);
    return {(x - dense).norm() / dense.norm(),
            (a * x - b).norm() / (a.norm() * x.norm())};
  }
} // namespace


TEST(BandLU, SolvesAsDenseLuWithRowExchanges)
{
  // Widths of a rod's tangent (11-32), and unequal ones.
  for (const auto &[kl, ku] : {std::pair{11, 11}, {3, 7}, {7, 3}, {32, 32}})
    {
      const auto [difference, backward] = errors_against_dense_lu(200, kl, ku);
      EXPECT_LT(difference, 1e-10) << kl << ", " << ku;
      EXPECT_LT(backward, 1e-14) << kl << ", " << ku;
    }
}


TEST(BandLU, EdgeWidthsWork)
{
  // Upper triangular (no row to exchange with), lower triangular, and
  // one entry; the zero diagonals of random_band() would make the first
  // two singular, so they get a diagonal of their own.
  for (const auto &[kl, ku] : {std::pair{0, 4}, {4, 0}})
    {
      Eigen::MatrixXd a = random_band(30, kl, ku, 3u);
      a.diagonal().setConstant(2.0);
      BandLU lu = band_of(a, kl, ku);
      ASSERT_EQ(lu.factorize(), 0);
      Eigen::VectorXd x = Eigen::VectorXd::Ones(30);
      lu.solve(x.data());
      EXPECT_LT((a * x - Eigen::VectorXd::Ones(30)).norm(), 1e-13);
    }
  BandLU one(1, 0, 0);
  one.storage()[one.entry(0, 0)] = 4.0;
  ASSERT_EQ(one.factorize(), 0);
  double x = 2.0;
  one.solve(&x);
  EXPECT_DOUBLE_EQ(x, 0.5);
}


TEST(BandLU, AZeroColumnIsReportedWhereItIs)
{
  Eigen::MatrixXd a = random_band(40, 3, 3, 11u);
  a.col(17).setZero();
  BandLU lu = band_of(a, 3, 3);
  // Columns are numbered from 1, as LAPACK's info.
  EXPECT_EQ(lu.factorize(), 18);
}
