// The peer figures the benchmark programs set their own beside
// (bench/peer_figures.h): read from BENCHMARKS.md as it stands, each with the
// date of its row. The reference is the text of BENCHMARKS.md's P1 and K1
// tables of 2026-12-04, reproduced below as written: DisMech's dt 2 run at
// N = 200 took 0.0338 s there (measured side by side with rodnet), where the
// figure copied into p1_gravity_cantilever on 2026-12-01 was 0.047 s, and
// the superseded figure the file still quotes must not be taken for a run.
#include <bench/peer_figures.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <string>

namespace
{
  using namespace rodnet;

  /// BENCHMARKS.md's P1 and K1 sections of 2026-12-04, the lines that
  /// matter here as written (the P1 problem's text shortened).
  const char benchmarks_of_2026_12_04[] =
    R"(# Benchmark problems and peer figures

## P1: gravity cantilever, large deflection
Exact tip (inextensible elastica): x = 0.5157790, z = -0.7938299.

Peers re-measured 2026-12-04 (and first on 2026-12-01), side by side with rodnet in alternating runs
on this machine kind,

| code | method | N | time in process | tip error in z | whole process |
|---|---|---|---|---|---|
| DisMech (C++ discrete elastic rods) | implicit dynamics to rest, dt 0.1 | 50 | 0.061 s | 5.0e-4 | 0.089 s |
| DisMech | same, dt 0.1 | 1000 | 1.28 s | 3.3e-5 | 1.56 s |
| DisMech | same, dt 2 (nearly pseudo-static), 2026-12-04 | 150 | 0.0241 s | 2.4e-5 (x: 6.4e-5) | |
| DisMech | same, dt 2, 2026-12-04 | 200 | 0.0338 s | 1.5e-6 (x: 3.8e-5) | |
| DisMech | same, dt 2, 2026-12-04 | 1000 | 0.188 s | 3.3e-5 (x: 6.9e-6) | 0.201 s |
| (DisMech dt 2 on 2026-12-01, a slower day) | | 200 / 1000 | 0.047 / 0.212 s | | 0.083 / 0.279 s |
| DRMSimulationModel (the bending-active tool's code), measured 2026-11-22 | dynamic relaxation | 50 | 7.25 s | 2.6e-4 | |
| DRMSimulationModel | same | 200 | 327 s | 5e-5 | |

DisMech's process starts in 0.01 s.

## K1: hinge kernel throughput
Open rod with N vertices on a helix.

| code | N | E+g+H hinges/s | gradient hinges/s |
|---|---|---|---|
| fabsim (Eigen discrete elastic rods), -O3 -march=native | 1e3 | 3.55e5 | 4.86e6 |
| fabsim, same | 1e5 | 2.96e5 | 4.55e6 |
| fabsim, same, 2026-12-04 | 1e3 / 1e5 | 3.62e5 / 2.98e5 | 4.67e6 / 4.62e6 |

Two-thirds of fabsim's Hessian time is turning triplets into the sparse matrix.
)";

  /// @p text written to the file @p name in the directory peer_figures of
  /// the working directory; its path.
  std::string
  written(const std::string &name, const std::string &text)
  {
    std::filesystem::create_directories("peer_figures");
    const std::string path = "peer_figures/" + name;
    std::ofstream(path) << text;
    return path;
  }

  /// The run of @p code at @p n with @p method among @p runs (it must be
  /// there).
  const bench::P1PeerRun &
  run_of(const std::vector<bench::P1PeerRun> &runs,
         const std::string                   &code,
         const std::string                   &method,
         const unsigned int                   n)
  {
    for (const bench::P1PeerRun &run : runs)
      if (run.code == code && run.method == method && run.n == n)
        return run;
    throw std::runtime_error("no run " + code + " " + method +
                             " at N = " + std::to_string(n));
  }
} // namespace

TEST(PeerFigures, P1RunsWithTheDatesOfTheirRows)
{
  const std::string file = written("BENCHMARKS.md", benchmarks_of_2026_12_04);
  const std::vector<bench::P1PeerRun> runs = bench::read_p1_peers(file);
  // Five DisMech runs and two of DRMSimulationModel; the superseded
  // times of 2026-12-01 (no tip error) are no run.
  ASSERT_EQ(runs.size(), 7u);
  for (const bench::P1PeerRun &run : runs)
    EXPECT_NE(run.time, 0.047);

  const bench::P1PeerRun &dt2 = run_of(runs, "DisMech", "dt 2", 200);
  EXPECT_DOUBLE_EQ(dt2.time, 0.0338);
  EXPECT_DOUBLE_EQ(dt2.z_error, 1.5e-6);
  EXPECT_DOUBLE_EQ(dt2.x_error, 3.8e-5);
  EXPECT_NEAR(dt2.tip_error(), std::hypot(1.5e-6, 3.8e-5), 1e-20);
  EXPECT_TRUE(std::isnan(dt2.whole_process));
  EXPECT_EQ(dt2.date, "2026-12-04");
  EXPECT_EQ(dt2.source, "BENCHMARKS.md's figure of 2026-12-04");

  // A row without a date of its own continuing a dated one takes its
  // date; the first of a code takes the section's.
  const bench::P1PeerRun &dt01 = run_of(runs, "DisMech", "dt 0.1", 1000);
  EXPECT_DOUBLE_EQ(dt01.time, 1.28);
  EXPECT_TRUE(std::isnan(dt01.x_error));
  EXPECT_DOUBLE_EQ(dt01.tip_error(), 3.3e-5);
  EXPECT_DOUBLE_EQ(dt01.whole_process, 1.56);
  EXPECT_EQ(dt01.date, "2026-12-04");
  const bench::P1PeerRun &drm = run_of(runs, "DRMSimulationModel", "", 200);
  EXPECT_DOUBLE_EQ(drm.time, 327);
  EXPECT_DOUBLE_EQ(drm.z_error, 5e-5);
  EXPECT_EQ(drm.date, "2026-11-22");
}

