// The roll-up of an isotropic cantilever under an end moment about the fixed
// axis z (scenes/rollup_lateral.prm) and its lateral instability, against
// our derivation (doc/continuation.md, "Roll-up under an end moment"): the
// moment -M theta_z(q) (Lestringant & Kochmann eq. 33) acts at every planar
// state like a quasi-tangential moment (Argyris et al. 1979) with the tip
// tangent as its lever, and the planar arc of angle theta = M L / EI is
// stable up to theta = pi / 2, M_cr = pi EI / (2 L), for every GJ / EI.
// Past it, the quarter circle turns about the clamp's tangent by phi with
// lambda = lambda_cr cos(phi): tip (2/pi, (2/pi) cos(phi), -+(2/pi) sin(phi))
// L, exact for the continuum rod.
#include <common/continuation_path.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;
  using Point = ArclengthContinuation::StepInfo;

  /// M = lambda 2 pi EI / L: the quarter circle is at load factor 1/4.
  constexpr double critical = 0.25;

  /// scenes/rollup_lateral.prm followed with @p changes appended (later
  /// entries override earlier ones), with the tip's position at every point.
  ContinuationPath
  rollup(const std::string &changes = "")
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/rollup_lateral.prm");
    std::stringstream scene;
    scene << file.rdbuf() << changes;
    return follow(scene.str(), {"end"});
  }

  /// Only the planar branch up to the bifurcation, in @p segments, with
  /// torsional rigidity @p GJ.
  std::string
  planar_only(const unsigned int segments, const double GJ)
  {
    return "subsection Geometry\n  set Segments = " + std::to_string(segments) +
           "\nend\nsubsection Material\n  subsection linear elastic\n"
           "    set GJ = " +
           std::to_string(GJ) +
           "\n  end\nend\nsubsection Solver\n  subsection Continuation\n"
           "    set Load factor range = -0.05, 0.3\n"
           "    set Switch branches = false\n  end\nend\n";
  }

  /// The shipped scene (100 segments, GJ = 0.5 EI), followed once.
  const ContinuationPath &
  shipped()
  {
    static const ContinuationPath path = rollup();
    return path;
  }

  TEST(RollupLateral, CriticalMomentIsAQuarterCircleForEveryGJ)
  {
    // Located at N = 50 / 100 / 200: 0.249958365 / 0.2499896572 /
    // 0.2499974229 (-1.7e-4 / -4.1e-5 / -1.0e-5 relative, N^-2). The
    // tolerance 1e-4 at N = 100 is 2.4 times the measured error; the step
    // length moves the located value by 2e-9. GJ = 2 EI gives the same
    // discrete value to 1e-8: the out-of-plane bending alone decides.
    ASSERT_EQ(shipped().bifurcations.size(), 1u);
    const double at_100 = shipped().bifurcations[0];
    EXPECT_NEAR(at_100 / critical, 1.0, 1e-4);
    const ContinuationPath coarse = rollup(planar_only(50, 0.5));
    ASSERT_EQ(coarse.bifurcations.size(), 1u);
    const double ratio =
      (coarse.bifurcations[0] - critical) / (at_100 - critical);
    EXPECT_NEAR(ratio, 4.0, 0.2) << "second order in the segment length";
    const ContinuationPath stiff = rollup(planar_only(100, 2.0));
    ASSERT_EQ(stiff.bifurcations.size(), 1u);
    EXPECT_NEAR(stiff.bifurcations[0], at_100, 1e-8);
  }

  TEST(RollupLateral, PlanarArcIsStableBelowTheCriticalMoment)
  {
    // Every point of the planar branch below the bifurcation is stable and
    // in the plane, its tip on the circle of radius EI / M:
    // ((sin theta) / kappa, (1 - cos theta) / kappa), kappa = theta / L
    // (within 2.0e-5 L at N = 100, 7.1e-5 L at N = 50; 1e-4 L allowed), z
    // zero to rounding
    // (3.8e-10 L at the bracket of the bifurcation, where the tangent is
    // within 1e-8 of singular; 1e-8 L allowed).
    const ContinuationPath &path   = shipped();
    unsigned int            planar = 0;
    for (std::size_t i = 0; i < path.points.size(); ++i)
      {
        const Point &p = path.points[i];
        if (p.branch != 0 || p.load_factor >= path.bifurcations[0] ||
            p.load_factor <= 0)
          continue;
        ++planar;
        EXPECT_EQ(p.check.negative_eigenvalues, 0u) << "step " << p.step;
        const double  theta = 2 * M_PI * p.load_factor;
        const Vector3 tip   = path.positions[i][0];
        EXPECT_NEAR(tip[0], std::sin(theta) / theta, 1e-4) << p.load_factor;
        EXPECT_NEAR(tip[1], (1 - std::cos(theta)) / theta, 1e-4);
        EXPECT_NEAR(tip[2], 0, 1e-8);
      }
    EXPECT_GT(planar, 10u);
  }

  TEST(RollupLateral, LateralBranchTurnsTheQuarterCircleOutOfPlane)
  {
    // Past the bifurcation the path follows the null vector out of the
    // plane: one negative eigenvalue, the load falls, and the tip stays on
    // the circle x = 2L/pi, y^2 + z^2 = (2L/pi)^2 while the quarter circle
    // turns by phi = atan2(|z|, y), lambda = cos(phi) / 4. At N = 100 / 50
    // the tip is within 1.3e-5 / 5.3e-5 L of that circle (1e-4 L allowed)
    // and lambda within 1.0e-5 / 4.2e-5 of cos(phi) / 4 (the critical
    // load's discretization error; 5e-5 allowed). The path leaves the range
    // past phi = 90 deg.
    const ContinuationPath &path    = shipped();
    const double            radius  = 2 / M_PI;
    unsigned int            lateral = 0;
    for (std::size_t i = 0; i < path.points.size(); ++i)
      {
        const Point &p = path.points[i];
        if (p.branch != 1 ||
            p.kind == ArclengthContinuation::PointKind::bifurcation)
          continue;
        ++lateral;
        EXPECT_EQ(p.check.negative_eigenvalues, 1u) << "step " << p.step;
        EXPECT_LT(p.load_factor_rate, 0) << "step " << p.step;
        const Vector3 tip = path.positions[i][0];
        EXPECT_NEAR(tip[0], radius, 1e-4) << p.load_factor;
        EXPECT_NEAR(std::hypot(tip[1], tip[2]), radius, 1e-4) << p.load_factor;
        const double phi = std::atan2(std::abs(tip[2]), tip[1]);
        EXPECT_NEAR(p.load_factor, critical * std::cos(phi), 5e-5)
          << "phi " << phi;
      }
    EXPECT_GT(lateral, 50u);
    EXPECT_EQ(path.points.back().load_factor, -0.05);
  }
} // namespace
