// TrustRegionNewton (NewtonSolver's "trust region") where a line search has
// nothing to offer: from a saddle, and in the hard case of the subproblem
// (tests/solvers/potential_globalizations.cc has the cases it shares with
// the energy line search).
#include <common/separable_potential.h>

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using rodnet::testing::double_well;
  using rodnet::testing::SeparablePotential;
  using rodnet::testing::solve;

  TEST(TrustRegion, LeavesASaddleForAMinimum)
  {
    // From the maximum z = 0 of every well (zero gradient, the tangent
    // -I): full steps stay on it, "converged"; the trust region steps off
    // along the negative curvature and ends in a minimum |z| = 1.
    const SeparablePotential potential = double_well(3);
    std::vector<double>      x;
    ASSERT_TRUE(solve(potential, {0.0, 0.0, 0.0}, "full step", x).converged);
    EXPECT_EQ(x[0], 0.0);
    const NewtonSolver::Result result =
      solve(potential, {0.0, 0.0, 0.0}, "trust region", x);
    ASSERT_TRUE(result.converged) << result.failure;
    for (const double z : x)
      EXPECT_NEAR(std::abs(z), 1.0, 1e-10);
  }

  TEST(TrustRegion, SolvesTheHardCase)
  {
    // z1 = 0 sits on a maximum (gradient 0, curvature -1), z2 = 2 on the
    // convex side (gradient 6, curvature 11): the gradient is orthogonal
    // to the negative curvature mode, the hard case of the subproblem,
    // whose step must be completed along the mode. Minimum: |z| = 1.
    const SeparablePotential   potential = double_well(2);
    std::vector<double>        x;
    const NewtonSolver::Result result =
      solve(potential, {0.0, 2.0}, "trust region", x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_NEAR(std::abs(x[0]), 1.0, 1e-10);
    EXPECT_NEAR(x[1], 1.0, 1e-10);
  }

} // namespace
