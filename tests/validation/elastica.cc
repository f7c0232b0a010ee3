// Planar elastica, clamped-free, dead compressive end load (Korner et al.
// 2021, section 5a; VALIDATION.md), B = L = 1: the critical load from the
// eigenvalue crossing against pi^2/4, and post-buckled tip positions against
// the exact elliptic-integral solution, for both hinge kernels.
#include <common/elastica_exact.h>
#include <common/run_scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The elastica scene: load P_max reached in @p steps equal steps, a
  /// transverse imperfection force imperfection * P_max at the tip; the
  /// rod's EA, or inextensible where @p EA is 0.
  std::string
  elastica_scene(unsigned int       n_segments,
                 const std::string &kernel,
                 double             P_max,
                 unsigned int       steps,
                 double             imperfection,
                 bool               critical_search,
                 double             EA = 1e7)
  {
    return "subsection Geometry\n"
           "  set Generator = straight\n"
           "  set Segments = " +
           std::to_string(n_segments) +
           "\n"
           "  set Clamp at first segment midpoint = true\n"
           "  set Director d1 = 0, 0, 1\n"
           "  set Hinge kernel = " +
           kernel +
           "\n"
           "end\n"
           "subsection Material\n"
           "  set Inextensible = " +
           (EA == 0 ? "true" : "false") +
           "\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = direct\n"
           "    set EA = " +
           std::to_string(EA == 0 ? 1e7 : EA) +
           "\n"
           "    set EI1 = 1\n"
           "    set EI2 = 1\n"
           "    set GJ = 1\n"
           "  end\n"
           "end\n"
           "subsection Supports\n"
           "  set Clamped ends = start\n"
           "end\n"
           "subsection Loads\n"
           "  set Steps = " +
           std::to_string(steps) +
           "\n"
           "  set Point forces = end: " +
           std::to_string(-P_max) + ", " +
           std::to_string(imperfection * P_max) +
           ", 0\n"
           "end\n"
           "subsection Solver\n"
           "  set Critical load search = " +
           (critical_search ? "true" : "false") +
           "\n"
           "  set Branch switching amplitude = 0.1\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = tip_x: position end x; tip_y: position end y; "
           "tip_z: position end z\n"
           "end\n";
  }

  /// Tip (x, deflection) at load P from a run whose rows hold the load
  /// factor of a scene with maximal load P_max. With EI1 = EI2 the buckling
  /// plane may turn about the load axis (a neutral mode), so the deflection
  /// is the distance from that axis.
  ElasticaTip
  tip_at(const RunSummary &run, double P, double P_max)
  {
    const std::size_t x = probe_column(run, "tip_x");
    const std::size_t y = probe_column(run, "tip_y");
    const std::size_t z = probe_column(run, "tip_z");
    for (const auto &row : run.rows)
      if (std::abs(row[0] * P_max - P) < 1e-9)
        return {row[x], std::hypot(row[y], row[z])};
    ADD_FAILURE() << "no converged step at P = " << P;
    return {NAN, NAN};
  }

  class Elastica : public ::testing::TestWithParam<std::string>
  {
  };

  TEST_P(Elastica, CriticalLoadFromEigenvalueCrossing)
  {
    // A perfect column loaded to P = 3: the lowest eigenvalue of the
    // tangent crosses zero at P_cr = pi^2/4 (tolerance 0.5%, N = 100).
    const double     P_max = 3;
    const RunSummary run =
      run_scene_text(elastica_scene(100, GetParam(), P_max, 15, 0.0, true),
                     "elastica_critical_" + GetParam());
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double P_cr  = run.critical_load_factor * P_max;
    const double exact = M_PI * M_PI / 4;
    std::cout << GetParam() << ": P_cr = " << P_cr << ", exact " << exact
              << ", relative error " << (P_cr - exact) / exact << std::endl;
    EXPECT_NEAR(P_cr, exact, 0.005 * exact);
  }

  TEST_P(Elastica, PostBuckledTipConvergesToExact)
  {
    // Tip positions at P = 3, 5, 10 within 0.005 L of the exact elastica at
    // N = 100, and the error shrinks as N grows (25, 50, 100).
    const double P_max             = 10;
    double       previous_error[3] = {INFINITY, INFINITY, INFINITY};
    for (const unsigned int n : {25u, 50u, 100u})
      {
        const RunSummary run =
          run_scene_text(elastica_scene(n, GetParam(), P_max, 40, 1e-6, false),
                         "elastica_" + GetParam() + "_" + std::to_string(n));
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        const double loads[3] = {3, 5, 10};
        for (unsigned int i = 0; i < 3; ++i)
          {
            const ElasticaTip exact    = elastica_tip(loads[i]);
            const ElasticaTip computed = tip_at(run, loads[i], P_max);
            const double      error =
              std::max(std::abs(computed.x - exact.x),
                       std::abs(computed.delta - exact.delta));
            std::cout << GetParam() << " N = " << n << " P = " << loads[i]
                      << ": tip (" << computed.x << ", " << computed.delta
                      << "), exact (" << exact.x << ", " << exact.delta
                      << "), error " << error << std::endl;
            if (n == 100)
              {
                EXPECT_LT(error, 0.005) << "P = " << loads[i];
              }
            EXPECT_LT(error, previous_error[i]) << "P = " << loads[i];
            previous_error[i] = error;
          }
      }
  }

  TEST(ElasticaDefaults, PerfectIsotropicColumnEndsBuckled)
  {
    // No imperfection, EI1 = EI2, P = 5 in the default 10 load steps and
    // the default branch switching: the first unstable step (P = 2.5) is
    // moved along its buckling mode onto the stable branch, and the last
    // one is the exact elastica at P = 5 (errors at N = 100: -2.0e-4 L in
    // x, -3.7e-5 L in the deflection; tolerance 5e-4 L), stable.
    std::string       scene = elastica_scene(100, "simple", 5, 10, 0.0, false);
    const std::string amplitude = "  set Branch switching amplitude = 0.1\n";
    scene.erase(scene.find(amplitude), amplitude.size());
    const RunSummary run = run_scene_text(scene, "elastica_defaults");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const ElasticaTip found = tip_at(run, 5, 5);
    const ElasticaTip exact = elastica_tip(5);
    EXPECT_NEAR(found.x, exact.x, 5e-4);
    EXPECT_NEAR(found.delta, exact.delta, 5e-4);
    EXPECT_EQ(run.unstable_steps, 0u);
  }

  TEST(InextensibleElastica, CriticalLoadOnTheConstraintManifold)
  {
    // The inertia of the KKT tangent less one per multiplier: the lowest
    // eigenvalue crosses zero at pi^2/4 (0.5 %, N = 100), not at the
    // first step (which counting every constraint would report).
    const double     P_max = 3;
    const RunSummary run =
      run_scene_text(elastica_scene(100, "simple", P_max, 15, 0.0, true, 0),
                     "elastica_inextensible_critical");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double exact = M_PI * M_PI / 4;
    std::cout << "inextensible P_cr = " << run.critical_load_factor * P_max
              << ", exact " << exact << std::endl;
    EXPECT_NEAR(run.critical_load_factor * P_max, exact, 0.005 * exact);
  }

  INSTANTIATE_TEST_SUITE_P(HingeKernels,
                           Elastica,
                           ::testing::Values("simple", "classic"));
} // namespace
