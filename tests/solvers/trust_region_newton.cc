// TrustRegionNewton (NewtonSolver's "trust region") on small potential
// problems with known minimizers: where full Newton steps diverge, from a
// saddle, and in the hard case of the subproblem.
#include <common/separable_potential.h>

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using rodnet::testing::SeparablePotential;
  using rodnet::testing::solve;

  /// The double well w(z) = z^4/4 - z^2/2: minima w(+-1) = -1/4, a
  /// maximum at z = 0 where w'' = -1.
  SeparablePotential
  double_well(const unsigned int n)
  {
    return {[](double z) { return z * z * z * z / 4 - z * z / 2; },
            [](double z) { return z * z * z - z; },
            [](double z) { return 3 * z * z - 1; },
            std::vector<double>(n, 0.0)};
  }

  TEST(TrustRegion, ConvergesWhereFullNewtonStepsDiverge)
  {
    // p(z) = sqrt(1 + z^2): a full Newton step maps z to -z^3, which
    // diverges from |z| > 1; the minimizer is x = c.
    const SeparablePotential potential{
      [](double z) { return std::sqrt(1 + z * z); },
      [](double z) { return z / std::sqrt(1 + z * z); },
      [](double z) { return std::pow(1 + z * z, -1.5); },
      {1.0, -2.0, 0.5}};
    std::vector<double> x;
    EXPECT_FALSE(solve(potential, {4.0, 1.0, 3.5}, "full step", x).converged);
    const NewtonSolver::Result result =
      solve(potential, {4.0, 1.0, 3.5}, "trust region", x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_LE(result.iterations, 30u);
    for (unsigned int i = 0; i < x.size(); ++i)
      EXPECT_NEAR(x[i], potential.centre[i], 1e-11);
  }

  TEST(TrustRegion, TakesTheNewtonStepOnAQuadratic)
  {
    const SeparablePotential   potential{[](double z) { return 2 * z * z; },
                                       [](double z) { return 4 * z; },
                                       [](double) { return 4.0; },
                                       {3.0, -1.0}};
    std::vector<double>        x;
    const NewtonSolver::Result result =
      solve(potential, {0.0, 0.0}, "trust region", x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_EQ(result.iterations, 1u);
    EXPECT_NEAR(x[0], 3.0, 1e-12);
    EXPECT_NEAR(x[1], -1.0, 1e-12);
  }

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

  TEST(TrustRegion, ConvergesToTheMinimumNotTheMaximum)
  {
    // From z = 0.3 in the double well (negative curvature), full steps
    // converge to the maximum z = 0, the trust region to the minimum.
    const SeparablePotential potential = double_well(1);
    std::vector<double>      x;
    ASSERT_TRUE(solve(potential, {0.3}, "full step", x).converged);
    EXPECT_NEAR(x[0], 0.0, 1e-10);
    ASSERT_TRUE(solve(potential, {0.3}, "trust region", x).converged);
    EXPECT_NEAR(x[0], 1.0, 1e-10);
  }

  TEST(TrustRegion, RefusesAProblemWithoutPotential)
  {
    const SeparablePotential potential = double_well(1);
    NewtonSolver::Problem    problem   = potential.problem();
    problem.energy                     = nullptr;
    NewtonSolver::MatrixType tangent;
    rodnet::testing::diagonal_tangent(1, tangent);
    NewtonSolver::VectorType u(tangent.locally_owned_domain_indices(),
                               MPI_COMM_WORLD);
    NewtonSolver::Parameters parameters;
    parameters.line_search = "trust region";
    const NewtonSolver::Result result =
      NewtonSolver(parameters).solve(problem, u, tangent);
    EXPECT_FALSE(result.converged);
    EXPECT_NE(result.failure.find("trust region needs the potential"),
              std::string::npos)
      << result.failure;
  }
} // namespace
