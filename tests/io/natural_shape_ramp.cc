// Loads/Ramped natural shape: the load factor scales the chosen parts of
// the rods' natural shape as it scales the loads. A cantilever whose
// natural curvature and twist are ramped is, at each load step, the helix of
// that fraction of its natural shape; one whose eigenstrain is ramped grows
// by that fraction of it; one whose natural curvature grows under an end
// moment held fixed (Loads/Fixed loads) is the arc of that curvature plus
// the moment's, with the elastic energy of the moment alone (the energy
// probe measures from the natural shape at the load factor); the entries'
// errors name them.
#include <common/run_scene_text.h>
#include <common/scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
  using namespace rodnet;

  /// A unit cantilever along x of @p n segments, clamped at its start
  /// (first segment centred on it), with natural curvature @p curvature,
  /// twist @p twist and eigenstrain @p eigenstrain, no load, @p steps load
  /// steps, and the entry Ramped natural shape = @p ramp; probes: the
  /// tip's position.
  std::string
  shaped_cantilever(const unsigned int n,
                    const double       curvature,
                    const double       twist,
                    const double       eigenstrain,
                    const unsigned int steps,
                    const std::string &ramp)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Geometry\n  set Segments = " << n
      << "\n  set Clamp at first segment midpoint = true\n"
      << "  set Director d1 = 0, 0, 1\nend\n"
         "subsection Material\n  subsection linear elastic\n"
         "    set Stiffness input = direct\n    set EA = 100\n"
         "    set EI1 = 1\n    set EI2 = 2\n    set GJ = 1\n"
      << "    set Natural curvature 1 = " << curvature
      << "\n    set Natural twist = " << twist
      << "\n    set Axial eigenstrain = " << eigenstrain
      << "\n  end\nend\n"
         "subsection Supports\n  set Clamped ends = start\nend\n"
         "subsection Loads\n  set Steps = "
      << steps << "\n  set Ramped natural shape = " << ramp
      << "\nend\n"
         "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
         "  set Probes = x: position end x; y: position end y; z: "
         "position end z; energy: energy\nend\n";
    return s.str();
  }

  TEST(NaturalShapeRamp, EachStepIsTheScaledHelix)
  {
    // Natural curvature k = 3 and twist tau = 2 ramped in four load steps
    // (cut where Newton needs it), no load: at load factor lambda the rod is
    // stress free, a helix of curvature lambda k and torsion lambda tau, whose
    // chord over the arc length s = 1 is (R = k / w^2, c = tau / w^2, w =
    // sqrt(k^2 + tau^2), all times lambda where due)
    //   chord^2 = 2 R^2 (1 - cos w s) + (c w s)^2.
    // The same shape present from the start fails to converge in four
    // load steps from the straight rod: ramping it is the way there.
    // The polygon's vertices lie on a helix whose curvature and torsion
    // differ from the natural ones by O(h^2): the chords agree to 4.2e-5
    // at n = 100 and 1.0e-5 at 200; tolerance 0.8 / n^2.
#ifdef DEBUG
    // deal.II's Debug library under the sanitizers (CI's "debug" label)
    // takes 7 minutes for both; n = 100 runs the same code.
    const std::vector<unsigned int> segment_counts{100u};
#else
    const std::vector<unsigned int> segment_counts{100u, 200u};
#endif
    for (const unsigned int n : segment_counts)
      {
        const RunSummary ramped = rodnet::testing::run_scene_text(
          shaped_cantilever(n, 3, 2, 0, 4, "curvature, twist"),
          "natural_shape_ramp_output");
        ASSERT_TRUE(ramped.failure.empty()) << ramped.failure;
        ASSERT_EQ(ramped.rows.back()[0], 1.0);
        double largest = 0;
        for (std::size_t step = 1; step < ramped.rows.size(); ++step)
          {
            const double lambda = ramped.rows[step][0];
            const double k = 3 * lambda, tau = 2 * lambda;
            const double w2 = k * k + tau * tau, w = std::sqrt(w2);
            const double R = k / w2, c = tau / w2;
            const double chord =
              std::sqrt(2 * R * R * (1 - std::cos(w)) + c * c * w2);
            const std::vector<double> &row = ramped.rows[step];
            const double               found =
              std::sqrt(row[1] * row[1] + row[2] * row[2] + row[3] * row[3]);
            largest = std::max(largest, std::abs(found / chord - 1));
            EXPECT_NEAR(found / chord, 1.0, 0.8 / (n * n))
              << n << " segments, step " << step;
          }
        std::cout << n << " segments: chord within " << largest
                  << " of the helix's" << std::endl;
      }
  }

  TEST(NaturalShapeRamp, EigenstrainOfChosenRod)
  {
    // Eigenstrain 0.1 ramped on rod 0 (the only one): the unloaded
    // cantilever grows to 1.1 at load factor 1, exactly (stress free).
    const RunSummary ramped = rodnet::testing::run_scene_text(
      shaped_cantilever(20, 0, 0, 0.1, 2, "eigenstrain: 0"),
      "natural_shape_ramp_eigenstrain");
    ASSERT_TRUE(ramped.failure.empty()) << ramped.failure;
    // The clamp holds the first segment (h = 1 / (n - 1/2), centred on
    // the start), which keeps its length: the rest, 1 - h/2 long, grows by
    // 5 % and 10 % at the two steps.
    const double rest = 1 - 0.5 / 19.5;
    EXPECT_NEAR(ramped.rows[1][1], 1 + 0.05 * rest, 1e-10);
    EXPECT_NEAR(ramped.rows[2][1], 1 + 0.1 * rest, 1e-10);
  }

  /// The chord 2 sin(k/2)/k of a unit arc of curvature @p k.
  double
  arc_chord(const double k)
  {
    return k == 0 ? 1.0 : 2 * std::sin(k / 2) / k;
  }

  TEST(NaturalShapeRamp, GrowsUnderAFixedMoment)
  {
    // Natural curvature k0 = 2 ramped in four steps under an end moment
    // M = 0.5 about d1 (EI1 = 1). With no force at the tip the internal
    // moment is M all along, EI1 (k - lambda k0) = M: at load factor
    // lambda the rod is the arc of curvature lambda k0 + M / EI1 with the
    // moment held at its full value (Loads/Fixed loads), and of curvature
    // lambda (k0 + M / EI1) with the moment ramped too (the default).
    // The polygon's curvature is the arc's to O(h^2): tolerance 0.8 / n^2.
    const unsigned int n = 100;
    for (const bool fixed : {true, false})
      {
        const RunSummary run = rodnet::testing::run_scene_text(
          shaped_cantilever(n, 2, 0, 0, 4, "curvature") +
            "subsection Loads\n  set Moments = end: 0,0,1 0.5\n"
            "  set Fixed loads = " +
            (fixed ? "true" : "false") + "\nend\n",
          "natural_shape_ramp_fixed_moment");
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        ASSERT_EQ(run.rows.back()[0], 1.0);
        for (std::size_t step = 1; step < run.rows.size(); ++step)
          {
            const double lambda = run.rows[step][0];
            const double k      = fixed ? 2 * lambda + 0.5 : lambda * 2.5;
            const std::vector<double> &row = run.rows[step];
            const double               chord =
              std::sqrt(row[1] * row[1] + row[2] * row[2] + row[3] * row[3]);
            EXPECT_NEAR(chord / arc_chord(k), 1.0, 0.8 / (n * n))
              << (fixed ? "fixed" : "ramped") << " moment, load factor "
              << lambda;
            // The elastic energy is that of the moment alone, measured
            // from the natural shape at lambda: L M^2 / (2 EI1), M the
            // applied moment at lambda, to the discrete hinges' cos(theta /
            // 2) between the moment and the curvature measure (below 2e-4
            // here). Measured from the unramped shape with the fixed
            // moment's potential, as it was, it is 1.875 at lambda = 1.
            const double moment = fixed ? 0.5 : 0.5 * lambda;
            const double energy = moment * moment / 2;
            EXPECT_NEAR(row[4], energy, 1e-3 * energy)
              << (fixed ? "fixed" : "ramped") << " moment, load factor "
              << lambda;
          }
      }
  }

  TEST(NaturalShapeRamp, FixedLoadsNeedSomethingToRamp)
  {
    try
      {
        rodnet::testing::run_scene_text(
          shaped_cantilever(20, 2, 0, 0, 1, "") +
            "subsection Loads\n  set Fixed loads = true\nend\n",
          "natural_shape_ramp_fixed_error");
        ADD_FAILURE() << "fixed loads with nothing ramped ran";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("entry \"Loads/Fixed loads\""),
                  std::string::npos)
          << e.what();
      }
  }

  TEST(NaturalShapeRamp, ErrorsNameTheEntry)
  {
    for (const std::string &ramp : {std::string("curvatures"),
                                    std::string("twist: 3"),
                                    std::string("eigenstrain: x"),
                                    std::string("twist:")})
      {
        try
          {
            rodnet::testing::run_scene_text(
              shaped_cantilever(20, 0, 0, 0, 1, ramp),
              "natural_shape_ramp_error");
            ADD_FAILURE() << "no error for \"" << ramp << "\"";
          }
        catch (const std::invalid_argument &e)
          {
            EXPECT_NE(std::string(e.what()).find(
                        "entry \"Loads/Ramped natural shape\""),
                      std::string::npos)
              << e.what();
          }
      }
  }
} // namespace
