// NewtonSolver: a residual that cannot be evaluated inside NOX (which turns
// our failure into a thrown C string) becomes a reported failure instead of
// aborting the process.
#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <solvers/newton_solver.h>

#include <gtest/gtest.h>
#include <stdexcept>

namespace
{
  using namespace rodnet;

  TEST(NewtonSolver, ResidualFailureInsideNoxIsReported)
  {
    // A two-DoF linear problem whose residual throws on its second
    // evaluation (inside NOX's iterations, which turn our failure into a
    // thrown C string): the solve returns unconverged with our message.
    using VectorType = NewtonSolver::VectorType;
    using MatrixType = NewtonSolver::MatrixType;
    dealii::IndexSet all(2);
    all.add_range(0, 2);
    dealii::TrilinosWrappers::SparsityPattern pattern(all, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        pattern.add(i, j);
    pattern.compress();
    MatrixType tangent;
    tangent.reinit(pattern);
    VectorType x(all, MPI_COMM_WORLD);

    unsigned int          calls = 0;
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &y, VectorType &r) {
      if (++calls > 1)
        throw std::runtime_error("segment 7 flipped");
      r    = y;
      r[0] = y[0] - 1.0;
      r.compress(dealii::VectorOperation::insert);
    };
    problem.tangent = [](const VectorType &, MatrixType &k) {
      k = 0;
      k.set(0, 0, 1.0);
      k.set(1, 1, 1.0);
      k.compress(dealii::VectorOperation::insert);
    };
    const NewtonSolver::Result result =
      NewtonSolver(NewtonSolver::Parameters()).solve(problem, x, tangent);
    EXPECT_FALSE(result.converged);
    EXPECT_EQ(result.failure, "segment 7 flipped");
  }
} // namespace
