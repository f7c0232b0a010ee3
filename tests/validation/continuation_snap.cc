// Pseudo-arclength continuation through a snap-through with a snap-back,
// against a published limit load: Lee's frame (Lee, Manuel & Rossow 1968,
// "Large deflections and stability of elastic frames", J. Eng. Mech. Div.
// ASCE 94; the path-following benchmark of Schweizerhof & Wriggers 1986,
// "Consistent linearization for path following methods in nonlinear FE
// analysis", Comput. Methods Appl. Mech. Eng. 59, 261-279). Two members of
// length L = 120 welded at a right angle, both supports hinged, a dead
// vertical load on the horizontal member at L/5 from the corner; E = 720,
// A = 6, I = 2. The published limit load is P = 1.85 (P L^2 / EI = 18.5).
// The members are slender (L / r = 208): shear deformation, which the
// Kirchhoff rods leave out, is below the tolerance, and so is the axial
// strain (EA x 1e4 moves the limit load by 1.1e-4).
#include <common/continuation_path.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;
  using Point = ArclengthContinuation::StepInfo;

  /// scenes/lee_frame.prm with @p overrides, followed, with the position
  /// of the load point (vertex 10 of the beam) at every point.
  ContinuationPath
  follow_lee_frame(const std::string &overrides)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/lee_frame.prm");
    std::stringstream scene;
    scene << file.rdbuf() << "\n" << overrides;
    return follow(scene.str(), {"1:10"}, RODNET_SOURCE_DIR "/scenes");
  }

  /// scenes/lee_frame.prm as shipped (50 segments per member, its comment
  /// has the geometry); followed once for all the tests.
  const ContinuationPath &
  lee_frame()
  {
    static const ContinuationPath path = follow_lee_frame("");
    return path;
  }

  TEST(ContinuationSnap, LeeFrameLimitLoad)
  {
    // Limit load at 25, 50, 100, 200, 400 segments per member: 1.8483,
    // 1.8538, 1.8552, 1.8556, 1.8556 (N^-2): +0.21 % of the published
    // value at 50, +0.31 % converged.
    const ContinuationPath &path = lee_frame();
    ASSERT_EQ(path.limit_points.size(), 2u);
    const double published = 1.85; // P, EI / L^2 = 0.1
    EXPECT_NEAR(path.limit_points[0], published, 0.005 * published);
    // Past the snap-back the load turns negative: it must pull the beam up
    // (here to -0.938) before the frame, its beam now below the corner,
    // carries it again up to the end of the range. No bifurcation: the
    // frame stays in its plane.
    EXPECT_LT(path.limit_points[1], 0);
    EXPECT_TRUE(path.bifurcations.empty());
    EXPECT_EQ(path.points.back().load_factor, 4.0);
  }

  TEST(ContinuationSnap, LeeFrameUnstableBetweenTheLimitPoints)
  {
    // One negative eigenvalue exactly between the two limit points, none
    // before the first or after the second.
    unsigned int folds = 0;
    for (const Point &p : lee_frame().points)
      {
        folds += p.kind == ArclengthContinuation::PointKind::limit_point;
        EXPECT_EQ(p.check.negative_eigenvalues, folds == 1 ? 1u : 0u)
          << "step " << p.step << ", load factor " << p.load_factor;
      }
    EXPECT_EQ(folds, 2u);
  }

  TEST(ContinuationSnap, LeeFrameSnapsBack)
  {
    // On the unstable branch, while the load falls, the deflection of the
    // load point first grows, then shrinks (the snap-back of the published
    // load-deflection path): here from 61.0 to 51.0, 8 % of L.
    const ContinuationPath &path = lee_frame();
    std::vector<double>     deflection;
    for (std::size_t i = 0; i < path.points.size(); ++i)
      if (!path.points[i].check.stable)
        {
          EXPECT_LT(path.points[i].load_factor_rate, 0) << "step " << i;
          deflection.push_back(120 - path.positions[i][0][1]);
        }
    ASSERT_FALSE(deflection.empty());
    const auto largest = std::max_element(deflection.begin(), deflection.end());
    const auto smallest_after = std::min_element(largest, deflection.end());
    EXPECT_GT(*largest - *smallest_after, 0.05 * 120);
  }

  /// The point of @p path that it jumped to (Limit points = snap), where
  /// there is exactly one such point; 0 (with a test failure) otherwise.
  std::size_t
  the_one_jump(const ContinuationPath &path)
  {
    std::vector<std::size_t> jumps;
    for (std::size_t i = 0; i < path.points.size(); ++i)
      if (path.points[i].kind == ArclengthContinuation::PointKind::jump)
        jumps.push_back(i);
    EXPECT_EQ(jumps.size(), 1u);
    return jumps.size() == 1 ? jumps[0] : 0;
  }

  /// Every point of @p path from @p first on is stable, its load factor
  /// above the one before: a load-controlled path.
  void
  expect_stable_and_rising_from(const ContinuationPath &path,
                                const std::size_t       first)
  {
    for (std::size_t i = first; i < path.points.size(); ++i)
      {
        EXPECT_TRUE(path.points[i].check.stable) << "step " << i;
        EXPECT_GT(path.points[i].load_factor, path.points[i - 1].load_factor)
          << "step " << i;
      }
  }

  TEST(ContinuationSnap, LeeFrameSnapsOntoTheStableBranchItsPathReturnsTo)
  {
    // Limit points = snap: at the limit load the frame jumps, as under
    // load control, to the one stable state past it, which the path
    // followed through the snap-back reaches only after its second limit
    // point, with the beam below the corner: the landed state must be that
    // path's state at the same load (found here by landing the followed
    // path on it), and the path from there its path up to P = 4.
    const ContinuationPath snapped =
      follow_lee_frame("subsection Solver\n  subsection Continuation\n"
                       "    set Limit points = snap\n  end\nend\n");
    const std::size_t jump = the_one_jump(snapped);
    ASSERT_GT(jump, 0u);
    const Point &fold   = snapped.points[jump - 1];
    const Point &landed = snapped.points[jump];
    // The fold located by bisection, against the parabola through the
    // followed path's points around it.
    ASSERT_EQ(snapped.limit_points.size(), 1u);
    EXPECT_EQ(fold.load_factor, snapped.limit_points[0]);
    std::cout << std::setprecision(10) << "fold at P = " << fold.load_factor
              << ", followed path's " << lee_frame().limit_points[0]
              << std::setprecision(6) << std::endl;
    // Measured 2e-8 apart (the parabola's error).
    EXPECT_NEAR(fold.load_factor, lee_frame().limit_points[0], 1e-6);
    EXPECT_EQ(fold.kind, ArclengthContinuation::PointKind::fold);
    EXPECT_TRUE(fold.check.stable);
    expect_stable_and_rising_from(snapped, jump);
    EXPECT_EQ(snapped.points.back().load_factor, 4.0);

    std::ostringstream landing;
    landing.precision(17);
    landing << "subsection Solver\n  subsection Continuation\n"
               "    set Output load factors = "
            << landed.load_factor << "\n  end\nend\n";
    const ContinuationPath   followed = follow_lee_frame(landing.str());
    std::vector<std::size_t> there;
    for (std::size_t i = 0; i < followed.points.size(); ++i)
      if (followed.points[i].load_factor == landed.load_factor)
        there.push_back(i);
    ASSERT_EQ(there.size(), 1u) << "the followed path passes the load once";
    EXPECT_TRUE(followed.points[there[0]].check.stable);
    const double L = 120;
    const double at_landing =
      (snapped.positions[jump][0] - followed.positions[there[0]][0]).norm();
    const double at_end =
      (snapped.positions.back()[0] - followed.positions.back()[0]).norm();
    std::cout
      << "snapped at P = " << fold.load_factor
      << " to P = " << landed.load_factor << ": the load point moves by "
      << (snapped.positions[jump][0] - snapped.positions[jump - 1][0]).norm()
      << "; from the followed path's " << at_landing << " there, " << at_end
      << " at P = 4" << std::endl;
    // Measured 8e-12 L and 1.2e-10 L (the corrector's tolerance).
    EXPECT_LT(at_landing, 1e-8 * L);
    EXPECT_LT(at_end, 1e-8 * L);
  }

  TEST(ContinuationSnap, InextensibleDeepArchSnapsOntoItsInvertedBranch)
  {
    // scenes/deep_arch.prm (N = 200) with inextensible rods: no potential
    // to descend, so the jump at the limit load is found by following the
    // path on, through its snap-back, until it comes back to the load on
    // the inverted arch. The fold against DaDeppo & Schmidt's limit load
    // P R^2 / EI = 8.97 (10 lambda here; the extensible arch has 8.962 at
    // N = 200); the path from the jump on against the path followed
    // through the snap-back, at the end of the range.
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/deep_arch.prm");
    std::stringstream scene;
    scene << file.rdbuf() << "\nsubsection Material\n"
          << "  set Inextensible = true\nend\n";
    const std::string      snap     = "subsection Solver\n  subsection "
                                      "Continuation\n    set Limit points = "
                                      "snap\n  end\nend\n";
    const ContinuationPath snapped  = follow(scene.str() + snap, {"100"});
    const ContinuationPath followed = follow(scene.str(), {"100"});
    const std::size_t      jump     = the_one_jump(snapped);
    ASSERT_GT(jump, 0u);
    const double published = 8.97;
    std::cout << "fold at P R^2 / EI = "
              << 10 * snapped.points[jump - 1].load_factor << std::endl;
    EXPECT_NEAR(10 * snapped.points[jump - 1].load_factor,
                published,
                0.005 * published);
    expect_stable_and_rising_from(snapped, jump);
    ASSERT_EQ(snapped.points.back().load_factor, 1.5);
    ASSERT_EQ(followed.points.back().load_factor, 1.5);
    const double R = 100;
    const double difference =
      (snapped.positions.back()[0] - followed.positions.back()[0]).norm();
    std::cout << "apex at load factor 1.5: " << difference
              << " from the followed path's" << std::endl;
    EXPECT_LT(difference, 1e-8 * R);
    // Inverted: the apex below the supports.
    EXPECT_LT(snapped.positions.back()[0][1], -R * std::sin(17.5 * M_PI / 180));

    // With too few points for the path to come back, the run stops there
    // (exit code 2), naming the fold and what each way to the state past
    // it gave.
    try
      {
        follow(scene.str() + snap +
                 "subsection Solver\n  subsection Continuation\n"
                 "    set Max points = 70\n  end\nend\n",
               {"100"});
        ADD_FAILURE() << "the run did not stop";
      }
    catch (const SolverFailure &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("snaps at the limit point at load factor "
                               "0.89623"),
                  std::string::npos)
          << message;
        EXPECT_NE(message.find("Newton in full steps"), std::string::npos)
          << message;
        EXPECT_NE(message.find("within 70 points"), std::string::npos)
          << message;
      }
  }
} // namespace
