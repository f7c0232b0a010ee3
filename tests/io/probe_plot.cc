// plot_probes turns a probe table into a PNG fit to show and never throws:
// a panel for each probe that varies, notes for what does not (constants,
// rounding noise, checks that hold throughout), unstable states dashed,
// lines broken between branches and at jumps, never through a limit
// point. The plan (plan_probe_plot) and the gnuplot script with its data
// blocks are checked, not the pixels; the runs of a Newton and of a
// continuation scene check what rodnet-run's probes.png is drawn from.
#include <common/run_scene_text.h>
#include <common/scene_text.h>
#include <io/probe_plot.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
  namespace fs = std::filesystem;
  using namespace rodnet;
  using namespace rodnet::testing;
  using Piece = std::vector<std::vector<double>>;

  bool
  gnuplot_is_there()
  {
    const char *path = std::getenv("PATH");
    if (path == nullptr)
      return false;
    std::istringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');)
      if (!dir.empty() && access((dir + "/gnuplot").c_str(), X_OK) == 0)
        return true;
    return false;
  }

  std::string
  text_of(const fs::path &path)
  {
    std::ifstream      file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }

  /// A fresh directory @p name for a test's files.
  fs::path
  fresh_directory(const std::string &name)
  {
    const fs::path dir = fs::path("probe_plot_tests") / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
  }

  /// The pieces of data block @p name of @p script: rows of numbers, a
  /// new piece after each blank line ("NaN" reads as NaN).
  std::vector<Piece>
  data_pieces(const std::string &script, const std::string &name)
  {
    const std::size_t begin = script.find(name + " << EOD\n");
    EXPECT_NE(begin, std::string::npos) << name << " missing in\n" << script;
    std::istringstream lines(script.substr(begin));
    std::string        line;
    std::getline(lines, line);
    std::vector<Piece> pieces(1);
    while (std::getline(lines, line) && line != "EOD")
      {
        if (line.empty())
          {
            pieces.emplace_back();
            continue;
          }
        std::istringstream  fields(line);
        std::vector<double> row;
        for (std::string field; fields >> field;)
          row.push_back(std::strtod(field.c_str(), nullptr));
        pieces.back().push_back(row);
      }
    if (pieces.back().empty())
      pieces.pop_back();
    return pieces;
  }

  /// The plan of the table @p csv (written to @p dir/probes.csv).
  ProbePlotPlan
  plan_of(const fs::path         &dir,
          const std::string      &csv,
          const ProbePlotOptions &options)
  {
    std::ofstream(dir / "probes.csv") << csv;
    return plan_probe_plot(read_csv_table((dir / "probes.csv").string()),
                           options);
  }

  /// The script of the plot of @p dir/probes.csv, which must succeed.
  std::string
  plotted_script(const fs::path &dir, const ProbePlotOptions &options)
  {
    EXPECT_TRUE(plot_probes((dir / "probes.csv").string(),
                            (dir / "probes.png").string(),
                            options));
    return text_of(dir / "probes.png.gp");
  }

  bool
  has_note(const ProbePlotPlan &plan, const std::string &note)
  {
    return std::find(plan.notes.begin(), plan.notes.end(), note) !=
           plan.notes.end();
  }

  TEST(ProbePlot, MakesPng)
  {
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const fs::path dir = fresh_directory("png");
    // Names with a blank, a quoted comma and gnuplot's quote character.
    std::ofstream(dir / "probes.csv")
      << "step,load_factor,tip x,\"a,b\",it's_y\n"
      << "0,0,0,1,5\n1,0.5,0.1,2,4\n2,1,0.3,2.5,nan\n";
    const fs::path   png = dir / "probes.png";
    ProbePlotOptions options;
    options.title = "it's a test";
    ::testing::internal::CaptureStderr();
    EXPECT_TRUE(plot_probes((dir / "probes.csv").string(), png, options));
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    ASSERT_TRUE(fs::exists(png));
    EXPECT_EQ(text_of(png).substr(1, 3), "PNG");
    const std::string script = text_of(dir / "probes.png.gp");
    for (const char *label :
         {"set ylabel 'tip x'", "set ylabel 'a,b'", "set ylabel 'it''s_y'"})
      EXPECT_NE(script.find(label), std::string::npos) << label;
  }

  TEST(ProbePlot, ConstantsAndRoundingNoiseAreNotesNotPanels)
  {
    // The positions' scale is 5 m (w's magnitude, above the length scale
    // 2 m): z varies by 1.1e-16 m and w by 4e-10 m, below 1e-10 of it; y
    // by 6e-10 m and x by 1 m, above it. The reaction r2 varies by 1.1e-13
    // N against r1's 3 N; r1 itself varies. The checks hold at every
    // checked row (step 0 is not checked): no panel for them either.
    const fs::path   dir = fresh_directory("constants");
    ProbePlotOptions options;
    options.units        = {"-", "m", "m", "m", "m", "N", "N"};
    options.n_probes     = 6;
    options.length_scale = 2;
    const ProbePlotPlan plan =
      plan_of(dir,
              "step,load_factor,x,y,z,w,r1,r2,stable,in_range\n"
              "0,0,1,0,1e-16,5,0,0,nan,nan\n"
              "1,0.5,1.5,6e-10,0,5.0000000004,1,1e-13,1,1\n"
              "2,1,2,4e-10,-1e-17,5,3,-1e-14,1,1\n",
              options);
    std::vector<std::string> labels;
    for (const auto &panel : plan.panels)
      labels.push_back(panel.label);
    EXPECT_EQ(labels, (std::vector<std::string>{"x [m]", "y [m]", "r1 [N]"}));
    for (const char *note : {"z = 0 m",
                             "w = 5 m",
                             "r2 = 0 N",
                             "stable at every step",
                             "strains within the rod model's range at every "
                             "step"})
      EXPECT_TRUE(has_note(plan, note)) << note;
    EXPECT_EQ(plan.x_label, "load factor [-]");
    // Step 0 is drawn: the line runs from load factor 0.
    ASSERT_EQ(plan.stable_lines.size(), 1u);
    EXPECT_EQ(plan.stable_lines[0], (ProbePlotPlan::Rows{0, 1, 2}));
    EXPECT_TRUE(plan.unstable_lines.empty());
  }

  TEST(ProbePlot, UnstableStatesAreDashedAndMarked)
  {
    // Stable, stable, unstable, unstable, stable: the pieces next to an
    // unstable state are dashed, and its points are the open red ones.
    const fs::path   dir = fresh_directory("unstable");
    ProbePlotOptions options;
    options.n_probes = 1;
    const std::string csv =
      "step,load_factor,y,stable,in_range\n"
      "0,0,0,nan,nan\n1,1,1,1,1\n2,2,3,0,1\n3,1.5,4,0,0\n4,1,5,1,1\n";
    const ProbePlotPlan plan = plan_of(dir, csv, options);
    EXPECT_EQ(plan.stable_lines, (std::vector<ProbePlotPlan::Rows>{{0, 1}}));
    EXPECT_EQ(plan.unstable_lines,
              (std::vector<ProbePlotPlan::Rows>{{1, 2, 3, 4}}));
    EXPECT_EQ(plan.unstable_points, (ProbePlotPlan::Rows{2, 3}));
    EXPECT_EQ(plan.stable_points, (ProbePlotPlan::Rows{0, 1, 4}));
    EXPECT_EQ(plan.out_of_range, (ProbePlotPlan::Rows{3}));
    EXPECT_FALSE(has_note(plan, "stable at every step"));
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const std::string script = plotted_script(dir, options);
    for (const char *key :
         {"title 'stable'", "title 'unstable'", "title 'strain out of range'"})
      EXPECT_NE(script.find(key), std::string::npos) << key;
    EXPECT_EQ(data_pieces(script, "$unstable_lines"),
              (std::vector<Piece>{{{1, 1}, {2, 3}, {1.5, 4}, {1, 5}}}));
  }

  TEST(ProbePlot, BranchesAndJumpsBreakLines)
  {
    // A continuation table: branch 0 to its bifurcation at load factor 1,
    // branch 1 leaving it (joined: its arclength goes on from there), then
    // branch 2, the bifurcation's other side, restarting at arclength 1
    // (not joined to the end of branch 1), whose last row is reached by a
    // jump: a dotted arrow, no line.
    const fs::path   dir = fresh_directory("branches");
    ProbePlotOptions options;
    options.n_probes = 1;
    const std::string csv =
      "step,load_factor,y,arclength,branch,negative_eigenvalues,stable,"
      "in_range,jump\n"
      "0,0,0,0,0,0,1,1,0\n1,1,0,1,0,0,1,1,0\n2,2,0.8,2,1,0,1,1,0\n"
      "3,1,0,1,2,0,1,1,0\n4,2,-0.8,2,2,0,1,1,0\n5,2,-3,2.5,2,0,1,1,1\n";
    const ProbePlotPlan plan = plan_of(dir, csv, options);
    EXPECT_EQ(plan.stable_lines,
              (std::vector<ProbePlotPlan::Rows>{{0, 1, 2}, {3, 4}}));
    ASSERT_EQ(plan.jumps.size(), 1u);
    EXPECT_EQ(plan.jumps[0], std::make_pair(std::size_t(4), std::size_t(5)));
    // No panel for the path's own columns.
    ASSERT_EQ(plan.panels.size(), 1u);
    EXPECT_EQ(plan.panels[0].label, "y");
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const std::string script = plotted_script(dir, options);
    EXPECT_EQ(data_pieces(script, "$stable_lines"),
              (std::vector<Piece>{{{0, 0}, {1, 0}, {2, 0.8}},
                                  {{1, 0}, {2, -0.8}}}));
    EXPECT_EQ(data_pieces(script, "$jumps"),
              (std::vector<Piece>{{{2, -0.8, 2, -3}}}));
    EXPECT_NE(script.find("title 'jump'"), std::string::npos);
  }

  TEST(ProbePlot, WarnsOnceAndReturnsWhenItCannotPlot)
  {
    const fs::path dir = fresh_directory("no_plot");
    ::testing::internal::CaptureStderr();
    EXPECT_FALSE(plot_probes((dir / "missing.csv").string(),
                             (dir / "missing.png").string()));
    std::string messages = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(messages.find("warning"), std::string::npos);
    EXPECT_EQ(std::count(messages.begin(), messages.end(), '\n'), 1);

    // Nothing varies: nothing to draw, and the warning says what is.
    std::ofstream(dir / "flat.csv") << "step,load_factor,x\n0,0,1\n1,1,1\n";
    ::testing::internal::CaptureStderr();
    EXPECT_FALSE(
      plot_probes((dir / "flat.csv").string(), (dir / "flat.png").string()));
    messages = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(messages.find("no probe varies (x = 1)"), std::string::npos)
      << messages;

    // Without gnuplot on PATH.
    std::ofstream(dir / "probes.csv") << "step,load_factor,x\n0,0,1\n1,1,2\n";
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    setenv("PATH", dir.c_str(), 1);
    ::testing::internal::CaptureStderr();
    plot_probes((dir / "probes.csv").string(), (dir / "probes.png").string());
    messages = ::testing::internal::GetCapturedStderr();
    setenv("PATH", path.c_str(), 1);
    EXPECT_NE(messages.find("gnuplot"), std::string::npos) << messages;
    EXPECT_EQ(std::count(messages.begin(), messages.end(), '\n'), 1);
    EXPECT_FALSE(fs::exists(dir / "probes.png"));
  }

  TEST(ProbePlot, WarnsOnceWhenGnuplotFails)
  {
    // A gnuplot that fails as the real one does on a script error: the
    // warning ends with its last line.
    const fs::path dir = fs::absolute(fresh_directory("failed_plot"));
    std::ofstream(dir / "gnuplot")
      << "#!/bin/sh\necho '         ^' >&2\n"
         "echo 'line 9: undefined variable: oops' >&2\nexit 1\n";
    fs::permissions(dir / "gnuplot", fs::perms::owner_all);
    std::ofstream(dir / "probes.csv") << "step,load_factor,x\n0,0,1\n1,1,2\n";
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    setenv("PATH", (dir.string() + ":" + path).c_str(), 1);
    ::testing::internal::CaptureStderr();
    plot_probes((dir / "probes.csv").string(), (dir / "probes.png").string());
    const std::string messages = ::testing::internal::GetCapturedStderr();
    setenv("PATH", path.c_str(), 1);
    EXPECT_NE(messages.find("gnuplot exited with code 1: line 9: undefined "
                            "variable: oops"),
              std::string::npos)
      << messages;
    EXPECT_EQ(std::count(messages.begin(), messages.end(), '\n'), 1);
  }

  /// What a run of a scene wrote: the rows of probes.csv as numbers, the
  /// column of its arclength (continuation) and the script of probes.png.
  struct PlottedRun
  {
    std::vector<std::vector<double>> rows;
    std::optional<std::size_t>       arclength;
    std::string                      script;
  };

  /// Runs the scene @p scene into probe_plot_tests/@p name.
  PlottedRun
  plotted_run(const std::string &scene, const std::string &name)
  {
    const std::string dir = "probe_plot_tests/" + name;
    const RunSummary  run = run_scene_text(scene, dir);
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    const CsvTable table = read_csv_table(dir + "/probes.csv");
    PlottedRun     plotted{{},
                       table.column("arclength"),
                       text_of(dir + "/probes.png.gp")};
    for (std::size_t r = 0; r < table.rows.size(); ++r)
      {
        plotted.rows.emplace_back();
        for (std::size_t c = 0; c < table.names.size(); ++c)
          plotted.rows.back().push_back(table.number(r, c));
      }
    return plotted;
  }

  TEST(ProbePlotOfRuns, NewtonPanelsStartAtTheUnloadedState)
  {
    // A cantilever of length 1 along x bent in the x-y plane by a tip
    // force along y: tip z stays 0 (up to rounding), every step is stable
    // and in range. Panels for tip x, tip y and the energy, none for tip z
    // or the checks; the first point drawn is the unloaded state (load
    // factor 0, tip at (1, 0), no energy).
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const PlottedRun run = plotted_run(
      "subsection Geometry\n  set Segments = 20\nend\n" + direct_material() +
        "subsection Supports\n  set Clamped ends = start\nend\n"
        "subsection Loads\n  set Steps = 4\n"
        "  set Point forces = end: 0, 2, 0\nend\n"
        "subsection Output\n  set Write VTU = false\n"
        "  set Probes = tip_x: position end x; tip_y: position end y; "
        "tip_z: position end z; energy: energy\nend\n",
      "newton_run");
    const std::string &script = run.script;
    for (const char *present : {"set ylabel 'tip_x [m]'",
                                "set ylabel 'tip_y [m]'",
                                "set ylabel 'energy [J]'",
                                "tip_z = 0 m",
                                "stable at every step"})
      EXPECT_NE(script.find(present), std::string::npos)
        << present << " missing in\n"
        << script;
    for (const char *absent : {"ylabel 'tip_z", "ylabel 'stable", "in_range"})
      EXPECT_EQ(script.find(absent), std::string::npos) << absent;
    const std::vector<Piece> lines = data_pieces(script, "$stable_lines");
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(lines[0].size(), 5u);
    const std::vector<double> unloaded = {0, 1, 0, 0};
    for (std::size_t c = 0; c < unloaded.size(); ++c)
      EXPECT_NEAR(lines[0][0][c], unloaded[c], 1e-12) << "column " << c;
  }

  TEST(ProbePlotOfRuns, ReactionsOfASelfEquilibratedRingAreNotes)
  {
    // A ring of radius 1 held against rigid motions only, whose natural
    // curvature grows to 1.1: it stays a circle under a uniform bending
    // moment (energy pi EI 0.1^2 at the end), and its supports carry
    // nothing; their reactions are what the accepted residuals leave,
    // stated as 0 instead of given panels.
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const PlottedRun run = plotted_run(
      "subsection Geometry\n  set Generator = ring\n  set Radius = 1\n"
      "  set Segments = 40\n  set Director d1 = 0, 0, 1\nend\n"
      "subsection Material\n  subsection linear elastic\n"
      "    set Stiffness input = direct\n    set EA = 1e4\n"
      "    set EI1 = 1\n    set EI2 = 1\n    set GJ = 1\n"
      "    set Natural curvature 1 = 0.1\n  end\nend\n"
      "subsection Supports\n"
      "  set Fixed components = 0: x y z; 20: y z; 10: z\nend\n"
      "subsection Loads\n  set Steps = 3\n"
      "  set Ramped natural shape = curvature\nend\n"
      "subsection Output\n  set Write VTU = false\n"
      "  set Probes = energy: energy; r0x: reaction 0 x; "
      "r20y: reaction 20 y; r10z: reaction 10 z\nend\n",
      "self_equilibrated_ring");
    const double energy = run.rows.back()[2];
    EXPECT_NEAR(energy, M_PI * 0.01, 2e-3 * M_PI * 0.01);
    for (std::size_t c = 3; c < 6; ++c)
      EXPECT_LT(std::abs(run.rows.back()[c]), 1e-6 * energy);
    EXPECT_NE(run.script.find("set ylabel 'energy [J]'"), std::string::npos);
    for (const char *note : {"r0x = 0 N", "r20y = 0 N", "r10z = 0 N"})
      EXPECT_NE(run.script.find(note), std::string::npos)
        << note << " missing in\n"
        << run.script;
    EXPECT_EQ(run.script.find("ylabel 'r"), std::string::npos) << run.script;
  }

  /// The pieces of every line of @p script, stable and unstable.
  std::vector<Piece>
  all_lines(const std::string &script)
  {
    std::vector<Piece> lines = data_pieces(script, "$stable_lines");
    for (const Piece &piece : data_pieces(script, "$unstable_lines"))
      lines.push_back(piece);
    return lines;
  }

  /// The rows of @p rows (columns step, load factor, first probe, ...) at
  /// @p point of a data block (load factor, first probe).
  std::vector<std::size_t>
  rows_at(const std::vector<std::vector<double>> &rows,
          const std::vector<double>              &point)
  {
    std::vector<std::size_t> found;
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (std::abs(rows[r][1] - point[0]) < 1e-9 &&
          std::abs(rows[r][2] - point[1]) < 1e-9)
        found.push_back(r);
    return found;
  }

  /// Counts the segments of the lines of @p run's plot that join rows r
  /// and r + 1 of its probes.csv; fails where a segment joins rows that
  /// do not follow each other on the path (the arclength growing from one
  /// to the next).
  std::size_t
  joined_neighbours(const PlottedRun &run)
  {
    const auto &rows = run.rows;
    EXPECT_TRUE(run.arclength);
    const std::size_t s        = run.arclength.value_or(0);
    std::size_t       segments = 0;
    for (const Piece &piece : all_lines(run.script))
      for (std::size_t k = 0; k + 1 < piece.size(); ++k)
        {
          bool neighbours = false;
          for (const std::size_t a : rows_at(rows, piece[k]))
            for (const std::size_t b : rows_at(rows, piece[k + 1]))
              neighbours =
                neighbours || (b == a + 1 && rows[b][s] > rows[a][s]);
          EXPECT_TRUE(neighbours)
            << "a line from (" << piece[k][0] << ", " << piece[k][1] << ") to ("
            << piece[k + 1][0] << ", " << piece[k + 1][1]
            << ") joins two states that are not neighbours on the path";
          segments += neighbours;
        }
    return segments;
  }

  TEST(ProbePlotOfRuns, ContinuationBranchesAreNotJoined)
  {
    // The elastica (L = EI1 = 1, EI2 = 2, end load -x) followed past its
    // bifurcation at P = pi^2/4 to P = 4, both sides (Switch branches =
    // both): branch 0 straight, branch 1 buckled one way, branch 2 the
    // other way from the bifurcation again. Each line segment joins two
    // successive points of one path; the only rows not joined to the row
    // before are step 0 and the restart of branch 2.
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    const PlottedRun run = plotted_run(
      "subsection Geometry\n  set Segments = 40\n"
      "  set Clamp at first segment midpoint = true\n"
      "  set Director d1 = 0, 0, 1\nend\n" +
        direct_material(1e7, 1, 2, 1) +
        "subsection Supports\n  set Clamped ends = start\nend\n"
        "subsection Loads\n  set Point forces = end: -1, 0, 0\nend\n"
        "subsection Solver\n  set Method = continuation\n"
        "  subsection Continuation\n    set Load factor range = -1, 4\n"
        "    set Initial step = 0.2\n    set Switch branches = both\n"
        "  end\nend\n"
        "subsection Output\n  set Write VTU = false\n"
        "  set Probes = tip_y: position end y\nend\n",
      "branches_run");
    // step, load_factor, tip_y, arclength, branch, ...: the three
    // branches are there, and step 0.
    ASSERT_GT(run.rows.size(), 10u);
    EXPECT_EQ(run.rows[0][1], 0);
    EXPECT_EQ(run.rows.back()[4], 2);
    EXPECT_EQ(joined_neighbours(run), run.rows.size() - 2);
  }

  /// @p text with its one @p from replaced by @p to.
  std::string
  replaced(std::string text, const std::string &from, const std::string &to)
  {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  }

  TEST(ProbePlotOfRuns, LimitPointsDoNotBreakTheLine)
  {
    // The deep arch of scenes/deep_arch.prm at 40 segments (its apex load
    // shared 3:1 by vertices 20 and 21): the load factor turns at its
    // limit point and at the snap-back, and the states between are
    // unstable. One path: every row joined to the one before.
    if (!gnuplot_is_there())
      GTEST_SKIP() << "gnuplot is not on PATH";
    std::string scene =
      text_of(std::string(RODNET_SOURCE_DIR) + "/scenes/deep_arch.prm");
    scene = replaced(scene, "Segments = 200", "Segments = 40");
    scene = replaced(scene, "100: 0, -750, 0; 101:", "20: 0, -750, 0; 21:");
    scene = replaced(scene, "position 100 y", "position 20 y");
    const PlottedRun run    = plotted_run(scene, "arch_run");
    bool             turned = false;
    for (std::size_t r = 1; r < run.rows.size(); ++r)
      turned = turned || run.rows[r][1] < run.rows[r - 1][1];
    EXPECT_TRUE(turned);
    EXPECT_FALSE(data_pieces(run.script, "$unstable_lines").empty());
    EXPECT_EQ(joined_neighbours(run), run.rows.size() - 1);
  }
} // namespace
