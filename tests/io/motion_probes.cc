// The probes of a model in motion (io/motion_probes.cc): kinetic energy of
// a rigid translation against m v0^2 / 2 (a rod, and a welded square whose
// junctions count once), and the momenta and energy of a free rod hit by a
// force pulse under the midpoint rule against the impulse and
// conservation; their refusal outside dynamics.
#include <common/run_scene_text.h>
#include <common/scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <stdexcept>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The straight rod from (0, 0, 0) to (1, 0, 0), free, of density 1000
  /// kg/m^3 and circular section of radius 0.01 m: mass rho pi r^2 L.
  const double rod_mass = 1000 * M_PI * 1e-4;

  const std::string motion_probes =
    "K: kinetic energy; P: potential energy; E: total energy; "
    "px: linear momentum x; py: linear momentum y; pz: linear momentum z; "
    "Lx: angular momentum x; Ly: angular momentum y; Lz: angular momentum z";

  /// The free rod in 8 segments, time stepping with @p integrator in steps
  /// of 5 ms to @p end_time; @p extra lines in subsection Time stepping.
  std::string
  free_rod(const std::string &integrator,
           const std::string &end_time,
           const std::string &extra)
  {
    return "subsection Geometry\n  set Segments = 8\nend\n"
           "subsection Material\n"
           "  set Density = 1000\n"
           "  subsection linear elastic\n"
           "    set Young's modulus = 1e6\n"
           "    set Cross section = circle\n"
           "    set Radius = 0.01\n"
           "  end\n"
           "end\n"
           "subsection Solver\n"
           "  set Method = time stepping\n"
           "  subsection Time stepping\n"
           "    set Integrator = " +
           integrator +
           "\n"
           "    set Time step = 0.005\n"
           "    set End time = " +
           end_time + "\n" + extra +
           "  end\n"
           "end\n" +
           probes_only(motion_probes);
  }

  TEST(MotionProbes, KineticEnergyOfARigidTranslation)
  {
    // v0 = (0.3, -0.4, 1.2): |v0|^2 = 1.69; the consistent mass matrix
    // moves as a rigid body, so 1/2 v.Mv = m |v0|^2 / 2, p = m v0 and
    // L = c x m v0 about the origin, c = (L/2, 0, 0) the centre of mass.
    const RunSummary run =
      run_scene_text(free_rod("midpoint",
                              "0.05",
                              "    set Initial velocity = 0.3; -0.4; 1.2\n"),
                     "motion_probes_translation");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 11u);
    const double m = rod_mass;
    for (const std::size_t k : {std::size_t(0), run.rows.size() - 1})
      {
        const std::vector<double> &row = run.rows[k];
        EXPECT_NEAR(row[probe_column(run, "K")], m * 1.69 / 2, 1e-12 * m);
        EXPECT_NEAR(row[probe_column(run, "P")], 0, 1e-12 * m);
        EXPECT_NEAR(row[probe_column(run, "px")], m * 0.3, 1e-12 * m);
        EXPECT_NEAR(row[probe_column(run, "py")], -m * 0.4, 1e-12 * m);
        EXPECT_NEAR(row[probe_column(run, "pz")], m * 1.2, 1e-12 * m);
        // About the origin, with the centre of mass at (1/2 + 0.3 t, ...).
        const double  t = row[0];
        const Vector3 c = Vector3(0.5, 0, 0) + t * Vector3(0.3, -0.4, 1.2);
        const Vector3 L = c.cross(m * Vector3(0.3, -0.4, 1.2));
        EXPECT_NEAR(row[probe_column(run, "Lx")], L[0], 1e-12 * m) << k;
        EXPECT_NEAR(row[probe_column(run, "Ly")], L[1], 1e-12 * m) << k;
        EXPECT_NEAR(row[probe_column(run, "Lz")], L[2], 1e-12 * m) << k;
      }
  }

  /// The force of the pulse (N) at the vertex "end" and its duration (s),
  /// ten steps of the midpoint rule, whose loads act at mid-step.
  const Vector3 pulse_force(0, 0.2, 0.05);
  const double  pulse_duration = 0.05;

  /// The free rod under pulse_force at its end while t < @p pulse_end,
  /// integrated by @p integrator to @p end_time, in motion_probes_@p name.
  RunSummary
  run_pulse(const std::string &integrator,
            const std::string &end_time,
            const std::string &pulse_end,
            const std::string &name)
  {
    return run_scene_text(free_rod(integrator,
                                   end_time,
                                   "    set Load factor = if(t < " + pulse_end +
                                     ", 1, 0)\n") +
                            "subsection Loads\n  set Point forces = end: " +
                            vector_text(pulse_force) + "\nend\n",
                          "motion_probes_" + name);
  }

  TEST(MotionProbes, ForcePulseOnAFreeRod)
  {
    // Loads at the load factor of t_n + h/2: exactly ten steps of the force.
    const RunSummary run = run_pulse("midpoint", "0.5", "0.05", "pulse");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 101u);
    // The impulse: the integral of the force over the pulse.
    const Vector3              impulse = pulse_force * pulse_duration;
    const std::vector<double> &after   = run.rows[10];
    ASSERT_NEAR(after[0], pulse_duration, 1e-12);
    const double energy = after[probe_column(run, "E")];
    EXPECT_GT(after[probe_column(run, "P")], 1e-3 * energy) << "no bending";
    const char *p[3] = {"px", "py", "pz"}, *L[3] = {"Lx", "Ly", "Lz"};
    double      drift_p = 0, drift_L = 0, drift_E = 0;
    for (std::size_t k = 10; k < run.rows.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const std::vector<double> &row = run.rows[k];
          drift_p =
            std::max(drift_p,
                     std::abs(row[probe_column(run, p[c])] - impulse[c]));
          drift_L = std::max(drift_L,
                             std::abs(row[probe_column(run, L[c])] -
                                      after[probe_column(run, L[c])]));
          drift_E =
            std::max(drift_E, std::abs(row[probe_column(run, "E")] - energy));
        }
    std::cout << "pulse: impulse " << impulse.transpose() << " N s, energy "
              << energy << " J; largest deviations after it: momentum "
              << drift_p << " N s, angular momentum " << drift_L
              << " N m s, energy " << drift_E << " J" << std::endl;
    // During the pulse (rows 0 to 9, load factor 1 at their times and
    // mid-steps) the total energy, with the work of the force, stays at its
    // initial 0; without that work it would grow as the kinetic energy.
    double during_E = 0;
    for (std::size_t k = 0; k < 10; ++k)
      during_E =
        std::max(during_E, std::abs(run.rows[k][probe_column(run, "E")]));
    const double kinetic_9 = run.rows[9][probe_column(run, "K")];
    std::cout << "during the pulse: largest |total energy| " << during_E
              << " J, kinetic energy at t = 0.045 s " << kinetic_9 << " J"
              << std::endl;
    EXPECT_LT(during_E, 1e-9 * kinetic_9);
    // The discrete-gradient correction has no resultant and no moment
    // (doc/dynamics.md, "Momenta under the midpoint rule"): the linear
    // momentum is the impulse to round-off (measured 4.8e-16 N s; 3.7e-6
    // with the correction along M d), the angular momentum kept to 4.1e-14
    // N m s (2.8e-6 before), the energy to the Newton tolerance.
    EXPECT_LT(drift_p, 1e-12 * impulse.norm());
    EXPECT_LT(drift_L, 1e-10 * impulse.norm());
    EXPECT_LT(drift_E, 1e-8 * energy);
  }

  TEST(MotionProbes, ForcePulseUnderBackwardEuler)
  {
    // Backward Euler: M (v_{n+1} - v_n) = h (f_{n+1} - grad W(u_{n+1})),
    // and the internal forces sum to zero, so the momentum is h times the
    // forces at the ends of the steps to round-off: 9 steps of the pulse
    // ending at 0.0475 s.
    const RunSummary run =
      run_pulse("backward euler", "0.2", "0.0475", "pulse_euler");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 41u);
    const char *p[3] = {"px", "py", "pz"};
    for (std::size_t k = 0; k < run.rows.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const Vector3 impulse = pulse_force * 0.005 * std::min<double>(k, 9);
          EXPECT_NEAR(run.rows[k][probe_column(run, p[c])],
                      impulse[c],
                      1e-12 * pulse_force.norm() * 0.045)
            << "row " << k << ", " << p[c];
        }
  }

  TEST(MotionProbes, RigidTranslationOfAWeldedSquare)
  {
    // One free square cell of side 1 (four rods welded at its corners,
    // rho A = 1000 pi 1e-4 each) in rigid translation: p = m v0 and
    // L = c x m v0, c = (1/2, 1/2, 0) + v0 t. A junction's vertex is named
    // by every rod end at it: counted once.
    const std::string scene =
      "subsection Geometry\n  set Generator = square lattice\n"
      "  set Cells = 1, 1\n  set Beam length = 1\n  set Segments = 4\n"
      "end\n" +
      free_rod("midpoint",
               "0.02",
               "    set Initial velocity = 0.3; -0.4; 1.2\n")
        .substr(
          std::string("subsection Geometry\n  set Segments = 8\nend\n").size());
    const RunSummary run = run_scene_text(scene, "motion_probes_square");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double  m = 4 * rod_mass;
    const Vector3 v0(0.3, -0.4, 1.2);
    for (const std::vector<double> &row : run.rows)
      {
        const Vector3 c    = Vector3(0.5, 0.5, 0) + row[0] * v0;
        const Vector3 L    = c.cross(m * v0);
        const char   *p[3] = {"px", "py", "pz"}, *l[3] = {"Lx", "Ly", "Lz"};
        for (unsigned int k = 0; k < 3; ++k)
          {
            EXPECT_NEAR(row[probe_column(run, p[k])], m * v0[k], 1e-12 * m);
            EXPECT_NEAR(row[probe_column(run, l[k])], L[k], 1e-12 * m);
          }
        EXPECT_NEAR(row[probe_column(run, "K")], m * 1.69 / 2, 1e-12 * m);
      }
  }

  TEST(MotionProbes, RefusedOutsideDynamics)
  {
    const std::string scene =
      "subsection Supports\n  set Clamped ends = start\nend\n" +
      direct_material() + probes_only("E: kinetic energy");
    try
      {
        run_scene_text(scene, "motion_probes_statics");
        FAIL() << "a kinetic energy probe in statics was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_EQ(std::string(e.what()),
                  "entry \"Output/Probes\", probe \"E\": energies and "
                  "momenta of the motion need dynamic time stepping "
                  "(Solver/Method = time stepping with an Integrator other "
                  "than quasi-static)");
      }
  }
} // namespace
