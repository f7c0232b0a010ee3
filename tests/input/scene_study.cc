// Several scenes and parameter sweeps in one rodnet-run process
// (app/scene_study.h): the sweep syntax, each run's own setting against the
// cantilever formula w = P L^3 / (3 EI), the summary table, and the
// refusals (every scene is checked before the first run).
#include <common/run_driver.h>
#include <common/scene_text.h>
#include <io/csv_table.h>
#include <io/scene_help.h>
#include <app/scene_study.h>

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

  /// The field of summary row @p r (from 0) in the column @p name.
  std::string
  field(const rodnet::CsvTable &summary,
        const std::size_t       r,
        const std::string      &name)
  {
    const auto column = summary.column(name);
    EXPECT_TRUE(column) << "no column " << name;
    return column ? summary.text(r, *column) : "";
  }

  /// The same as a number.
  double
  number(const rodnet::CsvTable &summary,
         const std::size_t       r,
         const std::string      &name)
  {
    return std::stod(field(summary, r, name));
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
    const auto summary = rodnet::read_csv_table("out_sweep/summary.csv");
    ASSERT_EQ(summary.rows.size(), 2u) << read_file("out_sweep/summary.csv");
    EXPECT_EQ(summary.names,
              (std::vector<std::string>{"run",
                                        "Loads/Point forces",
                                        "tip_z",
                                        "load_factor",
                                        "stable",
                                        "finished",
                                        "exit_code",
                                        "status",
                                        "converged_steps",
                                        "wall_time_s",
                                        "folder"}));
    for (unsigned int k = 0; k < 2; ++k)
      {
        ASSERT_EQ(summary.rows[k].size(), summary.names.size());
        // The value swept, as given: not a number.
        EXPECT_EQ(field(summary, k, "Loads/Point forces"),
                  k == 0 ? "end: 0, 0, 1e-4" : "end: 0, 0, 2e-4");
        EXPECT_EQ(field(summary, k, "status"), "done");
        const double P = (k + 1) * 1e-4;
        EXPECT_NEAR(number(summary, k, "tip_z"), P / 3, 2e-3 * P / 3);
        const std::string folder = field(summary, k, "folder");
        EXPECT_TRUE(
          std::filesystem::exists("out_sweep/" + folder + "/probes.csv"))
          << folder;
      }
    EXPECT_TRUE(std::filesystem::exists("out_sweep/summary.png"));
    // Against the run's number, each tic labelled with its value.
    EXPECT_NE(read_file("out_sweep/summary.png.gp")
                .find("set xtics ('end: 0, 0, 1e-4' 1, 'end: 0, 0, 2e-4' 2)"),
              std::string::npos)
      << read_file("out_sweep/summary.png.gp");
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
    const auto summary = rodnet::read_csv_table("out_steps/summary.csv");
    ASSERT_EQ(summary.rows.size(), 3u);
    for (unsigned int k = 1; k <= 3; ++k)
      {
        EXPECT_EQ(number(summary, k - 1, "Loads/Steps"), k);
        EXPECT_EQ(number(summary, k - 1, "converged_steps"), k);
        EXPECT_NEAR(number(summary, k - 1, "tip_z"), 1e-4 / 3, 1e-7);
        EXPECT_EQ(field(summary, k - 1, "folder"),
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
    const auto summary = rodnet::read_csv_table("out_two/summary.csv");
    ASSERT_EQ(summary.rows.size(), 2u);
    EXPECT_EQ(field(summary, 0, "scene"), "study_a");
    EXPECT_EQ(field(summary, 1, "scene"), "study_b");
    EXPECT_EQ(field(summary, 0, "folder"), "1_study_a");
    EXPECT_EQ(field(summary, 1, "folder"), "2_study_b");
    EXPECT_NEAR(number(summary, 0, "tip_z"), 1e-4 / 3, 1e-7);
    EXPECT_NEAR(number(summary, 1, "tip_z"), -2e-4 / 3, 2e-7);
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
    // of half of it: the first run stops early (exit code 2) in its first
    // step, at load factor 0 (the unloaded state, which is not checked for
    // stability); the second, with 25, completes at load factor 1 with a
    // stable equilibrium whose tip deflects by 0.09899 L (the inextensible
    // elastica EI theta'' = -P cos theta, theta(0) = theta'(L) = 0, solved
    // by shooting with RK4; 0.1 L in linear theory). The summary says which
    // run finished, and its plot draws the other as such.
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
    const auto summary = rodnet::read_csv_table("out_fail/summary.csv");
    ASSERT_EQ(summary.rows.size(), 2u);
    EXPECT_EQ(field(summary, 0, "status").substr(0, 13), "stopped early");
    EXPECT_EQ(field(summary, 0, "finished"), "0");
    EXPECT_EQ(field(summary, 0, "exit_code"), "2");
    EXPECT_EQ(number(summary, 0, "load_factor"), 0);
    EXPECT_EQ(field(summary, 0, "stable"), "");
    EXPECT_EQ(number(summary, 0, "tip_z"), 0);
    EXPECT_EQ(field(summary, 1, "status"), "done");
    EXPECT_EQ(field(summary, 1, "finished"), "1");
    EXPECT_EQ(field(summary, 1, "exit_code"), "0");
    EXPECT_EQ(number(summary, 1, "load_factor"), 1);
    EXPECT_EQ(field(summary, 1, "stable"), "1");
    EXPECT_NEAR(number(summary, 1, "tip_z"), 0.09899, 2e-3 * 0.09899);
    // The run that stopped early has its own marker ("stopped early" in
    // the key), at its number of iterations, 1.
    const std::string script = read_file("out_fail/summary.png.gp");
    EXPECT_NE(script.find("$unfinished << EOD\n1 0"), std::string::npos)
      << script;
    EXPECT_NE(script.find("title 'stopped early'"), std::string::npos);
  }

  TEST(Study, RadiusSweepIsLabelledInMetres)
  {
    // A steel cantilever (L = 1 m, E = 2e11 Pa, circular section of radius
    // r) under a tip force of 1 N: w = P L^3 / (3 E pi r^4 / 4) against the
    // radius, on an axis labelled with the entry's unit.
    std::string       text   = cantilever_scene("-1");
    const std::string direct = rodnet::testing::direct_material(1e7, 1, 1, 1);
    text.replace(text.find(direct),
                 direct.size(),
                 "subsection Material\n  subsection linear elastic\n"
                 "    set Young's modulus = 2e11\n"
                 "    set Cross section = circle\n"
                 "    set Radius = 0.01\n  end\nend\n");
    const std::string scene = write_scene_file("study_radius.prm", text);
    std::filesystem::remove_all("out_radius");
    const auto o = run_driver_with(
      scene + " --sweep \"Material/linear elastic/Radius=0.005:0.01:3\" "
              "--output out_radius");
    ASSERT_EQ(o.exit_code, 0) << o.output;
    const auto summary = rodnet::read_csv_table("out_radius/summary.csv");
    ASSERT_EQ(summary.rows.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k)
      {
        const double r = number(summary, k, "Material/linear elastic/Radius");
        EXPECT_NEAR(r, 0.005 + 0.0025 * k, 1e-15);
        const double w = 1 / (3 * 2e11 * M_PI * std::pow(r, 4) / 4);
        EXPECT_NEAR(number(summary, k, "tip_z"), -w, 2e-3 * w);
      }
    EXPECT_NE(read_file("out_radius/summary.png.gp")
                .find("set xlabel 'Material/linear elastic/Radius [m]'"),
              std::string::npos)
      << read_file("out_radius/summary.png.gp");
  }

  TEST(SweepAxis, EntryUnitsComeFromTheHelp)
  {
    EXPECT_EQ(rodnet::entry_unit("Geometry/Radius"), "m");
    EXPECT_EQ(rodnet::entry_unit("Loads/Steps"), "-");
    EXPECT_EQ(rodnet::entry_unit("Loads/Point forces"), "N");
    EXPECT_EQ(rodnet::entry_unit("Material/linear elastic/Radius"), "m");
    EXPECT_EQ(rodnet::entry_unit("Material/linear elastic/Young's modulus"),
              "Pa");
    EXPECT_EQ(rodnet::entry_unit("Material/linear elastic/EI1"), "N m^2");
    EXPECT_EQ(rodnet::entry_unit("Material/linear elastic/Natural curvature 1"),
              "1/m");
    EXPECT_EQ(rodnet::entry_unit("Material/linear elastic/Poisson's ratio"),
              "-");
    EXPECT_EQ(rodnet::entry_unit("Geometry/Nonexistent"), "");
    EXPECT_EQ(rodnet::entry_unit("Geometry"), "");
  }
} // namespace
