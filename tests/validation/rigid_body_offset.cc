// Rigid bodies with their centre off the junction, x_c = x_j + R r_0
// (RigidBody::centre_offset; solvers/time/body_rotation_inertia.h,
// families/body_weight_family.h; doc/dynamics.md, "Rigid bodies"): a
// compound pendulum about a held junction (isotropic and tensor inertia)
// against sqrt(m g d / (J_c + m d^2)); a free body launched spinning, whose
// centre moves uniformly and whose momenta and energy are kept, in free
// flight and in free fall; the force of the centre against central differences and its exact
// energy balance, and the weight's lever against central differences. (Its
// statics: tests/validation/rigid_bodies.cc, WeightActsAtTheCentre.)
#include <core/motion.h>
#include <core/tensor_body_spin.h>
#include <solvers/time/body_rotation_inertia.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <families/body_weight_family.h>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>
#include <tests/common/assembled_derivatives.h>
#include <tests/common/rod_models.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// Light rod (rho A = 1e-6 kg/m): its inertia is 1e-9 of the bodies'.
  const RodInertia rod_inertia{1e-6, 1e-9, 0};

  /// @p body (mass, inertia, centre_offset) on a rotation handle "hub" at
  /// the start of a rod of length 0.1 along x in 2 segments, soft (EA = 1,
  /// EI = GJ = 0.01) and light: the body moves as if alone. The handle's
  /// position is held where @p pivot; the weight under @p gravity acts at
  /// the centre (a force at the vertex and BodyWeightFamily).
  std::unique_ptr<RodModel>
  body_on_handle(RigidBody body, const bool pivot, const Vector3 &gravity)
  {
    auto network = straight_network(2, Vector3(0, 0, 0), Vector3(0.1, 0, 0));
    const unsigned int start = network->rods()[0].vertices.front();
    network->add_rotation_handle("hub", start);
    auto model =
      elastic_model(std::move(network), RodStiffness{1, 1e-2, 1e-2, 1e-2});
    body.where      = "rigid body \"hub\"";
    body.attachment = start;
    model->add_rigid_body(body);
    if (pivot)
      model->fix_components("pivot", start, {{true, true, true}});
    if (gravity != Vector3::Zero())
      {
        model->add_point_force(start, body.mass * gravity);
        model->add_element_family(body_weight_family(*model, gravity));
      }
    model->finalize();
    return model;
  }

  /// The integrator's parameters: midpoint rule, steps of @p h to
  /// @p end_time, the Newton tolerance 1e-8 of the soft rod's forces.
  TimeIntegrator::Parameters
  midpoint(const double h, const double end_time, const double tolerance)
  {
    TimeIntegrator::Parameters p;
    p.integrator         = "midpoint";
    p.time_step          = h;
    p.end_time           = end_time;
    p.relative_tolerance = tolerance;
    p.progress_interval  = 0;
    return p;
  }

  /// One converged state of a run.
  struct BodyState
  {
    double  time;
    Vector3 omega, centre;
    Motion  motion;
  };

  /// The run of @p model from the junction's angular velocity @p omega_0
  /// and the centre's velocity @p centre_rate (the vertex then moves at
  /// centre_rate - omega_0 x r_0, the rod with it), steps of @p h.
  std::vector<BodyState>
  run_body(RodModel      &model,
           const Vector3 &omega_0,
           const Vector3 &centre_rate,
           const double   h,
           const double   end_time,
           const double   tolerance = 1e-8)
  {
    TimeIntegrator   integrator(model,
                              {rod_inertia},
                              midpoint(h, end_time, tolerance));
    const TensorBody body = tensor_bodies(model).front();
    VectorType       u = model.create_vector(), v = model.create_vector();
    const Vector3    x_j      = model.position(u, body.vertex);
    const Vector3    x_j_rate = centre_rate - omega_0.cross(body.offset);
    for (unsigned int i = 0; i < model.network().n_vertices(); ++i)
      if (!model.constraints().is_constrained(model.layout().vertex_dof(i, 0)))
        {
          const Vector3 rate =
            x_j_rate + omega_0.cross(model.position(u, i) - x_j);
          for (unsigned int c = 0; c < 3; ++c)
            v[model.layout().vertex_dof(i, c)] = rate[c];
        }
    for (unsigned int c = 0; c < 3; ++c)
      v[body.dofs[c]] = omega_0[c] / 2; // omega = 2 adot at a = 0
    std::vector<BodyState> states;
    const auto             record =
      [&](const double time, const VectorType &x, const VectorType &w) {
        states.push_back(
          {time,
           angular_velocity(body, x, w),
           model.position(x, body.vertex) + centre_arm(model, body, x),
           motion_of(model, integrator.mass_matrix(), x, w, 1)});
      };
    record(0, u, v);
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &info,
                       const VectorType               &x,
                       const VectorType &w) { record(info.time, x, w); });
    return states;
  }

  /// The mean period of omega_z from its sign changes (linearly
  /// interpolated).
  double
  period_of_swing(const std::vector<BodyState> &states)
  {
    std::vector<double> zeros;
    for (unsigned int i = 1; i < states.size(); ++i)
      {
        const double a = states[i - 1].omega[2], b = states[i].omega[2];
        if (a * b < 0)
          zeros.push_back(states[i - 1].time +
                          (states[i].time - states[i - 1].time) * a / (a - b));
      }
    EXPECT_GE(zeros.size(), 5u) << "the pendulum does not swing";
    if (zeros.size() < 2)
      return std::nan("");
    return 2 * (zeros.back() - zeros.front()) / (zeros.size() - 1);
  }

  /// The largest |E - E_0| over the run.
  double
  energy_drift(const std::vector<BodyState> &states)
  {
    const auto energy = [](const BodyState &s) {
      return s.motion.kinetic_energy + s.motion.potential_energy;
    };
    double drift = 0;
    for (const BodyState &s : states)
      drift = std::max(drift, std::abs(energy(s) - energy(states.front())));
    return drift;
  }

  /// A compound pendulum: mass 1 kg with the inertia @p J_c about its
  /// centre, d = 0.5 m below the held junction, g = 9.81 m/s^2, swinging
  /// about z at an amplitude of 0.01 rad, steps of h = 0.01 s. Small
  /// swings have omega_0 = sqrt(m g d / (J_zz + m d^2)) (about z, a
  /// principal axis of the inertia about the pivot), to a relative
  /// amplitude^2 / 16 = 6e-6; the midpoint rule's period is that of
  /// omega_h = (2 / h) atan(omega_0 h / 2), longer by (omega_0 h)^2 / 12 =
  /// 1.4e-4.
  void
  check_compound_pendulum(const Matrix3 &J_c, const char *name)
  {
    const double m = 1, d = 0.5, g = 9.81, h = 0.01, amplitude = 0.01;
    RigidBody    body;
    body.mass = 1;
    if (J_c.isDiagonal() && J_c(0, 0) == J_c(1, 1) && J_c(1, 1) == J_c(2, 2))
      body.axial_inertia = body.transverse_inertia = J_c(0, 0);
    else
      body.inertia_tensor = J_c;
    body.centre_offset   = Vector3(0, -d, 0);
    const auto   model   = body_on_handle(body, true, Vector3(0, -g, 0));
    const double omega_0 = std::sqrt(m * g * d / (J_c(2, 2) + m * d * d));
    const double period  = 2 * M_PI / omega_0;
    const double discrete_period = M_PI * h / std::atan(omega_0 * h / 2);
    const std::vector<BodyState> states =
      run_body(*model,
               Vector3(0, 0, amplitude * omega_0),
               Vector3::Zero(),
               h,
               3.3 * period);
    const double measured = period_of_swing(states);
    const double kinetic =
      (J_c(2, 2) + m * d * d) * std::pow(amplitude * omega_0, 2) / 2;
    std::cout << name << " compound pendulum: period " << measured
              << " s against sqrt(m g d / (J + m d^2))'s " << period
              << " s (relative " << measured / period - 1
              << ") and the midpoint rule's " << discrete_period
              << " s (relative " << measured / discrete_period - 1
              << "); energy drift " << energy_drift(states) / kinetic
              << " of the kinetic energy" << std::endl;
    EXPECT_NEAR(measured / period, 1, 2 * std::pow(omega_0 * h, 2) / 12);
    EXPECT_NEAR(measured / discrete_period, 1, 2e-5);
    EXPECT_LT(energy_drift(states), 1e-6 * kinetic);
  }

  TEST(RigidBodyOffset, CompoundPendulumIsotropic)
  {
    check_compound_pendulum(0.05 * Matrix3::Identity(), "isotropic");
  }

  TEST(RigidBodyOffset, CompoundPendulumTensor)
  {
    Matrix3 J_c;
    J_c << 0.04, 0.01, 0, 0.01, 0.06, 0, 0, 0, 0.08;
    check_compound_pendulum(J_c, "tensor");
  }

  // A free body: m = 2 kg, J_c = diag(1, 2, 3) kg m^2 rotated, its centre
  // r_0 = (0.3, -0.2, 0.1) m from the handle, launched spinning at omega_0
  // = (0.4, 1.5, -0.6) rad/s with its centre at |v_c| = 0.24 m/s (the
  // handle's rod, light, moving with it rigidly), Newton tolerance 1e-11.
  // No force acts on the whole: its linear momentum m v_c, its angular
  // momentum about the origin, x_c x m v_c + R J_c R^T omega, and its
  // energy are kept, and the centre moves uniformly, turning the body
  // about itself. Measured: the linear momentum changes by 1.3e-9 of
  // itself, the level of the same run without the offset (r_0 = 1e-9 of
  // it: 9e-10), which the midpoint rule keeps only to the Newton tolerance
  // in this nearly rigid motion (doc/dynamics.md, "Rigid bodies"); the
  // angular momentum by 8e-10, the energy by 4e-11; the centre is off
  // v_c t by 2.4e-7 m after 10 s: the light rod, pulled round by the
  // spin, takes its share of the motion.
  TEST(RigidBodyOffset, FreeFlight)
  {
    const Matrix3 Q =
      Eigen::AngleAxisd(0.4, Vector3(1, -1, 2).normalized()).toRotationMatrix();
    RigidBody body;
    body.mass           = 2;
    body.inertia_tensor = Q * Vector3(1, 2, 3).asDiagonal() * Q.transpose();
    body.centre_offset  = Vector3(0.3, -0.2, 0.1);
    const auto    model = body_on_handle(body, false, Vector3::Zero());
    const Vector3 omega_0(0.4, 1.5, -0.6), v_c(0.2, 0.1, -0.1);
    const double  end_time = 10;
    const std::vector<BodyState> states =
      run_body(*model, omega_0, v_c, 0.01, end_time, 1e-11);
    const Motion &first = states.front().motion;
    const Vector3 L_0 =
      body.centre_offset.cross(body.mass * v_c) + body.inertia_tensor * omega_0;
    double momentum = 0, angular = 0, energy = 0;
    for (const BodyState &s : states)
      {
        momentum =
          std::max(momentum,
                   (s.motion.linear_momentum - first.linear_momentum).norm());
        angular =
          std::max(angular,
                   (s.motion.angular_momentum - first.angular_momentum).norm());
      }
    energy                = energy_drift(states);
    const Vector3 centre  = states.back().centre;
    const Vector3 uniform = body.centre_offset + v_c * states.back().time;
    std::cout << "free flight: linear momentum "
              << first.linear_momentum.transpose() << " (m v_c "
              << (body.mass * v_c).transpose() << "), largest change "
              << momentum << "; angular momentum "
              << first.angular_momentum.transpose() << " (" << L_0.transpose()
              << "), largest change " << angular << "; energy drift "
              << energy / first.kinetic_energy
              << " of it; centre at t = " << states.back().time << " s off "
              << "uniform motion by " << (centre - uniform).norm() << " m"
              << std::endl;
    // The rod's share: 1e-7 kg of 2 kg.
    EXPECT_LT((first.linear_momentum - body.mass * v_c).norm(),
              1e-6 * body.mass * v_c.norm());
    EXPECT_LT((first.angular_momentum - L_0).norm(), 1e-6 * L_0.norm());
    EXPECT_LT(momentum, 5e-9 * body.mass * v_c.norm());
    EXPECT_LT(angular, 1e-6 * L_0.norm());
    EXPECT_LT(energy, 1e-8 * first.kinetic_energy);
    EXPECT_LT((centre - uniform).norm(), 1e-6 * v_c.norm() * end_time);
  }

  // The same body falling under g = 9.81 m/s^2 along -z for 3 s: its
  // weight, a force at the handle and a lever about it (BodyWeightFamily),
  // has no moment about the centre, which the centre's force on the
  // rotation rows cancels. The centre falls on the parabola x_0 + v_c t +
  // g t^2 / 2, the linear momentum grows by m g t and the angular
  // momentum about the centre, L - x_c x p, is kept, as is the energy with
  // the weight's potential. Measured at h = 0.01 s (h = 0.005 s): the
  // momentum is off m g t by 4.5e-7 (1.1e-7) of it, the centre off the
  // parabola by 3.3e-5 m (9.7e-6 m), the angular momentum about the
  // centre by 5.8e-5 (1.4e-5) of it: second order, from the midpoint
  // rule's gradients of the weight's lever at v / 2 (doc/dynamics.md);
  // the energy to 5e-13. (With the centre's moment mapped as r_n x (I +
  // C^T) F_c, also exact in energy, the angular momentum drifted by
  // 6.5e-3 (3.2e-3): first order.)
  TEST(RigidBodyOffset, FreeFall)
  {
    const Matrix3 Q =
      Eigen::AngleAxisd(0.4, Vector3(1, -1, 2).normalized()).toRotationMatrix();
    RigidBody body;
    body.mass           = 2;
    body.inertia_tensor = Q * Vector3(1, 2, 3).asDiagonal() * Q.transpose();
    body.centre_offset  = Vector3(0.3, -0.2, 0.1);
    const Vector3 g(0, 0, -9.81), omega_0(0.4, 1.5, -0.6), v_c(0.2, 0.1, -0.1);
    const auto    model = body_on_handle(body, false, g);
    const std::vector<BodyState> states =
      run_body(*model, omega_0, v_c, 0.01, 3, 1e-11);
    const auto about_centre = [](const BodyState &s) {
      return Vector3(s.motion.angular_momentum -
                     s.centre.cross(s.motion.linear_momentum));
    };
    const Vector3 L_c      = about_centre(states.front());
    double        momentum = 0, angular = 0, path = 0, kinetic = 0;
    for (const BodyState &s : states)
      {
        const Vector3 p =
          states.front().motion.linear_momentum + body.mass * g * s.time;
        momentum = std::max(momentum, (s.motion.linear_momentum - p).norm());
        angular  = std::max(angular, (about_centre(s) - L_c).norm());
        path     = std::max(path,
                        (s.centre - body.centre_offset - v_c * s.time -
                         g * s.time * s.time / 2)
                          .norm());
        kinetic  = std::max(kinetic, s.motion.kinetic_energy);
      }
    std::cout << "free fall: linear momentum off p_0 + m g t by " << momentum
              << " (" << momentum / (body.mass * g.norm() * 3)
              << " of m g t); angular momentum about the centre "
              << L_c.transpose() << " ("
              << (body.inertia_tensor * omega_0).transpose()
              << "), largest change " << angular / L_c.norm()
              << " of it; centre off the parabola by " << path
              << " m; energy drift " << energy_drift(states) / kinetic
              << " of the largest kinetic energy" << std::endl;
    EXPECT_LT((L_c - body.inertia_tensor * omega_0).norm(), 1e-6 * L_c.norm());
    EXPECT_LT(momentum, 1e-6 * body.mass * g.norm() * 3);
    EXPECT_LT(angular, 2e-4 * L_c.norm());
    EXPECT_LT(path, 1e-4);
    EXPECT_LT(energy_drift(states), 1e-9 * kinetic);
  }
} // namespace

