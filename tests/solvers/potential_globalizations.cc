// The two globalizations on the potential, NewtonSolver's "energy" line
// search (EnergyLineSearch) and "trust region" (TrustRegionNewton), on small
// potential problems with known minimizers where full Newton steps fail, on
// a quadratic where they must not get in the way, and without a potential.
#include <common/diagonal_tangent.h>
#include <common/separable_potential.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using rodnet::testing::SeparablePotential;
  using rodnet::testing::solve;

  /// A globalization, the most iterations it may take from where full
  /// steps diverge, and the words of its refusal without a potential.
  struct Globalization
  {
    std::string  line_search;
    unsigned int max_iterations;
    std::string  refusal;
  };

  std::ostream &
  operator<<(std::ostream &out, const Globalization &g)
  {
    return out << g.line_search;
  }

  class PotentialGlobalization : public ::testing::TestWithParam<Globalization>
  {
  };

  TEST_P(PotentialGlobalization, ConvergesWhereFullNewtonStepsDiverge)
  {
    // p(z) = sqrt(1 + z^2): a full Newton step maps z to -z^3, which
    // diverges from |z| > 1; the minimizer is z = 0, i.e. x = c. Once the
    // steps are full, quadratic convergence: a handful of iterations (the
    // energy line search), a few more for the trust region's radius to grow.
    const SeparablePotential potential{
      [](double z) { return std::sqrt(1 + z * z); },
      [](double z) { return z / std::sqrt(1 + z * z); },
      [](double z) { return std::pow(1 + z * z, -1.5); },
      {1.0, -2.0, 0.5}};
    const std::vector<double> start = {4.0, -4.5, 2.0};

    std::vector<double> x;
    EXPECT_FALSE(solve(potential, start, "full step", x).converged);

    const NewtonSolver::Result result =
      solve(potential, start, GetParam().line_search, x);
    ASSERT_TRUE(result.converged) << result.failure;
    for (unsigned int i = 0; i < 3; ++i)
      EXPECT_NEAR(x[i], potential.centre[i], 1e-11);
    EXPECT_LE(result.iterations, GetParam().max_iterations);
  }

  TEST_P(PotentialGlobalization, TakesTheNewtonStepOnAQuadratic)
  {
    // p(z) = 3 z^2 / 2: Newton's first step is exact, and the globalization
    // must accept it as it is.
    const SeparablePotential   potential{[](double z) { return 1.5 * z * z; },
                                       [](double z) { return 3 * z; },
                                       [](double) { return 3.0; },
                                       {0.25, -7.0}};
    std::vector<double>        x;
    const NewtonSolver::Result result =
      solve(potential, {10.0, 10.0}, GetParam().line_search, x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_EQ(result.iterations, 1u);
    EXPECT_NEAR(x[0], 0.25, 1e-14);
    EXPECT_NEAR(x[1], -7.0, 1e-14);
  }

  TEST_P(PotentialGlobalization, GoesDownhillWhereTheNewtonStepClimbs)
  {
    // The double well from z = 0.3, where p'' < 0: full Newton steps
    // converge to the maximum z = 0; the energy line search turns the
    // climbing direction round, the trust region's step turns along the
    // negative curvature, and both find the minimum z = 1 on that side.
    const SeparablePotential potential = rodnet::testing::double_well(1);
    std::vector<double>      x;
    ASSERT_TRUE(solve(potential, {0.3}, "full step", x).converged);
    EXPECT_NEAR(x[0], 0.0, 1e-12);

    const NewtonSolver::Result result =
      solve(potential, {0.3}, GetParam().line_search, x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_NEAR(x[0], 1.0, 1e-12);
  }

  TEST_P(PotentialGlobalization, NeedsThePotential)
  {
    // A problem without Problem::energy: one clear failure, no solve.
    const SeparablePotential potential = rodnet::testing::double_well(1);
    NewtonSolver::Problem    problem   = potential.problem();
    problem.energy                     = nullptr;
    NewtonSolver::MatrixType tangent;
    rodnet::testing::diagonal_tangent(1, tangent);
    NewtonSolver::VectorType u(tangent.locally_owned_domain_indices(),
                               MPI_COMM_WORLD);
    NewtonSolver::Parameters parameters;
    parameters.line_search = GetParam().line_search;
    const NewtonSolver::Result result =
      NewtonSolver(parameters).solve(problem, u, tangent);
    EXPECT_FALSE(result.converged);
    EXPECT_NE(result.failure.find(GetParam().refusal), std::string::npos)
      << result.failure;
  }

  INSTANTIATE_TEST_SUITE_P(
    OnThePotential,
    PotentialGlobalization,
    ::testing::Values(
      Globalization{"energy", 12, "energy line search needs the potential"},
      Globalization{"trust region", 30, "trust region needs the potential"}));
} // namespace
