// Rigid bodies with a general inertia tensor at a junction under the
// midpoint rule (solvers/time/body_rotation_inertia.h; doc/dynamics.md, "Rigid
// bodies"): a torque-free asymmetric top, J_0 = diag(1, 2, 3) kg m^2 on a
// rotation handle at the end of a massless stiff rod, spinning about its
// largest axis (the wobble frequency of Euler's equations linearized about
// the spin) and about its intermediate axis (the tumbling of Dzhanibekov's
// nut, against a fine Runge-Kutta integration of Euler's equations written
// here); its spatial angular momentum and energy, read by the probes
// (motion_of()), kept; and the Jacobian of the body's force against
// central differences.
#include <core/motion.h>
#include <core/tensor_body_spin.h>
#include <solvers/time/body_rotation_inertia.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>
#include <tests/common/rod_models.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The principal moments of the top, along x, y, z (kg m^2).
  const Vector3 moments(1, 2, 3);

  /// A body of mass 1 kg and J_0 = diag(moments) on a rotation handle at
  /// the start of a rod of length 0.1 along x in 2 segments, light
  /// (rod_inertia) and soft (EA = 1, EI = GJ = 0.01): it turns with the
  /// handle, its inertia, rho A L^3 / 3 = 3.3e-10 kg m^2 about the handle,
  /// is 1e-10 of the body's, and its torques on the handle are small, so
  /// the body is a free rigid body about its centre. (A rod without mass
  /// would be held in equilibrium at the midpoint of each step, (x_n +
  /// x_{n+1}) / 2, which a finite rotation shortens: strained, the steps
  /// failed. A stiff rod, EA = 1e6, EI = GJ = 1e3, exchanges angular
  /// momentum with the body, 4e-5 |L| over the wobble test and 6e-5 over
  /// the tumbling one: the first-order deviation of the rods' midpoint
  /// steps with reference frames fixed over a step, doc/dynamics.md.)
  std::unique_ptr<RodModel>
  top_model()
  {
    auto network = straight_network(2, Vector3(0, 0, 0), Vector3(0.1, 0, 0));
    const unsigned int start = network->rods()[0].vertices.front();
    network->add_rotation_handle("hub", start);
    auto model =
      elastic_model(std::move(network), RodStiffness{1, 1e-2, 1e-2, 1e-2});
    RigidBody body;
    body.where          = "rigid body \"hub\"";
    body.attachment     = start;
    body.mass           = 1;
    body.inertia_tensor = moments.asDiagonal();
    model->add_rigid_body(body);
    model->finalize();
    return model;
  }

  const RodInertia rod_inertia{1e-6, 1e-9, 0};

  /// The top at one converged step.
  struct TopState
  {
    double time;
    /// R^T omega, the angular velocity in the body's axes.
    Vector3 body_omega;
    /// The probes' angular momentum and total energy.
    Vector3 momentum;
    double  energy;
  };

  /// The top's motion from the angular velocity @p omega_0 (in space and
  /// body axes, which agree at t = 0) to @p end_time, steps of @p h.
  std::vector<TopState>
  spin_top(const Vector3 &omega_0, const double h, const double end_time)
  {
    const std::unique_ptr<RodModel> top   = top_model();
    RodModel                       &model = *top;
    TimeIntegrator::Parameters      p;
    p.integrator = "midpoint";
    p.time_step  = h;
    p.end_time   = end_time;
    // The soft rod's forces set the scale of the residual criterion: at
    // 1e-10 of them Newton stalls at the rounding of the body's moments
    // (3e-12 N m of 600 N m); 1e-8 of them is still 1e-10 N m.
    p.relative_tolerance = 1e-8;
    p.progress_interval  = 0;
    TimeIntegrator   integrator(model, {rod_inertia}, p, nullptr);
    const TensorBody body = tensor_bodies(model).front();
    VectorType       u = model.create_vector(), v = model.create_vector();
    // omega = 2 adot at the increment a = 0.
    for (unsigned int c = 0; c < 3; ++c)
      v[body.dofs[c]] = omega_0[c] / 2;
    std::vector<TopState> states;
    const auto            record =
      [&](const double time, const VectorType &x, const VectorType &w) {
        const Matrix3 R =
          model.junction_rotation(x, body.junction).toRotationMatrix();
        const Motion m = motion_of(model, integrator.mass_matrix(), x, w, 1);
        states.push_back({time,
                          R.transpose() * angular_velocity(body, x, w),
                          m.angular_momentum,
                          m.kinetic_energy + m.potential_energy});
      };
    record(0, u, v);
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &info,
                       const VectorType               &x,
                       const VectorType &w) { record(info.time, x, w); });
    return states;
  }

  /// The times at which component @p c of the body's angular velocity
  /// changes sign, linearly interpolated between the states.
  std::vector<double>
  sign_changes(const std::vector<TopState> &states, const unsigned int c)
  {
    std::vector<double> times;
    for (unsigned int i = 1; i < states.size(); ++i)
      {
        const double a = states[i - 1].body_omega[c],
                     b = states[i].body_omega[c];
        if (a * b < 0)
          times.push_back(states[i - 1].time +
                          (states[i].time - states[i - 1].time) * a / (a - b));
      }
    return times;
  }

  /// The largest deviation of the angular momentum (relative to |L|) and
  /// of the energy (relative to E) from their initial values.
  std::pair<double, double>
  conservation(const std::vector<TopState> &states)
  {
    double momentum = 0, energy = 0;
    for (const TopState &s : states)
      {
        momentum = std::max(momentum,
                            (s.momentum - states[0].momentum).norm() /
                              states[0].momentum.norm());
        energy =
          std::max(energy,
                   std::abs(s.energy - states[0].energy) / states[0].energy);
      }
    return {momentum, energy};
  }

  // Spin Omega = 2 rad/s about the largest axis z with omega_x = 1e-3
  // Omega: omega_x and omega_y in body axes oscillate at Euler's
  // lambda = Omega sqrt((I3 - I1)(I3 - I2) / (I1 I2)) = 2 rad/s (Landau &
  // Lifshitz, Mechanics, section 37), to a relative (omega_x / Omega)^2
  // from the amplitude. Omega h = 0.02: the midpoint rule's phase error is
  // of order (lambda h)^2 / 12 = 3e-5.
  TEST(RigidBodyTensor, WobbleAboutTheLargestAxis)
  {
    const double Omega = 2, h = 0.01;
    const double lambda =
      Omega * std::sqrt((moments[2] - moments[0]) * (moments[2] - moments[1]) /
                        (moments[0] * moments[1]));
    const double                period = 2 * M_PI / lambda;
    const Vector3               omega_0(1e-3 * Omega, 0, Omega);
    const std::vector<TopState> states = spin_top(omega_0, h, 3.2 * period);
    const std::vector<double>   zeros  = sign_changes(states, 0);
    ASSERT_GE(zeros.size(), 6u) << "omega_x does not oscillate";
    // Half a period between sign changes.
    const double measured =
      2 * (zeros.back() - zeros.front()) / (zeros.size() - 1);
    const auto [momentum, energy] = conservation(states);
    // The probes count the body: L = J_0 omega_0, K = omega_0.J_0 omega_0/2.
    const Vector3 L_0 = moments.cwiseProduct(omega_0);
    std::cout << "wobble about the largest axis: period " << measured
              << " s against Euler's " << period << " s (relative "
              << measured / period - 1 << "); |L - L_0| / |L| " << momentum
              << ", |E - E_0| / E " << energy << "; L_0 "
              << states[0].momentum.transpose() << std::endl;
    EXPECT_NEAR(measured / period, 1, 2e-4);
    EXPECT_LT((states[0].momentum - L_0).norm(), 1e-14 * L_0.norm());
    EXPECT_NEAR(states[0].energy, omega_0.dot(L_0) / 2, 1e-14);
    EXPECT_LT(momentum, 2e-6);
    EXPECT_LT(energy, 1e-9);
  }

  /// Euler's equations of the torque-free body in its axes, dPi/dt = Pi x
  /// W, Pi = J_0 W, by the classical Runge-Kutta rule with steps of @p dt
  /// from @p W_0 to @p end_time: the times at which W_y changes sign.
  std::vector<double>
  euler_sign_changes(const Vector3 &W_0, const double dt, const double end_time)
  {
    const auto rate = [](const Vector3 &W) {
      return Vector3(moments.cwiseProduct(W).cross(W).cwiseQuotient(moments));
    };
    std::vector<double> times;
    Vector3             W = W_0;
    for (double t = 0; t < end_time; t += dt)
      {
        const Vector3 k1 = rate(W), k2 = rate(W + dt / 2 * k1),
                      k3 = rate(W + dt / 2 * k2), k4 = rate(W + dt * k3);
        const Vector3 next = W + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        if (W[1] * next[1] < 0)
          times.push_back(t + dt * W[1] / (W[1] - next[1]));
        W = next;
      }
    return times;
  }

  // Spin 2 rad/s about the intermediate axis y, perturbed by omega_x =
  // 0.02 rad/s: the body flips over and back (Dzhanibekov's nut), omega_y
  // changing sign every half period. Each sign change of the midpoint run
  // against Euler's equations integrated by Runge-Kutta at dt = 1e-4 (a
  // step 100 times shorter, error of order dt^4).
  TEST(RigidBodyTensor, TumblingAboutTheIntermediateAxis)
  {
    const Vector3               omega_0(0.02, 2, 0);
    const double                end_time = 30;
    const std::vector<TopState> states   = spin_top(omega_0, 0.01, end_time);
    const std::vector<double>   run      = sign_changes(states, 1);
    const std::vector<double>   exact =
      euler_sign_changes(omega_0, 1e-4, end_time);
    ASSERT_GE(exact.size(), 3u) << "Euler's body does not tumble";
    ASSERT_EQ(run.size(), exact.size());
    double largest = 0;
    for (unsigned int k = 0; k < run.size(); ++k)
      {
        std::cout << "tumbling: omega_y changes sign at " << run[k]
                  << " s, Euler's equations " << exact[k] << " s" << std::endl;
        largest = std::max(largest, std::abs(run[k] / exact[k] - 1));
      }
    const auto [momentum, energy] = conservation(states);
    std::cout << "tumbling: largest relative error of the flip times "
              << largest << "; |L - L_0| / |L| " << momentum
              << ", |E - E_0| / E " << energy << std::endl;
    EXPECT_LT(largest, 2e-4);
    EXPECT_LT(momentum, 2e-6);
    // The energy balance is exact to the Newton tolerance, 1e-8 of the
    // soft rod's forces (1e-10 N m on the body's rows).
    EXPECT_LT(energy, 3e-8);
  }

  // The Jacobian of the body's force f(v) (BodyRotationInertia::
  // step_force()) against central differences, at an oblique inertia and a
  // step that turns by 0.53 rad.
  TEST(RigidBodyTensor, ForceJacobianMatchesCentralDifferences)
  {
    const Matrix3 Q =
      Eigen::AngleAxisd(0.7, Vector3(1, 2, -1).normalized()).toRotationMatrix();
    const Matrix3 J_n = Q * moments.asDiagonal() * Q.transpose();
    const Vector3 pi_n(0.3, -1.1, 0.8), v(0.1, -0.2, 0.15);
    const double  h = 0.05, step = 1e-6;
    const BodyRotationInertia::BodyStep exact =
      BodyRotationInertia::step_force(J_n, pi_n, v, h);
    Matrix3 differences;
    for (unsigned int c = 0; c < 3; ++c)
      {
        const Vector3 e = step * Vector3::Unit(c);
        differences.col(c) =
          (BodyRotationInertia::step_force(J_n, pi_n, v + e, h).force -
           BodyRotationInertia::step_force(J_n, pi_n, v - e, h).force) /
          (2 * step);
      }
    const double error = (exact.jacobian - differences).cwiseAbs().maxCoeff() /
                         exact.jacobian.cwiseAbs().maxCoeff();
    std::cout << "body force Jacobian: largest difference " << error
              << " of the largest entry" << std::endl;
    EXPECT_LT(error, 1e-8);
  }
} // namespace