namespace
{
  /// (F_c, g) of BodyRotationInertia::centre_force() at a step that moves
  /// the vertex by @p dx and turns by @p v.
  BodyRotationInertia::CentreStep
  centre_step(const Eigen::Matrix<double, 6, 1> &x)
  {
    const Vector3 r_n(0.3, -0.2, 0.5), vc_n(0.7, -0.4, 0.2);
    return BodyRotationInertia::centre_force(1.7,
                                             r_n,
                                             vc_n,
                                             x.head<3>(),
                                             x.tail<3>(),
                                             0.05);
  }

  // The Jacobian of the centre's force with respect to (Delta x_j, v)
  // against central differences, at a step that turns by 0.6 rad.
  TEST(RigidBodyOffset, CentreForceJacobianMatchesCentralDifferences)
  {
    Eigen::Matrix<double, 6, 1> x;
    x << 0.02, -0.01, 0.03, 0.1, -0.2, 0.2;
    const double                step  = 1e-6;
    const auto                  exact = centre_step(x).jacobian;
    Eigen::Matrix<double, 6, 6> differences;
    for (unsigned int c = 0; c < 6; ++c)
      {
        const Eigen::Matrix<double, 6, 1> e =
          step * Eigen::Matrix<double, 6, 1>::Unit(c);
        differences.col(c) =
          (centre_step(x + e).force - centre_step(x - e).force) / (2 * step);
      }
    const double error =
      (exact - differences).cwiseAbs().maxCoeff() / exact.cwiseAbs().maxCoeff();
    std::cout << "centre force Jacobian: largest difference " << error
              << " of the largest entry" << std::endl;
    EXPECT_LT(error, 1e-8);
  }

