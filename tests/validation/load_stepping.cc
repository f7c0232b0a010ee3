// Load stepping of StaticSolver on the right-angle frame (scenes/frame.prm):
// the predictor keeps a displacement-driven network converging in its
// nominal steps without changing the answer, and cut steps still land on the
// load grid. In the validation set: the run without predictor is what the
// predictor saves, too slow for the Debug library.
#include <common/run_scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
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
    // Step 0 and the 20 load steps.
    EXPECT_EQ(predicted.rows.size(), 21u);
    EXPECT_GT(plain.rows.size(), 21u);
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
} // namespace
