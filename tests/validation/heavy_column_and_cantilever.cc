// Heavy column (critical distributed load, VALIDATION.md) and the
// small-deflection cantilever (P L^3 / (3 EI)), through the scene format.
#include <common/run_scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// A clamped straight rod of unit length and B = 1 along x with the given
  /// loads and probes.
  std::string
  cantilever_scene(const std::string &kernel,
                   const std::string &loads,
                   const std::string &solver,
                   const std::string &probes)
  {
    return "subsection Geometry\n"
           "  set Segments = 100\n"
           "  set Clamp at first segment midpoint = true\n"
           "  set Director d1 = 0, 0, 1\n"
           "  set Hinge kernel = " +
           kernel +
           "\n"
           "end\n"
           "subsection Material\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = direct\n"
           "    set EA = 1e7\n"
           "    set EI1 = 1\n"
           "    set EI2 = 1\n"
           "    set GJ = 1\n"
           "  end\n"
           "end\n"
           "subsection Supports\n"
           "  set Clamped ends = start\n"
           "end\n"
           "subsection Loads\n" +
           loads +
           "end\n"
           "subsection Solver\n" +
           solver +
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = " +
           probes +
           "\n"
           "end\n";
  }

  class ClampedRod : public ::testing::TestWithParam<std::string>
  {
  };

  TEST_P(ClampedRod, HeavyColumnCriticalLoad)
  {
    // Distributed compressive dead load q up to 10 B/L^3; the lowest
    // eigenvalue crosses zero at q L^3/B = (9/4) j_{-1/3,1}^2 = 7.83735
    // (tolerance 1%, N = 100).
    const double     q_max = 10;
    const RunSummary run   = run_scene_text(
      cantilever_scene(
        GetParam(),
        "  set Steps = 10\n  set Distributed force = -10, 0, 0\n",
        "  set Critical load search = true\n",
        "tip_x: position end x"),
      "heavy_column_" + GetParam());
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double q_cr  = run.critical_load_factor * q_max;
    const double exact = 7.83735;
    std::cout << GetParam() << ": q_cr = " << q_cr << ", exact " << exact
              << ", relative error " << (q_cr - exact) / exact << std::endl;
    EXPECT_NEAR(q_cr, exact, 0.01 * exact);
  }

  TEST_P(ClampedRod, SmallDeflectionCantilever)
  {
    // Transverse tip load P = 1e-4 B/L^2: deflection P L^3/(3 EI), tip
    // rotation P L^2 / (2 EI) (tolerance 0.5%); the reaction at the clamp
    // balances the load.
    const double     P   = 1e-4;
    const RunSummary run = run_scene_text(
      cantilever_scene(
        GetParam(),
        "  set Steps = 1\n  set Point forces = end: 0, 0, -1e-4\n",
        "",
        "tip_z: position end z; before_tip_z: position -2 z; "
        "reaction_z: reaction start z"),
      "cantilever_" + GetParam());
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    // Step 0 (unloaded) and the one load step.
    ASSERT_EQ(run.rows.size(), 2u);
    const auto  &row        = run.rows[1];
    const double deflection = -row[probe_column(run, "tip_z")];
    std::cout << GetParam() << ": tip deflection " << deflection
              << ", P L^3/(3EI) = " << P / 3 << ", relative error "
              << (deflection - P / 3) / (P / 3) << std::endl;
    EXPECT_NEAR(deflection, P / 3, 0.005 * P / 3);
    // The last segment's slope: its midpoint sits at L - l/2, where the
    // exact slope is P/(2EI) (L^2 - (l/2)^2) to first order.
    const double l     = 1.0 / 99.5;
    const double slope = (row[probe_column(run, "before_tip_z")] -
                          row[probe_column(run, "tip_z")]) /
                         l;
    EXPECT_NEAR(slope, P / 2 * (1 - 0.25 * l * l), 0.005 * P / 2);
    EXPECT_NEAR(row[probe_column(run, "reaction_z")], P, 1e-6 * P);
  }

  INSTANTIATE_TEST_SUITE_P(HingeKernels,
                           ClampedRod,
                           ::testing::Values("simple", "classic"));
} // namespace
