// The elastic Moebius band of Wunderlich's developable ribbon model
// (scenes/moebius_band.prm; Korner et al. section 5(d), Starostin & van der
// Heijden 2007): a strip of length L = 2 pi and half-width w = pi/30 closed
// through its clamped end segments, one clamp turned by pi about its
// tangent. At the end of the continuation, for 74, 148 and 296 segments:
// - the state is a Moebius band: the linking number of the centreline with
//   the strip's edge, Tw + Wr (Calugareanu), is 1/2 (Wr by the Gauss
//   integral of the centreline);
// - the constraints hold: every segment keeps its length, kappa_2 = 0 and
//   kappa_3 = eta kappa_1 at every hinge;
// - the band has the two-fold symmetry of the published shapes: the
//   strains at s and L - s agree;
// - in the narrow limit the clamps hold nothing: the free band (a closed
//   ring with a half turn of its frame) started from the clamped one stays
//   there, and is stable;
// - the energy V converges at second order, the strain distributions
//   kappa_1 / l, kappa_3 / l at first order at their worst point (beside
//   the clamps).
#include <common/moebius_band.h>

#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;
  using moebius::Band;

  constexpr double pi         = M_PI;
  constexpr double half_width = pi / 30;

  /// Writhe of the closed polygon @p x by the Gauss integral over pairs of
  /// segments, midpoint rule.
  double
  writhe(const std::vector<Vector3> &x)
  {
    const unsigned int n   = x.size();
    double             sum = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          if (i == j)
            continue;
          const Vector3 ti = x[(i + 1) % n] - x[i];
          const Vector3 tj = x[(j + 1) % n] - x[j];
          const Vector3 r =
            0.5 * (x[i] + x[(i + 1) % n] - x[j] - x[(j + 1) % n]);
          sum += ti.cross(tj).dot(r) / std::pow(r.norm(), 3);
        }
    return sum / (4 * pi);
  }

  /// Negative eigenvalues on the constraint manifold at the free band's
  /// equilibrium (relax_freely()).
  unsigned int negative_eigenvalues = 0;

  /// The free band of width 1e-5 (the narrow limit, D = 1) relaxed by
  /// Newton from the clamped band @p clamped.
  Band
  relax_freely(const Band &clamped)
  {
    const auto model  = moebius::free_band(clamped.centreline, 1e-5);
    VectorType u      = moebius::free_state(*model, clamped);
    const auto result = moebius::newton(*model, u, 1e-11, 1e-13);
    EXPECT_TRUE(result.converged) << "the free band's Newton";
    std::cout << "free band: " << result.iterations
              << " Newton iterations, |r| = " << result.residual << std::endl;
    negative_eigenvalues = result.negative_eigenvalues;
    return moebius::band_state(*model, u, clamped.centreline.size());
  }

  class MoebiusBandTest : public ::testing::Test
  {
  protected:
    static void
    SetUpTestSuite()
    {
      for (const unsigned int m : {74u, 148u, 296u})
        bands.push_back(moebius::solve_clamped(m + 1));
    }
    static std::vector<Band> bands;
  };
  std::vector<Band> MoebiusBandTest::bands;

  TEST_F(MoebiusBandTest, IsAMoebiusBandWithItsConstraints)
  {
    for (const Band &band : bands)
      {
        double twist = 0, developability = 0;
        for (unsigned int h = 0; h < band.strains.size(); ++h)
          {
            const Vector3 &k = band.strains[h];
            twist += k[2];
            developability = std::max({developability,
                                       std::abs(k[1]),
                                       std::abs(k[2] - band.etas[h] * k[0])});
          }
        const double linking = twist / (2 * pi) + writhe(band.centreline);
        std::cout << band.centreline.size() << " segments: V = " << band.energy
                  << ", Tw = " << twist / (2 * pi) << ", Tw + Wr = " << linking
                  << ", constraints " << developability << ", lengths "
                  << band.length_error << std::endl;
        // Tw and Wr are O(l^2) sums.
        // The sums converge as O(l^2), not faster than 0.2 / N here.
        EXPECT_NEAR(linking, 0.5, 0.2 / band.centreline.size());
        EXPECT_LT(developability, 1e-10);
        EXPECT_LT(band.length_error, 1e-12);
      }
  }

  // In the narrow limit the clamps of the closure hold nothing: the free
  // band (the closed ring with a half turn, no clamp, a statically
  // determinate support), started from the clamped one, stays where it is,
  // and is stable. Where the curvature changes sign at the clamp the
  // generatrix slope is eta = +-1, where the bending moment
  // d/dkappa_1 [kappa_1^2 (1 + eta^2)^2] at fixed kappa_3 vanishes.
  TEST_F(MoebiusBandTest, NarrowBandIsFreeOfItsClamps)
  {
    // Width 1e-5 with D = 1 (Y h^3 / 12, h = w / 2).
    const Band clamped =
      moebius::solve_clamped(149,
                             "    set Young's modulus = 9.6e16\n"
                             "    set Width = 1e-5\n"
                             "    set Thickness = 5e-6\n");
    const Band   band   = relax_freely(clamped);
    const double change = band.energy / clamped.energy - 1;
    std::cout << "narrow band: V / (D w) = " << clamped.energy / 0.5e-5
              << " clamped, " << band.energy / 0.5e-5
              << " free; eta at the clamp " << clamped.etas.front() << ", "
              << clamped.etas.back() << std::endl;
    EXPECT_LT(std::abs(change), 1e-6);
    EXPECT_EQ(negative_eigenvalues, 0u);
  }

  TEST_F(MoebiusBandTest, HasTheTwoFoldSymmetry)
  {
    for (const Band &band : bands)
      {
        const unsigned int n         = band.strains.size();
        double             asymmetry = 0;
        for (unsigned int h = 0; h < n; ++h)
          asymmetry = std::max(
            asymmetry,
            (band.strains[h] - band.strains[n - 1 - h]).cwiseAbs().maxCoeff());
        EXPECT_LT(asymmetry / band.segment, 1e-6);
      }
  }

  TEST_F(MoebiusBandTest, EnergyConvergesAtSecondOrderAndStrainsConverge)
  {
    const double order_energy = std::log2((bands[0].energy - bands[1].energy) /
                                          (bands[1].energy - bands[2].energy));
    const double extrapolated =
      bands[2].energy + (bands[2].energy - bands[1].energy) / 3;
    // D = 1: V / (D w) with the half-width.
    std::cout << "energy order " << order_energy << ", V = " << extrapolated
              << ", V / (D w) = " << extrapolated / half_width << std::endl;
    EXPECT_NEAR(order_energy, 2.0, 0.1);

    // The strain densities kappa / l of each band at its hinges, s = (k -
    // 1/2) l from the clamp's middle for the hinge at vertex k, against
    // the next band's interpolated between its hinges at s -+ l / 4.
    double errors[2] = {0, 0};
    for (unsigned int b = 0; b < 2; ++b)
      for (unsigned int j = 0; j < bands[b].strains.size(); ++j)
        {
          const Vector3 coarse = bands[b].strains[j] / bands[b].segment;
          const Vector3 fine =
            (bands[b + 1].strains[2 * j] + bands[b + 1].strains[2 * j + 1]) /
            (2 * bands[b + 1].segment);
          errors[b] =
            std::max(errors[b], (coarse - fine).cwiseAbs().maxCoeff());
        }
    std::cout << "strain differences " << errors[0] << ", " << errors[1]
              << std::endl;
    // First order at the worst point: the one-sided differences of eta at
    // the hinges beside the clamped closure; 0.1% of the strains at 296
    // segments.
    EXPECT_GT(std::log2(errors[0] / errors[1]), 0.9);
    EXPECT_LT(errors[1], 2e-3);
  }
} // namespace
