// The continuation's limit-point estimates on lambda(s) = 2 - (s - 1)^2,
// whose limit point is lambda = 2 at s = 1: both are exact for a parabola.
#include <solvers/continuation/limit_point_estimate.h>

#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  double
  parabola_path(const double s)
  {
    return 2 - (s - 1) * (s - 1);
  }

  double
  parabola_slope(const double s)
  {
    return -2 * (s - 1);
  }

  TEST(LimitPointEstimate, ParabolaThroughThreePoints)
  {
    EXPECT_NEAR(parabola_extremum({{{0.2, parabola_path(0.2)},
                                    {0.7, parabola_path(0.7)},
                                    {1.6, parabola_path(1.6)}}}),
                2.0,
                1e-14);
    // Collinear points: the middle one's load factor.
    EXPECT_EQ(parabola_extremum({{{0, 0}, {1, 1}, {2, 2}}}), 1.0);
  }

  TEST(LimitPointEstimate, SlopesAtTheTwoEndsOfTheFirstStep)
  {
    // The first step from s = 0 lands past the fold at s = 1.7.
    EXPECT_NEAR(slope_extremum(0,
                               parabola_path(0),
                               parabola_slope(0),
                               1.7,
                               parabola_slope(1.7)),
                2.0,
                1e-14);
    // And a falling path's lowest point, from the other side.
    EXPECT_NEAR(slope_extremum(1.5,
                               -parabola_path(1.5),
                               -parabola_slope(1.5),
                               0.4,
                               -parabola_slope(0.4)),
                -2.0,
                1e-14);
  }
} // namespace
