// Loads/Imperfections: small forces and moments held at their full value
// from the first step on (Magnitude = held) or ramped by the load factor
// (ramped), independently of the other loads, which ramp as always. A
// cantilever whose natural curvature grows under a ramped end moment and a
// held (ramped) imperfection moment is the arc of the curvature that the
// moments and the natural shape give at each load factor; one whose
// eigenstrain grows under a ramped and a held (ramped) axial force at its
// tip has the length of that strain; a held imperfection with nothing
// else ramped, or a ramped one under Loads/Fixed loads, is refused naming
// Loads/Imperfections/Magnitude.
#include <common/run_scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace
{
  using namespace rodnet;

  /// A unit cantilever along x of @p n segments, clamped at its start
  /// (first segment centred on it), EA = 100, EI1 = 1 (about d1 = e_z),
  /// with natural curvature @p curvature and eigenstrain @p eigenstrain
  /// ramped in four steps, the Loads entries @p loads and the
  /// imperfections @p imperfections (subsection Loads/Imperfections); the
  /// probes: the tip's position.
  std::string
  imperfect_cantilever(const unsigned int n,
                       const double       curvature,
                       const double       eigenstrain,
                       const std::string &loads,
                       const std::string &imperfections)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Geometry\n  set Segments = " << n
      << "\n  set Clamp at first segment midpoint = true\n"
         "  set Director d1 = 0, 0, 1\nend\n"
         "subsection Material\n  subsection linear elastic\n"
         "    set Stiffness input = direct\n    set EA = 100\n"
         "    set EI1 = 1\n    set EI2 = 2\n    set GJ = 1\n"
      << "    set Natural curvature 1 = " << curvature
      << "\n    set Axial eigenstrain = " << eigenstrain
      << "\n  end\nend\n"
         "subsection Supports\n  set Clamped ends = start\nend\n"
         "subsection Loads\n  set Steps = 4\n"
         "  set Ramped natural shape = curvature, eigenstrain\n"
      << loads << "  subsection Imperfections\n"
      << imperfections
      << "  end\nend\n"
         "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
         "  set Probes = x: position end x; y: position end y; "
         "z: position end z\nend\n";
    return s.str();
  }

  /// The chord 2 sin(k/2)/k of a unit arc of curvature @p k.
  double
  chord_of_unit_arc(const double k)
  {
    return k == 0 ? 1.0 : 2 * std::sin(k / 2) / k;
  }

  TEST(Imperfections, HeldOrRampedMomentBesideARampedMoment)
  {
    // Natural curvature k0 = 2 and the end moment M = 0.5 ramped, the
    // imperfection m = 0.1 at the same end: with no force at the tip the
    // internal moment is the applied one all along, EI1 (k - lambda k0) =
    // lambda M + m (held) or lambda (M + m) (ramped). The polygon's
    // curvature is the arc's to O(h^2): tolerance 0.8 / n^2.
    const unsigned int n = 100;
    for (const std::string magnitude : {"held", "ramped"})
      {
        const RunSummary run = rodnet::testing::run_scene_text(
          imperfect_cantilever(n,
                               2,
                               0,
                               "  set Moments = end: 0,0,1 0.5\n",
                               "    set Moments = end: 0,0,1 0.1\n"
                               "    set Magnitude = " +
                                 magnitude + "\n"),
          "imperfections_moment");
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        ASSERT_EQ(run.rows.size(), 5u);
        for (std::size_t step = 1; step < run.rows.size(); ++step)
          {
            const double lambda = run.rows[step][0];
            const double k =
              magnitude == "held" ? 2.5 * lambda + 0.1 : 2.6 * lambda;
            const std::vector<double> &row = run.rows[step];
            const double               chord =
              std::sqrt(row[1] * row[1] + row[2] * row[2] + row[3] * row[3]);
            EXPECT_NEAR(chord / chord_of_unit_arc(k), 1.0, 0.8 / (n * n))
              << magnitude << " imperfection, load factor " << lambda;
          }
      }
  }

  TEST(Imperfections, HeldOrRampedForceBesideARampedForce)
  {
    // Eigenstrain e0 = 0.1 and the axial tip force P = 2 ramped, the
    // imperfection f = 1 at the tip: the free length 1 - h/2 (the clamp
    // holds half the first segment, h = 1 / (n - 1/2)) stretches by
    // lambda e0 + (lambda P + f) / EA (held) or lambda (e0 + (P + f) / EA)
    // (ramped), exactly.
    const unsigned int n    = 20;
    const double       rest = 1 - 0.5 / (n - 0.5);
    for (const std::string magnitude : {"held", "ramped"})
      {
        const RunSummary run = rodnet::testing::run_scene_text(
          imperfect_cantilever(n,
                               0,
                               0.1,
                               "  set Point forces = end: 2, 0, 0\n",
                               "    set Point forces = end: 1, 0, 0\n"
                               "    set Magnitude = " +
                                 magnitude + "\n"),
          "imperfections_force");
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        for (std::size_t step = 1; step < run.rows.size(); ++step)
          {
            const double lambda = run.rows[step][0];
            const double strain = magnitude == "held" ?
                                    lambda * 0.1 + (lambda * 2 + 1) / 100 :
                                    lambda * (0.1 + 3.0 / 100);
            EXPECT_NEAR(run.rows[step][1], 1 + rest * strain, 1e-10)
              << magnitude << " imperfection, load factor " << lambda;
          }
      }
  }

  /// The message of the std::invalid_argument that building @p scene
  /// throws, or "" if it throws none.
  std::string
  imperfection_refusal(const std::string &scene)
  {
    try
      {
        rodnet::testing::run_scene_text(scene, "imperfections_refused");
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }

  TEST(Imperfections, MagnitudeThatCannotActIsRefused)
  {
    const std::string entry = "entry \"Loads/Imperfections/Magnitude\": ";
    // Nothing ramped but the held imperfection (no natural shape ramped:
    // the material has none to ramp, so a plain cantilever).
    const std::string plain =
      "subsection Material\n  subsection linear elastic\n"
      "    set Stiffness input = direct\n    set EA = 100\n"
      "    set EI1 = 1\n    set EI2 = 1\n    set GJ = 1\n  end\nend\n"
      "subsection Supports\n  set Clamped ends = start\nend\n"
      "subsection Output\n  set Write VTU = false\n  set Plot = false\nend\n";
    EXPECT_NE(imperfection_refusal(
                plain + "subsection Loads\n  subsection Imperfections\n"
                        "    set Point forces = end: 0, 1e-3, 0\n"
                        "  end\nend\n")
                .find(entry + "the imperfections are held at their full "
                              "value and the load factor has nothing else "
                              "to ramp"),
              std::string::npos);
    // The same beside a ramped load runs.
    EXPECT_EQ(imperfection_refusal(plain +
                                   "subsection Loads\n  set Steps = 1\n"
                                   "  set Point forces = end: 0, 0, 1e-3\n"
                                   "  subsection Imperfections\n"
                                   "    set Point forces = end: 0, 1e-3, 0\n"
                                   "  end\nend\n"),
              "");
    // Ramped while Fixed loads holds every load.
    EXPECT_NE(imperfection_refusal(
                imperfect_cantilever(10,
                                     0,
                                     0.1,
                                     "  set Fixed loads = true\n",
                                     "    set Point forces = end: 1, 0, 0\n"
                                     "    set Magnitude = ramped\n"))
                .find(entry + "\"ramped\" contradicts Loads/Fixed loads = "
                              "true"),
              std::string::npos);
  }
} // namespace