TEST(PeerFigures, FastestDisMechRunAsAccurate)
{
  const std::vector<bench::P1PeerRun> runs =
    bench::read_p1_peers(written("BENCHMARKS.md", benchmarks_of_2026_12_04));
  // rodnet's tip errors at N = 50, 100 and 1000 (doc/performance.md, P1).
  const bench::P1PeerRun *coarse =
    bench::fastest_as_accurate(runs, "DisMech", 1.14e-4);
  ASSERT_NE(coarse, nullptr);
  EXPECT_EQ(coarse->n, 150u);
  EXPECT_DOUBLE_EQ(coarse->time, 0.0241);
  // dt 2 at N = 1000 (3.4e-5, 0.188 s) is as accurate as 3.40e-5, dt 0.1
  // at N = 1000 too (by its z error alone), but slower.
  const bench::P1PeerRun *fine =
    bench::fastest_as_accurate(runs, "DisMech", 3.40e-5);
  ASSERT_NE(fine, nullptr);
  EXPECT_DOUBLE_EQ(fine->time, 0.188);
  // No DisMech run comes within 10% of a tip error of 2.72e-5.
  EXPECT_EQ(bench::fastest_as_accurate(runs, "DisMech", 2.72e-5), nullptr);
  // 0.0241 s against 0.00157 s: 15.35x, printed with the date.
  EXPECT_EQ(bench::ratio_text(*coarse, 0.00157),
            "DisMech dt 2 at N = 150 (tip error 6.8e-05): 0.0241 s, 15.4x, "
            "against BENCHMARKS.md's figure of 2026-12-04");
}

TEST(PeerFigures, K1TakesTheNewestRowPerSize)
{
  const std::vector<bench::K1PeerFigure> figures =
    bench::read_k1_peers(written("BENCHMARKS.md", benchmarks_of_2026_12_04));
  ASSERT_EQ(figures.size(), 2u);
  for (const bench::K1PeerFigure &figure : figures)
    {
      EXPECT_EQ(figure.code, "fabsim");
      EXPECT_EQ(figure.date, "2026-12-04");
    }
  EXPECT_EQ(figures[0].n, 1000u);
  EXPECT_DOUBLE_EQ(figures[0].hessian_rate, 3.62e5);
  EXPECT_DOUBLE_EQ(figures[0].gradient_rate, 4.67e6);
  EXPECT_EQ(figures[1].n, 100000u);
  EXPECT_DOUBLE_EQ(figures[1].hessian_rate, 2.98e5);
  EXPECT_DOUBLE_EQ(figures[1].gradient_rate, 4.62e6);
}

TEST(PeerFigures, AnUnreadableTableNamesFileSectionAndColumn)
{
  std::string without_error = benchmarks_of_2026_12_04;
  without_error.replace(without_error.find("tip error in z"), 14, "accuracy");
  const std::string file = written("BENCHMARKS-changed.md", without_error);
  try
    {
      bench::read_p1_peers(file);
      FAIL() << "a P1 table without a tip error column was read";
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_EQ(std::string(e.what()),
                "peer_figures/BENCHMARKS-changed.md, section \"P1\": no "
                "column \"tip error\" in its table");
    }
  EXPECT_THROW(bench::read_p1_peers("no-such-BENCHMARKS.md"),
               std::runtime_error);
}

// The file the benchmarks read by default, where this machine has it: its
// tables must stay readable, every row dated.
TEST(PeerFigures, TheSharedFileIsReadable)
{
  if (!std::filesystem::exists(bench::default_peer_file))
    GTEST_SKIP() << bench::default_peer_file << " is not on this machine";
  const std::regex date("[0-9]{4}-[0-9]{2}-[0-9]{2}");
  unsigned int     dismech = 0;
  for (const bench::P1PeerRun &run :
       bench::read_p1_peers(bench::default_peer_file))
    {
      dismech += run.code == "DisMech";
      EXPECT_TRUE(std::regex_match(run.date, date)) << run.name();
    }
  EXPECT_GT(dismech, 0u);
  EXPECT_FALSE(bench::read_k1_peers(bench::default_peer_file).empty());
}