  // What the centre's force keeps: F_c . Delta x_j + g . v is the change
  // of 1/2 m |vc|^2 from vc_n to vc_{n+1} = 2 (Delta x_j + (C - I) r_n) /
  // h - vc_n, C the rotation of q = (1, v) (Eigen's), at any step.
  TEST(RigidBodyOffset, CentreForceKeepsEnergy)
  {
    const Vector3 r_n(0.3, -0.2, 0.5), vc_n(0.7, -0.4, 0.2);
    const Vector3 dx(0.02, -0.01, 0.03), v(0.1, -0.2, 0.2);
    const double  m = 1.7, h = 0.05;
    const Matrix3 C =
      Quaternion(1, v[0], v[1], v[2]).normalized().toRotationMatrix();
    const Vector3 vc_1   = 2 * (dx + C * r_n - r_n) / h - vc_n;
    const double  change = m * (vc_1.squaredNorm() - vc_n.squaredNorm()) / 2;
    const auto    f = BodyRotationInertia::centre_force(m, r_n, vc_n, dx, v, h);
    const double  work = f.force.head<3>().dot(dx) + f.force.tail<3>().dot(v);
    std::cout << "centre force: work " << work << ", change of 1/2 m |vc|^2 "
              << change << std::endl;
    EXPECT_NEAR(work, change, 1e-12 * std::abs(change));
  }

  // The weight's lever (BodyWeightFamily) in the assembled residual and
  // tangent against central differences of the energy and residual, at a
  // junction turned by 0.5 rad and a quaternion off the unit sphere.
  TEST(RigidBodyOffset, WeightDerivativesMatchCentralDifferences)
  {
    RigidBody body;
    body.mass          = 3;
    body.centre_offset = Vector3(0.2, 0.4, -0.3);
    const auto model   = body_on_handle(body, false, Vector3(0.5, -9.81, 1.0));
    VectorType u       = model->create_vector();
    const TensorBody   b   = tensor_bodies(*model).front();
    const unsigned int j   = b.junction;
    const double       q[] = {0.05, 0.1, -0.2, 0.15};
    for (unsigned int c = 0; c < 4; ++c)
      u[model->layout().rotation_dof(j, c)] = q[c];
    const DerivativeErrors errors =
      assembled_derivative_errors(*model, u, 0.8, 1e-6);
    std::cout << "weight lever: gradient error " << errors.residual
              << ", Hessian error " << errors.tangent
              << " of the largest entries" << std::endl;
    EXPECT_LT(errors.residual, 1e-7);
    EXPECT_LT(errors.tangent, 1e-7);
  }
} // namespace
