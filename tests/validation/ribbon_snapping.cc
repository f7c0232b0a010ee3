// Twist-induced snapping of a bent ribbon (scenes/ribbon_snapping.prm;
// Sano & Wada 2019, Korner et al. section 5(c), Fig. 5.3): a strip of the
// Sano-Wada ribbon material (h = 0.2 mm, R = 108 mm, L = pi R) held in a
// half circle, its clamped ends turned by phi in opposite senses. The
// reference is the paper's statement: below w* ~ 1.24 sqrt(L h) = 10.2 mm
// the path has a fold in phi where the lowest eigenvalue of the tangent
// crosses zero (w = 8 mm snaps); for w = 15 mm it has none.
#include <common/run_scene_text.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The columns of the scene's probes in a row of RunSummary::rows.
  struct RibbonColumns
  {
    std::size_t apex_x, apex_y, lowest;
  };

  /// scenes/ribbon_snapping.prm run with @p overrides appended (later
  /// entries override earlier ones), without VTU files and plots.
  RunSummary
  run_ribbon(const std::string &overrides)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/ribbon_snapping.prm");
    std::stringstream text;
    text << file.rdbuf() << "\n"
         << overrides << "\nsubsection Output\n  set Plot = false\nend\n";
    const std::string directory =
      (std::filesystem::temp_directory_path() / "rodnet_ribbon_snapping")
        .string();
    return run_scene_text(text.str(), directory);
  }

  RibbonColumns
  columns(const RunSummary &run)
  {
    return {probe_column(run, "apex_x"),
            probe_column(run, "apex_y"),
            probe_column(run, "lowest")};
  }

  /// The ribbon of width @p width (m) in @p segments segments, the arc's
  /// end segments straddling 0 and 180 degrees as in the shipped scene.
  std::string
  ribbon(const double width, const unsigned int segments)
  {
    const double       delta = 180. / (segments - 1);
    std::ostringstream text;
    text.precision(17);
    text << "subsection Geometry\n  set Segments = " << segments
         << "\n  set Start angle = " << -delta / 2
         << "\n  set End angle = " << 180 + delta / 2
         << "\nend\nsubsection Material\n  subsection sano-wada ribbon\n"
            "    set Width = "
         << width << "\n  end\nend\n";
    return text.str();
  }

  /// Index of the row of the largest load factor.
  std::size_t
  fold_row(const RunSummary &run)
  {
    std::size_t fold = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i)
      if (run.rows[i][0] > run.rows[fold][0])
        fold = i;
    return fold;
  }

  TEST(RibbonSnapping, NarrowRibbonHasAFoldWhereTheLowestEigenvalueCrossesZero)
  {
    // w = 8 mm, N = 100 (the shipped scene): the load factor rises to the
    // fold at phi = 180 lambda = 115.36 degrees (lambda = 0.64091), every
    // point before it stable with a positive lowest eigenvalue (6.2e-5 at
    // phi = 0), every point after it on the way back unstable with a
    // negative one; at the point nearest the fold the eigenvalue is -0.9%
    // of its start value (5% allowed). The path stays in the symmetry
    // plane x = 0 of the clamps (1e-9 m allowed, 1e-16 measured). The
    // run stops at "Max points" past the fold (the scene's comment).
    const RunSummary run = run_ribbon("");
    EXPECT_NE(run.failure.find("Max points"), std::string::npos) << run.failure;
    const RibbonColumns c    = columns(run);
    const std::size_t   fold = fold_row(run);
    ASSERT_GT(fold, 10u);
    ASSERT_LT(fold + 10, run.rows.size());
    const double phi_c = 180 * run.rows[fold][0];
    std::cout << "fold at phi = " << phi_c << " degrees, lowest eigenvalue "
              << run.rows[fold][c.lowest] << std::endl;
    EXPECT_GT(phi_c, 110.);
    EXPECT_LT(phi_c, 120.);
    const double start = run.rows[0][c.lowest];
    EXPECT_GT(start, 0.);
    EXPECT_LT(std::abs(run.rows[fold][c.lowest]), 0.05 * start);
    for (std::size_t i = 1; i < run.rows.size(); ++i)
      {
        const std::vector<double> &row = run.rows[i];
        EXPECT_NEAR(row[c.apex_x], 0., 1e-9) << "row " << i;
        if (i + 1 < fold)
          {
            EXPECT_GT(row[0], run.rows[i - 1][0]) << "row " << i;
            EXPECT_GT(row[c.lowest], 0.) << "row " << i;
          }
        if (i > fold + 1 && i < fold + 10)
          {
            EXPECT_LT(row[0], run.rows[i - 1][0]) << "row " << i;
            EXPECT_LT(row[c.lowest], 0.) << "row " << i;
          }
      }
  }

  TEST(RibbonSnapping, FoldConvergesWithTheSegments)
  {
    // The fold at N = 50 / 100 / 200: 115.61 / 115.36 / 115.30 degrees
    // (bench/ribbon_threshold.sh), differences falling by 4 (second
    // order); N = 50 within 0.5 degree of N = 100 (0.25 measured).
    const RunSummary coarse  = run_ribbon(ribbon(8e-3, 50));
    const RunSummary fine    = run_ribbon("");
    const double     phi_50  = 180 * coarse.rows[fold_row(coarse)][0];
    const double     phi_100 = 180 * fine.rows[fold_row(fine)][0];
    std::cout << "fold at N = 50: " << phi_50 << ", N = 100: " << phi_100
              << " degrees" << std::endl;
    EXPECT_NEAR(phi_50, phi_100, 0.5);
  }

  TEST(RibbonSnapping, WideRibbonTurnsOverWithoutAFold)
  {
    // w = 15 mm: the path reaches phi = 180 degrees with the load factor
    // rising at every point, every point stable with a positive lowest
    // eigenvalue (its minimum 3.5e-6 at phi = 180, where the path is
    // about to pass the mirror image of its start), and the apex turned
    // over continuously from y = R to y = -0.0255 m (156 points; the
    // scene's Max points raised to 300).
    const RunSummary run =
      run_ribbon(ribbon(15e-3, 100) + "subsection Solver\n  subsection "
                                      "Continuation\n    set Max points = "
                                      "300\n  end\nend\n");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const RibbonColumns c = columns(run);
    EXPECT_EQ(run.rows.back()[0], 1.);
    for (std::size_t i = 1; i < run.rows.size(); ++i)
      {
        EXPECT_GT(run.rows[i][0], run.rows[i - 1][0]) << "row " << i;
        EXPECT_GT(run.rows[i][c.lowest], 0.) << "row " << i;
      }
    EXPECT_NEAR(run.rows.front()[c.apex_y], 0.108, 1e-9);
    EXPECT_LT(run.rows.back()[c.apex_y], -0.02);
  }
} // namespace
