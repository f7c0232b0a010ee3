// Free flight of an unsupported right-angle frame after an impulse, under
// the midpoint rule with the momentum-free discrete gradient
// (doc/dynamics.md, "Momenta under the midpoint rule"). The frame
// (tests/common/free_frame.h) is that of Simo & Vu-Quoc's right-angle
// cantilever (CMAME 66, 1988) without its clamp, with the twist inertia of
// a slender section: a force at the tip and a moment at the corner act
// with a triangular time history (0 -> 1 -> 0 over 0 <= t <= 2), then the
// frame flies free, tumbling.
// References, independent of the code: the impulse of the force (the
// midpoint rule samples the loads at mid-step, exact for a load factor
// linear within each step), conservation of momenta and energy after the
// pulse; and, for the fallback of nearly rigid steps, the exact
// translation of a stressed rod in equilibrium.
#include <core/mass_matrix.h>
#include <core/motion.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/solver_failure.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>
#include <tests/common/free_frame.h>
#include <tests/common/rod_models.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// What a converged step of the flight shows.
  struct FlightState
  {
    double       time, step, energy;
    Vector3      momentum, angular_momentum, spin, leg;
    unsigned int iterations;
  };

  /// Sum over the twist DoFs of (M v) times the segment's unit tangent:
  /// the angular momentum of the sections' spin about their centrelines.
  Vector3
  spin_momentum(const RodModel   &model,
                const DofRoles   &roles,
                const VectorType &u,
                const VectorType &mv)
  {
    Vector3 spin = Vector3::Zero();
    for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
      if (roles.kind(d) == DofRoles::Kind::twist)
        {
          const auto [r, k] = roles.cell_place(roles.owner(d));
          const std::vector<unsigned int> &chain =
            model.network().rods()[r].vertices;
          const Vector3 e = model.configuration().position(u, chain[k + 1]) -
                            model.configuration().position(u, chain[k]);
          spin += mv[d] * e.normalized();
        }
    return spin;
  }

  /// Flies the frame of @p n segments per leg with time step @p h to
  /// @p end_time by the midpoint rule, its sections' inertia @p inertia.
  std::vector<FlightState>
  fly(const unsigned int n,
      const double       h,
      const double       end_time,
      const RodInertia  &inertia = frame_inertia)
  {
    FreeFrame                  frame = free_frame(n);
    RodModel                  &model = *frame.model;
    TimeIntegrator::Parameters p;
    p.integrator         = "midpoint";
    p.time_step          = h;
    p.end_time           = end_time;
    p.load_factor        = triangle_pulse;
    p.relative_tolerance = 1e-10;
    p.progress_interval  = 0;
    TimeIntegrator           integrator(model,
                              std::vector<RodInertia>(2, inertia),
                              p,
                              nullptr);
    const DofRoles           roles(model);
    std::vector<FlightState> flight;
    VectorType u = model.create_vector(), v = model.create_vector(),
               mv = model.create_vector();
    integrator.run(
      u,
      v,
      [&](const TimeIntegrator::StepInfo &info,
          const VectorType               &x,
          const VectorType               &w) {
        const Motion m =
          motion_of(model, integrator.mass_matrix(), x, w, info.load_factor);
        integrator.mass_matrix().vmult(mv, w);
        flight.push_back({info.time,
                          info.time_step,
                          m.kinetic_energy + m.potential_energy,
                          m.linear_momentum,
                          m.angular_momentum,
                          spin_momentum(model, roles, x, mv),
                          model.configuration().position(x, frame.tip) -
                            model.configuration().position(x, frame.corner),
                          info.iterations});
      });
    return flight;
  }

  /// The first state of @p flight at the end of the pulse.
  std::size_t
  pulse_end(const std::vector<FlightState> &flight)
  {
    std::size_t after = 0;
    while (flight[after].time < frame_pulse_end - 1e-9)
      ++after;
    return after;
  }

  /// The largest |L - L_0| of @p flight after the pulse (L_0 at its end).
  double
  angular_momentum_drift(const std::vector<FlightState> &flight)
  {
    const std::size_t after = pulse_end(flight);
    double            drift = 0;
    for (std::size_t k = after; k < flight.size(); ++k)
      drift = std::max(
        drift,
        (flight[k].angular_momentum - flight[after].angular_momentum).norm());
    return drift;
  }

  TEST(FreeFlight, FrameAfterAnImpulse)
  {
    const double                   h = 0.01, end = 20;
    const std::vector<FlightState> flight = fly(10, h, end);
    ASSERT_NEAR(flight.back().time, end, 1e-12);

    // Linear momentum: after each step, sum_j h_j F lambda(t_j + h_j/2),
    // the impulse of the loads at the midpoint rule's load times (internal
    // forces sum to zero, and so does the discrete-gradient correction);
    // after the pulse, F int lambda dt = F exactly (lambda is linear
    // within each step). To round-off: that of the linear solves, whose
    // last increment leaves an error of ~1e-8 of the previous residual in
    // the resultant, accumulates over the steps (1.3e-10 N s after 2000
    // steps, 3.2e-12 of the impulse): 1e-12 of the impulse per 100 steps.
    // With the correction along M d (before): 0.17 N s.
    double sampled = 0, largest_p = 0;
    for (const FlightState &s : flight)
      {
        sampled += s.step * triangle_pulse(s.time - s.step / 2);
        largest_p =
          std::max(largest_p, (s.momentum - frame_tip_force * sampled).norm());
      }
    EXPECT_NEAR(sampled, 1, 1e-14);
    EXPECT_LT(largest_p, 1e-12 * frame_tip_force.norm() * flight.size() / 100);

    // From the end of the pulse on: energy and angular momentum.
    const std::size_t  after   = pulse_end(flight);
    const FlightState &start   = flight[after];
    const Vector3      L0      = start.angular_momentum;
    const Vector3      centre0 = L0 - start.spin;
    double             drift_E = 0, drift_L = 0, drift_centre = 0, turned = 0;
    double             largest_spin    = 0;
    unsigned int       most_iterations = 0;
    for (std::size_t k = after; k < flight.size(); ++k)
      {
        const FlightState &s = flight[k];
        drift_E      = std::max(drift_E, std::abs(s.energy - start.energy));
        drift_L      = std::max(drift_L, (s.angular_momentum - L0).norm());
        drift_centre = std::max(drift_centre,
                                (s.angular_momentum - s.spin - centre0).norm());
        largest_spin = std::max(largest_spin, s.spin.norm());
        // The second leg starts along e_y.
        turned =
          std::max(turned,
                   std::acos(std::clamp(s.leg.normalized()[1], -1.0, 1.0)));
        most_iterations = std::max(most_iterations, s.iterations);
      }
    std::cout << "free frame, h = " << h << ": linear momentum "
              << flight.back().momentum.transpose() << ", largest deviation "
              << largest_p << " N s; energy " << start.energy << " J, drift "
              << drift_E << " J; angular momentum " << L0.transpose()
              << " (|L| " << L0.norm() << "), drift " << drift_L
              << ", of the centreline alone " << drift_centre
              << ", largest spin " << largest_spin
              << "; largest turn of the second leg " << turned
              << " rad; at most " << most_iterations
              << " Newton iterations per step" << std::endl;
    EXPECT_GT(turned, 2.0) << "no large rotation";
    EXPECT_LT(drift_E, 1e-8 * start.energy);
    // The angular momentum is conserved by the exact motion; the discrete
    // one keeps it to a deviation of first order in h (doc/dynamics.md).
    // Measured: 4.9e-3 (9.4e-6 |L|) with the spin; 0.41 (7.9e-4 |L|) for
    // the centreline alone, which exchanges it with the spin through the
    // gyroscopic force (GyroscopicCoupling). Without that force, 0.124
    // (2.4e-4 |L|), whatever h; with the correction along M d (before
    // RigidMotionSplit), 4.1e-3 |L|.
    EXPECT_LT(drift_L, 5e-5 * L0.norm());
    EXPECT_LT(drift_centre, 1.5e-3 * L0.norm());
  }

  // The frame with Simo & Vu-Quoc's own stocky sections, rho J = 20 and
  // rho I_b = 10 (against rho A L^2 = 100 of a leg): the sections' spin
  // turns with the tangents, and the gyroscopic force of
  // GyroscopicCoupling must turn it (doc/dynamics.md). Reference: the
  // angular momentum is conserved by the exact motion; the discrete one
  // keeps it to a deviation of first order in h (0.0032 |L| at h = 0.01,
  // 0.0063 |L| at h = 0.02). Without the force: 820 against |L| = 588,
  // whatever h, the spin turned with no torque to balance it.
  TEST(FreeFlight, StockyFrameKeepsItsAngularMomentum)
  {
    const RodInertia               stocky{1, 20, 10};
    const std::vector<FlightState> fine   = fly(10, 0.01, 20, stocky);
    const std::vector<FlightState> coarse = fly(10, 0.02, 20, stocky);
    const double L0           = fine[pulse_end(fine)].angular_momentum.norm();
    const double fine_drift   = angular_momentum_drift(fine),
                 coarse_drift = angular_momentum_drift(coarse);
    double drift_E            = 0;
    for (std::size_t k = pulse_end(fine); k < fine.size(); ++k)
      drift_E =
        std::max(drift_E,
                 std::abs(fine[k].energy - fine[pulse_end(fine)].energy));
    std::cout << "stocky frame: |L| " << L0 << ", largest deviation "
              << fine_drift << " (h = 0.01), " << coarse_drift
              << " (h = 0.02); energy drift " << drift_E << " J of "
              << fine[pulse_end(fine)].energy << " J" << std::endl;
    EXPECT_LT(fine_drift, 5e-3 * L0);
    // First order: halving the step halves the deviation.
    EXPECT_LT(fine_drift, 0.6 * coarse_drift);
    EXPECT_LT(drift_E, 1e-8 * fine[pulse_end(fine)].energy);
  }

  // A free symmetric top: a straight rod (L = 1, 8 segments, rho A = 1,
  // rho J = 0.05, rho I_b = 0.025, stiff: EA = 1e6, EI = GJ = 1e3)
  // spinning about its line at omega_3 = 10 rad/s and turning about e_z at
  // omega_t = 4 rad/s. Reference (Euler's torque-free symmetric body; the
  // rod stretches by 1e-5 under the centrifugal forces): its axis turns
  // about the constant angular momentum
  // L = I_3 omega_3 e_x + I_t omega_t e_z at the rate |L| / I_t, with
  // I_3 = rho J L and I_t = rho A L^3 / 12 + rho I_b L (exact for the
  // consistent mass, doc/theory.md), on a cone of half-angle 41 degrees.
  // Measured: 5.0e-5 from Euler's axis over a second (one turn). Without
  // the spin's gyroscopic force the axis stays in the plane normal to e_z
  // (3e-9 off it) and ends 1.79 from Euler's.
  TEST(FreeFlight, SpinningRodPrecessesAsASymmetricTop)
  {
    const double     rod_length = 1, omega_3 = 10, omega_t = 4, h = 2e-3;
    const RodInertia inertia{1, 0.05, 0.025};
    const std::unique_ptr<RodModel> rod =
      elastic_model(straight_network(8,
                                     Vector3(-rod_length / 2, 0, 0),
                                     Vector3(rod_length / 2, 0, 0)),
                    frame_stiffness);
    RodModel &model = *rod;
    model.finalize();
    const std::vector<unsigned int> &chain = model.network().rods()[0].vertices;
    const DofRoles                   roles(model);
    VectorType u = model.create_vector(), v = model.create_vector();
    for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
      if (roles.kind(d) == DofRoles::Kind::twist)
        v[d] = omega_3;
    for (const unsigned int i : chain)
      {
        const Vector3 velocity =
          omega_t * Vector3::UnitZ().cross(model.position(u, i));
        for (unsigned int c = 0; c < 3; ++c)
          v[model.layout().vertex_dof(i, c)] = velocity[c];
      }
    const double I_3 = inertia.rotational_inertia_per_length * rod_length,
                 I_t = inertia.mass_per_length * std::pow(rod_length, 3) / 12 +
                       inertia.rotary_inertia_per_length * rod_length;
    const Vector3 L =
      I_3 * omega_3 * Vector3::UnitX() + I_t * omega_t * Vector3::UnitZ();

    TimeIntegrator::Parameters p;
    p.integrator        = "midpoint";
    p.time_step         = h;
    p.end_time          = 1;
    p.progress_interval = 0;
    // Every step is a rigid motion but for the small bending that carries
    // the gyroscopic moments; at the default 1e-9 the residual of some
    // steps stalls at its rounding (5e-8 N against 2.2e-8 N).
    p.relative_tolerance = 1e-8;
    TimeIntegrator integrator(model, {inertia}, p);
    double         largest = 0, off_plane = 0;
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &info,
                       const VectorType               &x,
                       const VectorType &) {
                     const Vector3 axis = (model.position(x, chain.back()) -
                                           model.position(x, chain.front()))
                                            .normalized();
                     const Vector3 exact =
                       Eigen::AngleAxisd(L.norm() / I_t * info.time,
                                         L.normalized()) *
                       Vector3::UnitX();
                     largest   = std::max(largest, (axis - exact).norm());
                     off_plane = std::max(off_plane, std::abs(axis[2]));
                   });
    std::cout << "symmetric top: precession " << L.norm() / I_t
              << " rad/s about L = " << L.transpose()
              << "; largest distance of the axis to Euler's " << largest
              << ", largest e_z component " << off_plane << std::endl;
    EXPECT_GT(off_plane, 0.9) << "the axis did not leave the plane";
    EXPECT_LT(largest, 1e-3);
  }

  // The fallback of MidpointScheme for steps that are rigid motions: a
  // straight rod (L = 1, 8 segments, the frame's section) stretched
  // uniformly by eps = 1e-3 and held by the end forces +-EA eps that keep
  // it so (an equilibrium of the discrete rod: every segment carries EA
  // eps), moving at v0 = (0.3, -0.4, 1.2). The exact motion is the
  // translation x0 + v0 t with the stored energy EA eps^2 L / 2 kept. Its
  // steps are translations to rounding (d_def ~ 1e-16 d): dividing the
  // energy's rounding by |d_def|_M^2 would put an arbitrary force on the
  // rod; the fallback to w = M d keeps the translation.
  TEST(FreeFlight, StressedRodInTranslation)
  {
    const double                    eps = 1e-3, EA = frame_stiffness.EA;
    const Vector3                   v0(0.3, -0.4, 1.2);
    const std::unique_ptr<RodModel> rod =
      elastic_model(straight_network(8), frame_stiffness);
    RodModel                        &model = *rod;
    const std::vector<unsigned int> &chain = model.network().rods()[0].vertices;
    model.add_point_force(chain.front(), Vector3(-EA * eps, 0, 0));
    model.add_point_force(chain.back(), Vector3(EA * eps, 0, 0));
    model.finalize();

    VectorType u = model.create_vector(), v = model.create_vector();
    for (const unsigned int i : chain)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const global_dof_index d = model.layout().vertex_dof(i, c);
          u[d] = c == 0 ? eps * model.position(u, i)[0] : 0.0;
          v[d] = v0[c];
        }
    // Equilibrium: the residual of the stretched rod under its loads.
    VectorType r = model.create_vector();
    model.assemble(u, 1, &r, nullptr);
    ASSERT_LT(r.linfty_norm(), 1e-9 * EA * eps);

    TimeIntegrator::Parameters p;
    p.integrator        = "midpoint";
    p.time_step         = 0.01;
    p.end_time          = 0.5;
    p.progress_interval = 0;
    TimeIntegrator   integrator(model, {frame_inertia}, p);
    const VectorType u0 = u;
    integrator.run(u, v, [](const auto &, const auto &, const auto &) {});
    double deviation = 0;
    for (const unsigned int i : chain)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const global_dof_index d = model.layout().vertex_dof(i, c);
          deviation                = std::max(deviation,
                               std::abs(u[d] - u0[d] - 0.5 * v0[c]) +
                                 std::abs(v[d] - v0[c]));
        }
    std::cout << "stressed rod in translation: largest deviation from "
              << "x0 + v0 t and v0 after 50 steps " << deviation << std::endl;
    EXPECT_LT(deviation, 1e-12);
  }
} // namespace
