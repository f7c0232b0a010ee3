// Solver/Max step time: a load step that keeps failing stops the run once
// it has taken longer than the bound, instead of cutting on to the minimum
// step. The column of tests/input/bad_scenes.cc ("solver_failure"), loaded
// past its buckling load in steps that Newton, limited to 4 iterations and
// without a predictor, cannot cross: with the bound of a microsecond the
// run stops at the first failed attempt, with exit code 2 and a message
// naming the bound, after the converged steps before it (their probes
// written); without it, the same step is cut several times.
#include <common/run_driver.h>
#include <common/scene_text.h>

#include <gtest/gtest.h>
#include <string>

namespace
{
  std::string
  buckling_column(const std::string &step_time)
  {
    return "subsection Geometry\n  set Segments = 50\n"
           "  set Director d1 = 0, 0, 1\nend\n" +
           rodnet::testing::direct_material() +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Loads\n  set Steps = 10\n"
           "  set Point forces = end: -10, 1e-3, 0\nend\n"
           "subsection Solver\n  set Max iterations = 4\n"
           "  set Predictor = false\n  set Minimum step fraction = 0.0625\n"
           "  set Branch switching amplitude = 0\n"
           "  set Max step time = " +
           step_time +
           "\nend\n"
           "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
           "  set Probes = tip_y: position end y\nend\n";
  }

  std::size_t
  count(const std::string &text, const std::string &part)
  {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos;
         at      = text.find(part, at + 1))
      ++n;
    return n;
  }

  TEST(StepTimeBound, AStepThatKeepsFailingStopsAtTheBound)
  {
    const rodnet::testing::DriverOutcome bounded =
      rodnet::testing::run_driver("bounded_step", buckling_column("1e-6"));
    ASSERT_EQ(bounded.exit_code, 2) << bounded.output;
    EXPECT_NE(bounded.output.find("more than Solver/Max step time = 1e-06 s"),
              std::string::npos)
      << bounded.output;
    EXPECT_EQ(count(bounded.output, "cutting the step"), 0u) << bounded.output;
    const std::string probes =
      rodnet::testing::read_file("out_bounded_step/probes.csv");
    EXPECT_GE(count(probes, "\n"), 3u) << "the header, step 0 and a step";

    const rodnet::testing::DriverOutcome unbounded =
      rodnet::testing::run_driver("unbounded_step", buckling_column("0"));
    ASSERT_EQ(unbounded.exit_code, 2) << unbounded.output;
    EXPECT_GE(count(unbounded.output, "cutting the step"), 2u)
      << unbounded.output;
    EXPECT_EQ(unbounded.output.find("Max step time"), std::string::npos)
      << unbounded.output;
  }
} // namespace
