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
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;
  using Point = ArclengthContinuation::StepInfo;

  /// scenes/lee_frame.prm as shipped (50 segments per member, its comment
  /// has the geometry), with the position of the load point (vertex 10 of
  /// the beam) at every point; followed once for all the tests.
  const ContinuationPath &
  lee_frame()
  {
    static const ContinuationPath path = [] {
      std::ifstream     file(RODNET_SOURCE_DIR "/scenes/lee_frame.prm");
      std::stringstream scene;
      scene << file.rdbuf();
      return follow(scene.str(), {"1:10"}, RODNET_SOURCE_DIR "/scenes");
    }();
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
} // namespace