namespace
{
  // What the body's force keeps, at an oblique inertia J_n and momentum
  // pi_n (h = 0.05): at any increment v, f . v is the change of the kinetic
  // energy K = pi . J^{-1} pi / 2 from pi_n at J_n to pi_{n+1} = C ((4 / h)
  // J_n v - pi_n) at J_{n+1} = C J_n C^T, C the rotation of q = (1, v)
  // (Eigen's); and the v with f(v) = 0 (no torque), found by Newton with
  // the force's Jacobian, keeps pi and K to round-off.
  TEST(RigidBodyTensor, ForceKeepsEnergyAndMomentum)
  {
    const Matrix3 Q =
      Eigen::AngleAxisd(0.7, Vector3(1, 2, -1).normalized()).toRotationMatrix();
    const Matrix3 J_n = Q * moments.asDiagonal() * Q.transpose();
    const Vector3 pi_n(0.3, -1.1, 0.8);
    const double  h       = 0.05;
    const auto    kinetic = [](const Matrix3 &J, const Vector3 &pi) {
      return pi.dot(J.inverse() * pi) / 2;
    };
    const auto next = [&](const Vector3 &v) {
      const Matrix3 C =
        Quaternion(1, v[0], v[1], v[2]).normalized().toRotationMatrix();
      return std::make_pair(Matrix3(C * J_n * C.transpose()),
                            Vector3(C * (4 / h * J_n * v - pi_n)));
    };
    const Vector3 v(0.1, -0.2, 0.15);
    const auto [J_1, pi_1] = next(v);
    const double change    = kinetic(J_1, pi_1) - kinetic(J_n, pi_n);
    const double work =
      BodyRotationInertia::step_force(J_n, pi_n, v, h).force.dot(v);
    std::cout << "body force: f . v = " << work
              << ", K_{n+1} - K_n = " << change << std::endl;
    EXPECT_NEAR(work, change, 1e-12 * std::abs(change));

    Vector3 free = h / 2 * J_n.inverse() * pi_n;
    for (unsigned int i = 0; i < 20; ++i)
      {
        const BodyRotationInertia::BodyStep s =
          BodyRotationInertia::step_force(J_n, pi_n, free, h);
        free -= s.jacobian.inverse() * s.force;
      }
    const auto [J_f, pi_f] = next(free);
    std::cout << "torque-free step: |pi_{n+1} - pi_n| = "
              << (pi_f - pi_n).norm()
              << ", K_{n+1} - K_n = " << kinetic(J_f, pi_f) - kinetic(J_n, pi_n)
              << std::endl;
    EXPECT_LT((pi_f - pi_n).norm(), 1e-14 * pi_n.norm());
    EXPECT_NEAR(kinetic(J_f, pi_f),
                kinetic(J_n, pi_n),
                1e-14 * kinetic(J_n, pi_n));
  }
} // namespace
