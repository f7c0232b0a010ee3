// What probes.csv records over a run: a row for the unloaded state (step
// 0) under Newton, dynamic relaxation and time stepping with a preload,
// rotations continuous over the steps beyond a half turn, and units on the
// plot's axes.
#include <common/run_scene_text.h>
#include <common/scene_text.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The right-angle frame (legs of length 1 from the clamp at the origin
  /// to the corner (1, 0, 0) and on to the tip (1, 1, 0)), its clamp turned
  /// by 540 degrees about z in 12 steps of 45 degrees: with no load the
  /// frame turns rigidly.
  const std::string turning_frame =
    "subsection Geometry\n"
    "  set Generator = frame\n"
    "  set Segments = 4\n"
    "end\n" +
    direct_material("100") +
    "subsection Supports\n"
    "  set Prescribed rotations = clamp: 0,0,1 540\n"
    "end\n"
    "subsection Loads\n"
    "  set Steps = 12\n"
    "end\n"
    "subsection Output\n"
    "  set Write VTU = false\n"
    "  set Probes = clamp_turn: rotation clamp 0,0,1; corner_turn: rotation "
    "corner 0,0,1; tip_x: position @tip x; tip_y: position @tip y\n"
    "end\n";

  TEST(ProbeHistory, RotationsAreContinuousOverTurns)
  {
    const RunSummary run = run_scene_text(turning_frame, "probe_history_turn");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 13u);
    const std::size_t clamp  = probe_column(run, "clamp_turn"),
                      corner = probe_column(run, "corner_turn"),
                      x      = probe_column(run, "tip_x"),
                      y      = probe_column(run, "tip_y");
    for (unsigned int k = 0; k <= 12; ++k)
      {
        const std::vector<double> &row = run.rows[k];
        // The prescribed angle, 3 pi at the end: not wrapped into
        // (-2 pi, 2 pi].
        const double angle = 3 * M_PI * k / 12;
        EXPECT_NEAR(row[0], k / 12.0, 1e-14);
        EXPECT_NEAR(row[clamp], angle, 1e-9) << "step " << k;
        EXPECT_NEAR(row[corner], angle, 1e-6) << "step " << k;
        // The tip (1, 1, 0) turned by the angle.
        EXPECT_NEAR(row[x], std::cos(angle) - std::sin(angle), 1e-6);
        EXPECT_NEAR(row[y], std::sin(angle) + std::cos(angle), 1e-6);
      }
  }

  TEST(ProbeHistory, PlotAxesHaveUnits)
  {
    run_scene_text(turning_frame, "probe_history_units");
    std::ifstream      script("probe_history_units/probes.png.gp");
    std::ostringstream text;
    text << script.rdbuf();
    // Newton runs record which steps are stable: a frame turned rigidly
    // is stable at every step, which the title says (no panel, no key).
    for (const char *label : {"set xlabel 'load factor [-]'",
                              "set ylabel 'clamp_turn [rad]'",
                              "set ylabel 'tip_x [m]'",
                              "stable at every step"})
      EXPECT_NE(text.str().find(label), std::string::npos)
        << label << " missing in\n"
        << text.str();
  }

  /// A cantilever along x of length 1, tip force along y, solved by
  /// @p method.
  std::string
  cantilever(const std::string &method)
  {
    return "subsection Geometry\n"
           "  set Segments = 10\n"
           "  set Director d1 = 0, 0.6, 0.8\n"
           "end\n" +
           direct_material() +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Loads\n"
           "  set Steps = 2\n"
           "  set Point forces = end: 0, 0.01, 0\n"
           "end\n"
           "subsection Solver\n  set Method = " +
           method +
           "\nend\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = tip_x: position end x; tip_y: position end y; "
           "reaction_y: reaction start y; energy: energy\n"
           "end\n";
  }

  class UnloadedRow : public ::testing::TestWithParam<std::string>
  {
  };

  TEST_P(UnloadedRow, FirstRowIsTheUnloadedState)
  {
    const RunSummary run =
      run_scene_text(cantilever(GetParam()), "probe_history_" + GetParam());
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 3u);
    // Load factor 0: the tip where the straight rod ends, no reaction, no
    // energy; the steps after it bend the rod.
    const std::vector<double> expected = {0, 1, 0, 0, 0};
    for (std::size_t c = 0; c < expected.size(); ++c)
      EXPECT_NEAR(run.rows[0][c], expected[c], 1e-14) << "column " << c;
    EXPECT_GT(run.rows[2][probe_column(run, "tip_y")], 1e-3);
    std::ifstream csv("probe_history_" + GetParam() + "/probes.csv");
    std::string   header, first;
    std::getline(csv, header);
    std::getline(csv, first);
    // Newton rows end with the checks of the state, not made at step 0.
    EXPECT_EQ(first,
              GetParam() == "newton" ? "0,0,1,0,0,0,nan,nan" : "0,0,1,0,0,0");
  }

  TEST(ProbeHistory, PreloadedTimeSteppingStartsWithTheInitialState)
  {
    // Quasi-static time stepping from t = 0 to 1 in steps of 0.5 after a
    // preload of 1 s in 2 steps (h = 0.5): the preload's steps end at
    // t = -1 and -0.5, so the run starts from the initial state, the
    // straight unloaded rod (tip at (1, 0), no energy), at t = -1.5.
    const RunSummary run = run_scene_text(
      cantilever("time stepping") +
        "subsection Solver\n  subsection Time stepping\n"
        "    set Integrator = quasi-static\n    set Start time = 0\n"
        "    set End time = 1\n    set Time step = 0.5\n"
        "    set Preload time = 1\n    set Preload steps = 2\n  end\nend\n",
      "probe_history_preload");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 5u);
    const std::vector<double> expected = {-1.5, 1, 0, 0, 0};
    for (std::size_t c = 0; c < expected.size(); ++c)
      EXPECT_NEAR(run.rows[0][c], expected[c], 1e-14) << "column " << c;
    EXPECT_NEAR(run.rows[1][0], -1, 1e-14);
    EXPECT_GT(run.rows[1][probe_column(run, "tip_y")], 1e-3);
    std::ifstream csv("probe_history_preload/probes.csv");
    std::string   header, first;
    std::getline(csv, header);
    std::getline(csv, first);
    EXPECT_EQ(first.substr(0, 7), "0,-1.5,");
  }

  INSTANTIATE_TEST_SUITE_P(Methods,
                           UnloadedRow,
                           ::testing::Values("newton", "dynamic relaxation"),
                           [](const auto &info) {
                             return info.param == "newton" ?
                                      "newton" :
                                      "dynamic_relaxation";
                           });
} // namespace
