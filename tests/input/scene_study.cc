// Several scenes and parameter sweeps in one rodnet-run process
// (io/scene_study.h): the sweep syntax, each run's own setting against the
// cantilever formula w = P L^3 / (3 EI), the summary table, and the
// refusals (every scene is checked before the first run).
#include <common/run_driver.h>
#include <common/scene_text.h>
#include <io/scene_study.h>

#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>

namespace
{
  using rodnet::parse_sweep;
  using rodnet::testing::read_file;
  using rodnet::testing::run_driver_with;

  /// A cantilever of length 1 (midpoint clamp, 40 segments, EI = 1) under
  /// a tip force of @p force in z, probing the tip's z.
  std::string
  cantilever_scene(const std::string &force)
  {
    return "subsection Geometry\n"
           "  set Generator = straight\n"
           "  set Start = 0, 0, 0\n"
           "  set End = 1, 0, 0\n"
           "  set Segments = 40\n"
           "  set Clamp at first segment midpoint = true\n"
           "end\n" +
           rodnet::testing::direct_material(1e7, 1, 1, 1) +
           "subsection Supports\n"
           "  set Clamped ends = start\n"
           "end\n"
           "subsection Loads\n"
           "  set Steps = 1\n"
           "  set Point forces = end: 0, 0, " +
           force +
           "\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Probes = tip_z: position end z\n"
           "end\n";
  }

  /// Writes @p text to @p path; returns @p path.
  std::string
  write_scene_file(const std::string &path, const std::string &text)
  {
    std::ofstream(path) << text;
    return path;
  }

  /// The rows of a CSV file as fields (no quoting needed here).
  std::vector<std::vector<std::string>>
  read_csv(const std::string &path)
  {
    std::vector<std::vector<std::string>> rows;
    std::istringstream                    lines(read_file(path));
    for (std::string line; std::getline(lines, line);)
      {
        std::vector<std::string> fields;
        std::istringstream       cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
          fields.push_back(cell);
        rows.push_back(fields);
      }
    return rows;
  }

  TEST(SweepSyntax, RangesAndLists)
  {
    const rodnet::Sweep range = parse_sweep("Loads/Steps = 1:3:3");
    EXPECT_EQ(range.entry, "Loads/Steps");
    EXPECT_EQ(range.values, (std::vector<std::string>{"1", "2", "3"}));
    EXPECT_EQ(parse_sweep("A/b=0:1:5").values,
              (std::vector<std::string>{"0", "0.25", "0.5", "0.75", "1"}));
    EXPECT_EQ(parse_sweep("A/b=0.1, 0.2,0.4").values,
              (std::vector<std::string>{"0.1", "0.2", "0.4"}));
    // ';' separates values that hold commas themselves.
    EXPECT_EQ(parse_sweep("A/b=0, 0, 1; 0, 0, 2").values,
              (std::vector<std::string>{"0, 0, 1", "0, 0, 2"}));
  }

  TEST(SweepSyntax, MalformedSweepsAreRefused)
  {
    for (const char *bad : {"Loads/Steps",
                            "=1,2",
                            "A/b=",
                            "A/b=1:2",
                            "A/b=1:2:0",
                            "A/b=1:2:2.5",
                            "A/b=x:2:3",
                            "A/b=1,,2"})
      EXPECT_THROW(parse_sweep(bad), std::invalid_argument) << bad;
  }

  TEST(Study, SweepOfTheTipForceAgainstTheBeamFormula)
  {
    // w = P L^3 / (3 EI) with L = 1, EI = 1: each run has its own force
    // (relative error of the discrete, slightly nonlinear rod < 2e-3 at
    // P <= 2e-4).
    const std::string scene =
      write_scene_file("study_cantilever.prm", cantilever_scene("0"));
    std::filesystem::remove_all("out_sweep");
    const auto o = run_driver_with(
      scene + " --sweep \"Loads/Point forces=end: 0, 0, 1e-4; end: 0, 0, "
              "2e-4\" --output out_sweep");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    const auto rows = read_csv("out_sweep/summary.csv");
    ASSERT_EQ(rows.size(), 3u) << read_file("out_sweep/summary.csv");
    EXPECT_EQ(rows[0],
              (std::vector<std::string>{"run",
                                        "Loads/Point forces",
                                        "tip_z",
                                        "status",
                                        "converged_steps",
                                        "wall_time_s",
                                        "folder"}));
    for (unsigned int k = 1; k <= 2; ++k)
      {
        ASSERT_EQ(rows[k].size(), 7u);
        EXPECT_EQ(rows[k][3], "done");
        const double P = k * 1e-4;
        EXPECT_NEAR(std::stod(rows[k][2]), P / 3, 2e-3 * P / 3);
        EXPECT_TRUE(
          std::filesystem::exists("out_sweep/" + rows[k][6] + "/probes.csv"))
          << rows[k][6];
      }
    EXPECT_TRUE(std::filesystem::exists("out_sweep/summary.png"));
  }

