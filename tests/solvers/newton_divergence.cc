// Newton stops a diverging solve early (DivergenceTest in
// solvers/newton/nox_line_search.cc): on r(x) = x with a Jacobian of the
// wrong sign, -1/2, each full step triples x, so the residual grows as
// 3^k and passes a million times its start at k = 13 (3^13 = 1.6e6). The
// solve stops after five such iterations in a row, at k = 17, with a
// failure that says so, instead of running to its 40 allowed iterations.
// The same problem with the right Jacobian converges in one step.
#include <common/diagonal_tangent.h>
#include <solvers/newton/newton_solver.h>

#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  NewtonSolver::Result
  solve_identity(const double jacobian, NewtonSolver::VectorType &x)
  {
    NewtonSolver::Problem problem;
    problem.residual = [](const NewtonSolver::VectorType &u,
                          NewtonSolver::VectorType       &r) { r = u; };
    problem.tangent  = [jacobian](const NewtonSolver::VectorType &,
                                 NewtonSolver::MatrixType &k) {
      k.set(0, 0, jacobian);
      k.compress(dealii::VectorOperation::insert);
    };
    NewtonSolver::MatrixType tangent;
    rodnet::testing::diagonal_tangent(1, tangent);
    x.reinit(tangent.locally_owned_domain_indices(), MPI_COMM_WORLD);
    x[0] = 1.0;
    x.compress(dealii::VectorOperation::insert);
    NewtonSolver::Parameters parameters;
    parameters.max_iterations = 40;
    return NewtonSolver(parameters).solve(problem, x, tangent);
  }

  TEST(NewtonDivergence, AGrowingResidualStopsTheSolveEarly)
  {
    NewtonSolver::VectorType   x;
    const NewtonSolver::Result result = solve_identity(-0.5, x);
    EXPECT_FALSE(result.converged);
    EXPECT_EQ(result.iterations, 17u);
    EXPECT_NE(result.failure.find("Newton diverges from this start"),
              std::string::npos)
      << result.failure;
    EXPECT_NEAR(result.residual_norm, 129140163.0, 1e-6 * 129140163.0)
      << "3^17";
  }

  TEST(NewtonDivergence, TheRightJacobianConvergesInOneStep)
  {
    NewtonSolver::VectorType   x;
    const NewtonSolver::Result result = solve_identity(1.0, x);
    EXPECT_TRUE(result.converged) << result.failure;
    EXPECT_EQ(result.iterations, 1u);
  }
} // namespace
