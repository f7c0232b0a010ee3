// NewtonSolver: a residual that cannot be evaluated inside NOX (which turns
// our failure into a thrown C string) becomes a reported failure instead of
// aborting the process.
#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <solvers/newton/newton_solver.h>

#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace
{
  using namespace rodnet;

  /// Solves a two-DoF linear problem whose residual throws on its second
  /// evaluation (inside NOX's iterations, which turn our failure into a
  /// thrown C string) with @p line_search; what NOX printed meanwhile on
  /// std::cout and std::cerr into @p printed.
  NewtonSolver::Result
  solve_with_failing_residual(const std::string &line_search,
                              std::string       &printed)
  {
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
    NewtonSolver::Parameters parameters;
    parameters.line_search = line_search;
    std::ostringstream         captured;
    std::streambuf            *out = std::cout.rdbuf(captured.rdbuf());
    std::streambuf            *err = std::cerr.rdbuf(captured.rdbuf());
    const NewtonSolver::Result result =
      NewtonSolver(parameters).solve(problem, x, tangent);
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
    printed = captured.str();
    return result;
  }

  TEST(NewtonSolver, ResidualFailureInsideNoxIsReported)
  {
    // The solve returns unconverged with our message, with every line
    // search; NOX itself prints nothing (a backtracking search once printed
    // "NOX::LineSearch::BackTrack::compute - Unable to compute F" into a
    // run's output: a library's internal message, while the step that
    // follows recovers or reports the failure in our words).
    for (const std::string line_search : {"full step", "backtrack"})
      {
        std::string                printed;
        const NewtonSolver::Result result =
          solve_with_failing_residual(line_search, printed);
        EXPECT_FALSE(result.converged) << line_search;
        EXPECT_EQ(result.failure, "segment 7 flipped") << line_search;
        EXPECT_EQ(printed, "") << line_search;
      }
  }
} // namespace