  TEST(Study, NumericSweepIsTheAbscissa)
  {
    // Load steps 1, 2, 3: the same answer, as many converged steps as the
    // value, and the value in the parameter column.
    const std::string scene =
      write_scene_file("study_steps.prm", cantilever_scene("1e-4"));
    std::filesystem::remove_all("out_steps");
    const auto o =
      run_driver_with(scene + " --sweep Loads/Steps=1:3:3 --output out_steps");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    const auto rows = read_csv("out_steps/summary.csv");
    ASSERT_EQ(rows.size(), 4u);
    for (unsigned int k = 1; k <= 3; ++k)
      {
        EXPECT_EQ(std::stod(rows[k][1]), k);
        EXPECT_EQ(rows[k][4], std::to_string(k));
        EXPECT_NEAR(std::stod(rows[k][2]), 1e-4 / 3, 1e-7);
        EXPECT_EQ(rows[k][6],
                  std::to_string(k) + "_Steps=" + std::to_string(k));
      }
  }

  TEST(Study, SeveralScenesInOneProcess)
  {
    const std::string a =
      write_scene_file("study_a.prm", cantilever_scene("1e-4"));
    const std::string b =
      write_scene_file("study_b.prm", cantilever_scene("-2e-4"));
    std::filesystem::remove_all("out_two");
    const auto o = run_driver_with(a + " " + b + " --output out_two");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    const auto rows = read_csv("out_two/summary.csv");
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[1][6], "1_study_a");
    EXPECT_EQ(rows[2][6], "2_study_b");
    EXPECT_NEAR(std::stod(rows[1][2]), 1e-4 / 3, 1e-7);
    EXPECT_NEAR(std::stod(rows[2][2]), -2e-4 / 3, 2e-7);
  }

  TEST(Study, EveryRunIsCheckedBeforeTheFirst)
  {
    // The third value is refused by the entry's pattern: nothing runs.
    const std::string scene =
      write_scene_file("study_bad.prm", cantilever_scene("1e-4"));
    std::filesystem::remove_all("out_bad");
    auto o = run_driver_with(
      scene + " --sweep \"Loads/Steps=1,2,two\" --output out_bad");
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find("Steps=two"), std::string::npos) << o.output;
    EXPECT_NE(o.output.find("cannot set \"Loads/Steps\" to \"two\""),
              std::string::npos)
      << o.output;
    EXPECT_FALSE(std::filesystem::exists("out_bad"));

    o = run_driver_with(scene + " --sweep Loads/Stepz=1,2 --output out_bad");
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find("no entry \"Loads/Stepz\""), std::string::npos)
      << o.output;

    o = run_driver_with(scene + " missing.prm --output out_bad");
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find("missing.prm"), std::string::npos) << o.output;
    EXPECT_FALSE(std::filesystem::exists("out_bad"));

    o = run_driver_with(scene + " " + scene + " --sweep A/b=1,2");
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find("--sweep varies one scene"), std::string::npos)
      << o.output;
  }

  TEST(Study, AFailedRunDoesNotStopTheOthers)
  {
    // One Newton iteration cannot converge a step of P L^2 / EI = 0.3, nor
    // of half of it: the first run stops early (exit code 2), the second,
    // with 25, completes.
    const std::string scene =
      write_scene_file("study_fail.prm",
                       cantilever_scene("0.3") +
                         "subsection Solver\n"
                         "  set Minimum step fraction = 0.5\n"
                         "end\n");
    std::filesystem::remove_all("out_fail");
    const auto o = run_driver_with(
      scene + " --sweep \"Solver/Max iterations=1,25\" --output out_fail");
    EXPECT_EQ(o.exit_code, 2) << o.output;
    std::istringstream       lines(read_file("out_fail/summary.csv"));
    std::vector<std::string> rows;
    for (std::string line; std::getline(lines, line);)
      rows.push_back(line);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_NE(rows[1].find("stopped early"), std::string::npos) << rows[1];
    EXPECT_NE(rows[2].find(",done,"), std::string::npos) << rows[2];
  }
} // namespace
