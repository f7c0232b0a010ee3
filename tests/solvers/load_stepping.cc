// Load stepping of StaticSolver: the predictor keeps a displacement-driven
// network converging in its nominal steps without changing the answer, and
// a residual that cannot be evaluated inside NOX becomes a reported failure
// instead of aborting the process.
#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <common/run_scene_text.h>
#include <solvers/newton_solver.h>

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The right-angle frame of scenes/frame.prm, N segments per leg, its tip
  /// moved out of plane by u_z = L in 20 steps.
  std::string
  frame_scene(const unsigned int n, const bool predictor)
  {
    return "subsection Geometry\n"
           "  set Generator = frame\n"
           "  set Segments = " +
           std::to_string(n) +
           "\n"
           "  set Director d1 = 0, 0, 1\n"
           "end\n"
           "subsection Material\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = direct\n"
           "    set EA = 400\n"
           "    set EI1 = 1\n"
           "    set EI2 = 1\n"
           "    set GJ = 0.6666666666666667\n"
           "  end\n"
           "end\n"
           "subsection Supports\n"
           "  set Prescribed displacements = @tip: z=1\n"
           "end\n"
           "subsection Loads\n"
           "  set Steps = 20\n"
           "end\n"
           "subsection Solver\n"
           "  set Predictor = " +
           std::string(predictor ? "true" : "false") +
           "\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = force_z: reaction @tip z\n"
           "end\n";
  }

  TEST(LoadStepping, PredictorKeepsNominalStepsAndTheAnswer)
  {
    // Without the predictor the first iterate of each step stretches the
    // tip segment by u_z / 20 = 2.5 segment lengths at N = 40 and the steps
    // are cut; with it every nominal step converges as it is. Both runs
    // reach the same equilibrium (to the Newton tolerance, 1e-9 of the
    // force scale).
    const RunSummary predicted =
      run_scene_text(frame_scene(40, true), "load_stepping_predicted");
    const RunSummary plain =
      run_scene_text(frame_scene(40, false), "load_stepping_plain");
    ASSERT_TRUE(predicted.failure.empty()) << predicted.failure;
    ASSERT_TRUE(plain.failure.empty()) << plain.failure;
    EXPECT_EQ(predicted.rows.size(), 20u);
    EXPECT_GT(plain.rows.size(), 20u);
    const std::size_t f = probe_column(predicted, "force_z");
    // Cut steps never skip a point of the load grid k / 20: every one has
    // its row, to rounding (the sum of cut steps is snapped onto it).
    for (unsigned int k = 1; k <= 20; ++k)
      {
        bool found = false;
        for (const auto &row : plain.rows)
          found = found || std::abs(row[0] - k / 20.0) < 1e-14;
        EXPECT_TRUE(found) << "no row at load factor " << k / 20.0;
      }
    EXPECT_NEAR(predicted.rows.back()[f], plain.rows.back()[f], 1e-7);
    // And the value is the frame's (doc/junctions.md, N = 40: 0.851074).
    EXPECT_NEAR(predicted.rows.back()[f], 0.851074, 1e-6);
  }

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
