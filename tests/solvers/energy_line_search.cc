// EnergyLineSearch (NewtonSolver's "energy" line search) on small potential
// problems with known minimizers, where full Newton steps fail.
#include <common/diagonal_tangent.h>
#include <common/separable_potential.h>
#include <solvers/newton_solver.h>

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using VectorType = NewtonSolver::VectorType;
  using MatrixType = NewtonSolver::MatrixType;
  using rodnet::testing::SeparablePotential;
  using rodnet::testing::solve;

  TEST(EnergyLineSearch, ConvergesWhereFullNewtonStepsDiverge)
  {
    // p(z) = sqrt(1 + z^2): a full Newton step maps z to -z^3, which
    // diverges from |z| > 1; the minimizer is z = 0, i.e. x = c.
    const SeparablePotential potential{
      [](double z) { return std::sqrt(1 + z * z); },
      [](double z) { return z / std::sqrt(1 + z * z); },
      [](double z) { return std::pow(1 + z * z, -1.5); },
      {1.0, -2.0, 0.5}};
    const std::vector<double> start = {4.0, -4.5, 2.0};

    std::vector<double> x;
    EXPECT_FALSE(solve(potential, start, "full step", x).converged);

    const NewtonSolver::Result result = solve(potential, start, "energy", x);
    ASSERT_TRUE(result.converged) << result.failure;
    for (unsigned int i = 0; i < 3; ++i)
      EXPECT_NEAR(x[i], potential.centre[i], 1e-11);
    // Quadratic convergence once the steps are full: a handful of
    // iterations, not a creep.
    EXPECT_LE(result.iterations, 12u);
  }

  TEST(EnergyLineSearch, TakesTheFullStepOnAQuadratic)
  {
    // p(z) = 3 z^2 / 2: Newton's first step is exact, and the line search
    // must accept it as it is.
    const SeparablePotential   potential{[](double z) { return 1.5 * z * z; },
                                       [](double z) { return 3 * z; },
                                       [](double) { return 3.0; },
                                       {0.25, -7.0}};
    std::vector<double>        x;
    const NewtonSolver::Result result =
      solve(potential, {10.0, 10.0}, "energy", x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_EQ(result.iterations, 1u);
    EXPECT_NEAR(x[0], 0.25, 1e-14);
    EXPECT_NEAR(x[1], -7.0, 1e-14);
  }

  TEST(EnergyLineSearch, GoesDownhillWhereTheNewtonStepClimbs)
  {
    // The double well p(z) = z^4 / 4 - z^2 / 2 from z = 0.3, where p'' < 0:
    // full Newton steps converge to the maximum z = 0; the energy line
    // search turns the climbing direction round and finds the minimum
    // z = 1 on that side.
    const SeparablePotential potential{[](double z) {
                                         return z * z * z * z / 4 - z * z / 2;
                                       },
                                       [](double z) { return z * z * z - z; },
                                       [](double z) { return 3 * z * z - 1; },
                                       {0.0}};
    std::vector<double>      x;
    ASSERT_TRUE(solve(potential, {0.3}, "full step", x).converged);
    EXPECT_NEAR(x[0], 0.0, 1e-12);

    const NewtonSolver::Result result = solve(potential, {0.3}, "energy", x);
    ASSERT_TRUE(result.converged) << result.failure;
    EXPECT_NEAR(x[0], 1.0, 1e-12);
  }

  TEST(EnergyLineSearch, NeedsThePotential)
  {
    // A problem without Problem::energy: one clear failure, no solve.
    SeparablePotential    potential{[](double z) { return z * z / 2; },
                                 [](double z) { return z; },
                                 [](double) { return 1.0; },
                                 {0.0}};
    NewtonSolver::Problem problem = potential.problem();
    problem.energy                = nullptr;
    MatrixType tangent;
    rodnet::testing::diagonal_tangent(1, tangent);
    VectorType u(tangent.locally_owned_domain_indices(), MPI_COMM_WORLD);
    NewtonSolver::Parameters parameters;
    parameters.line_search = "energy";
    const NewtonSolver::Result result =
      NewtonSolver(parameters).solve(problem, u, tangent);
    EXPECT_FALSE(result.converged);
    EXPECT_NE(result.failure.find("energy line search needs the potential"),
              std::string::npos);
  }
} // namespace
