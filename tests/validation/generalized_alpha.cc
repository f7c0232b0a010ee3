// The generalized-alpha integrator (solvers/time/generalized_alpha_scheme.h)
// against Chung & Hulbert's analysis (J. Appl. Mech. 60, 1993): for the
// linear oscillator qddot + omega^2 q = 0 one step maps (q, v, a) by an
// amplification matrix A(omega h) that follows from the method's defining
// equations alone,
//   (1 - alpha_m) a_{n+1} + alpha_m a_n
//     + omega^2 ((1 - alpha_f) q_{n+1} + alpha_f q_n) = 0,
//   q_{n+1} = q_n + h v_n + h^2 ((1/2 - beta) a_n + beta a_{n+1}),
//   v_{n+1} = v_n + h ((1 - gamma) a_n + gamma a_{n+1}),
// whose principal eigenvalues r e^{+-i phi} give the amplification r per
// step (r -> rho_inf as omega h -> infinity) and the period 2 pi h / phi.
// Measured on rods:
// - a stiff axial mode (a bar of two segments, clamped, the free end
//   vertex a linear oscillator of k = EA/l, m = rho A l/2 lumped): r per
//   step at omega h = 10 and 100, rho_inf = 0.8 and 0.5;
// - the first bending mode of the cantilever of tests/common/
//   cantilever_swing.h: the period against the exact discrete one, second
//   order in h, and its (small) damping per step;
// - rho_inf = 1 is Newmark's average acceleration step for step.
// r is read from a sequence x_n = Re(c lambda^n) as x_{n+1}^2 - x_n x_{n+2}
// = |c|^2 r^{2n+2} sin^2 phi, which decays as r^{2n} whatever the phase.
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <iostream>
#include <tests/common/cantilever_swing.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// Principal eigenvalue (largest modulus, positive phase) of Chung &
  /// Hulbert's amplification matrix at @p omega_h for @p rho_inf.
  std::complex<double>
  principal_root(const double rho_inf, const double omega_h)
  {
    const double am = (2 * rho_inf - 1) / (rho_inf + 1);
    const double af = rho_inf / (rho_inf + 1);
    const double g  = 0.5 - am + af;
    const double b  = 0.25 * (1 - am + af) * (1 - am + af);
    const double w2 = omega_h * omega_h;
    // L (q, v h, a h^2)_{n+1} = R (q, v h, a h^2)_n.
    Eigen::Matrix3d lhs, rhs;
    lhs << w2 * (1 - af), 0, 1 - am, 1, 0, -b, 0, 1, -g;
    rhs << -w2 * af, 0, -am, 1, 1, 0.5 - b, 0, 1, 1 - g;
    const Eigen::Vector3cd roots =
      Eigen::Matrix3d(lhs.inverse() * rhs).eigenvalues();
    std::complex<double> best = 0;
    for (const std::complex<double> &z : roots)
      if (std::abs(z) > std::abs(best) + 1e-12 ||
          (std::abs(std::abs(z) - std::abs(best)) <= 1e-12 && z.imag() > 0))
        best = z;
    return best;
  }

  /// r per step from x_{n+1}^2 - x_n x_{n+2} between steps @p n1 and @p n2.
  double
  measured_radius(const std::vector<double> &x,
                  const unsigned int         n1,
                  const unsigned int         n2)
  {
    const auto d = [&](const unsigned int n) {
      return x[n + 1] * x[n + 1] - x[n] * x[n + 2];
    };
    return std::pow(d(n2) / d(n1), 1.0 / (2.0 * (n2 - n1)));
  }

  /// Axial displacement of the free end of a bar of two segments (l =
  /// 0.5, rho A = 1, lumped: m = 0.25, k = EA / l), started from 1e-2 at
  /// rest with steps h = 1e-3, @p steps of them: a linear oscillator of
  /// omega h = @p omega_h (a displacement along the axis strains the end
  /// segment linearly and nothing else).
  std::vector<double>
  stiff_axial_history(const double       rho_inf,
                      const double       omega_h,
                      const unsigned int steps)
  {
    const double h = 1e-3, l = 0.5, m = 0.25;
    const double omega = omega_h / h, EA = omega * omega * m * l;
    auto         network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          2),
                     false,
                     Vector3::UnitY(),
                     "simple");
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(
                     RodStiffness{EA, 1e-3 * EA, 1e-3 * EA, 1e-3 * EA})});
    model.clamp_end("clamp", 0, true);
    model.finalize();
    TimeIntegrator::Parameters p;
    p.integrator                  = "generalized alpha";
    p.spectral_radius_at_infinity = rho_inf;
    p.mass                        = MassKind::lumped;
    p.time_step                   = h;
    p.end_time                    = steps * h;
    p.load_factor                 = [](double) { return 0.0; };
    p.relative_tolerance          = 1e-13;
    TimeIntegrator      integrator(model, {{1.0, 1e-3}}, p);
    VectorType          u = model.create_vector(), v = model.create_vector();
    const unsigned int  dof = model.layout().vertex_dof(2, 0);
    std::vector<double> x{1e-2};
    u[dof] = x[0];
    u.compress(dealii::VectorOperation::insert);
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &,
                       const VectorType &y,
                       const VectorType &) { x.push_back(y[dof]); });
    return x;
  }

  // At omega h = 10 and 100 the amplification per step is Chung &
  // Hulbert's r (0.930 and 0.835 for rho_inf = 0.8, 0.683 and 0.537 for
  // 0.5), which tends to rho_inf: the stiff modes lose 1 - r of their
  // amplitude per step. Measured from step n/2 to n, n up to 80 where the
  // amplitude has fallen to 1e-8 (29 for 0.537), when the spurious root
  // (0.59 and 0.73, 0.26 and 0.43) has died out, to 0.5 %.
  TEST(GeneralizedAlpha, SpectralRadiusOfAStiffMode)
  {
    for (const double rho_inf : {0.8, 0.5})
      {
        EXPECT_NEAR(std::abs(principal_root(rho_inf, 1e6)), rho_inf, 1e-4);
        for (const double omega_h : {10.0, 100.0})
          {
            const double expected = std::abs(principal_root(rho_inf, omega_h));
            // Until the amplitude has fallen to 1e-8 of the start, well
            // above the rounding of the positions (1e-16 m).
            const unsigned int n2 =
              std::min(80,
                       static_cast<int>(std::log(1e-8) / std::log(expected)));
            const std::vector<double> x =
              stiff_axial_history(rho_inf, omega_h, n2 + 2);
            ASSERT_EQ(x.size(), n2 + 3);
            const double measured = measured_radius(x, n2 / 2, n2);
            std::cout << "rho_inf " << rho_inf << ", omega h " << omega_h
                      << ": r per step " << measured << ", Chung-Hulbert "
                      << expected << std::endl;
            EXPECT_NEAR(measured, expected, 5e-3 * expected)
              << rho_inf << " " << omega_h;
          }
      }
  }

  /// Free vibration of the cantilever (N = 20) from its first discrete
  /// mode with @p steps steps per period: the tip history.
  SwingHistory
  first_mode_vibration(const std::string &method,
                       const double       rho_inf,
                       const unsigned int steps,
                       double            &period,
                       double            *start_tip = nullptr)
  {
    auto model =
      cantilever(20, std::make_shared<LinearElasticRod>(swing_stiffness), 0);
    const auto [omega, shape] = first_mode(*model);
    period                    = 2 * M_PI / omega;
    const double scale        = 1e-4 / shape.linfty_norm();
    if (start_tip != nullptr)
      {
        VectorType u = shape;
        u *= scale;
        const unsigned int tip = model->network().rods()[0].vertices.back();
        *start_tip             = model->configuration().position(u, tip)[2];
      }
    return free_vibration(*model,
                          shape,
                          scale,
                          method,
                          period / steps,
                          3 * period,
                          [rho_inf](TimeIntegrator::Parameters &p) {
                            p.spectral_radius_at_infinity = rho_inf;
                          });
  }

  // The first bending mode at omega h = 2 pi / n, n = 20, 40, 80: the
  // period from the zero crossings against the discrete mode's own 2 pi /
  // omega_1 is Chung & Hulbert's 2 pi h / phi to 3 % of its error, second
  // order (ratio 4 per halving, +-0.4), and the amplitude falls by r per
  // step as predicted (1 - r = 6.5e-6, 4.1e-7, 2.6e-8 for rho_inf = 0.8:
  // fourth order in omega h; to 10 % of 1 - r).
  TEST(GeneralizedAlpha, PeriodAndDampingOfALowMode)
  {
    const double        rho_inf = 0.8;
    std::vector<double> errors;
    for (const unsigned int n : {20u, 40u, 80u})
      {
        double             period = 0;
        const SwingHistory h =
          first_mode_vibration("generalized alpha", rho_inf, n, period);
        ASSERT_EQ(h.failure, "");
        const std::complex<double> root = principal_root(rho_inf, 2 * M_PI / n);
        const double predicted          = 2 * M_PI / n / std::arg(root) - 1;
        const double error              = zero_crossing_period(h) / period - 1;
        errors.push_back(error);
        // The history starts at the first step: x_0 is its first entry.
        const double measured = measured_radius(h.tip, n / 2, 5 * n / 2);
        std::cout << n << " steps per period: period error " << error
                  << " (Chung-Hulbert " << predicted << "), 1 - r "
                  << 1 - measured << " (" << 1 - std::abs(root) << ")"
                  << std::endl;
        EXPECT_NEAR(error, predicted, 0.03 * predicted) << n;
        // At n = 80, 1 - r = 2.6e-8 is below what 160 steps resolve.
        if (n <= 40)
          {
            EXPECT_NEAR(1 - measured,
                        1 - std::abs(root),
                        0.1 * (1 - std::abs(root)))
              << n;
          }
      }
    for (unsigned int i = 0; i + 1 < errors.size(); ++i)
      EXPECT_NEAR(errors[i] / errors[i + 1], 4, 0.4);
  }

  // The start: from the first mode at rest, q_n = q_0 Re(lambda^n) with
  // lambda the principal root (80 steps per period, one period), which
  // needs a_0 = qddot_0 (M a_0 = p_0, the out-of-balance force): measured
  // 3.4e-7 of q_0; with a_0 = 0 (the solve left out) the velocity starts
  // (1 - gamma) h qddot_0 off, and the tip 4.4e-3 of q_0.
  TEST(GeneralizedAlpha, StartsWithTheAccelerationOfTheState)
  {
    const unsigned int n      = 80;
    double             period = 0, start = 0;
    const SwingHistory h =
      first_mode_vibration("generalized alpha", 0.8, n, period, &start);
    ASSERT_EQ(h.failure, "");
    const std::complex<double> root  = principal_root(0.8, 2 * M_PI / n);
    double                     error = 0;
    for (unsigned int k = 0; k < n; ++k)
      error =
        std::max(error,
                 std::abs(h.tip[k] - start * std::pow(root, k + 1.0).real()));
    std::cout << "first period against q_0 Re(lambda^n): "
              << error / std::abs(start) << " of q_0" << std::endl;
    EXPECT_LT(error, 1e-3 * std::abs(start));
  }

  // rho_inf = 1 gives alpha_m = alpha_f = 1/2, gamma = 1/2, beta = 1/4:
  // Newmark's average acceleration. Its history is Newmark's to round-off
  // (measured 4.7e-12 of the amplitude over 120 steps; the velocity update
  // adds its terms in another order).
  TEST(GeneralizedAlpha, SpectralRadiusOneIsNewmark)
  {
    double             period = 0;
    const SwingHistory alpha =
      first_mode_vibration("generalized alpha", 1.0, 40, period);
    const SwingHistory newmark =
      first_mode_vibration("newmark", 1.0, 40, period);
    ASSERT_EQ(alpha.failure, "");
    ASSERT_EQ(newmark.failure, "");
    ASSERT_EQ(alpha.tip.size(), newmark.tip.size());
    double difference = 0, amplitude = 0;
    for (unsigned int i = 0; i < alpha.tip.size(); ++i)
      {
        difference =
          std::max(difference, std::abs(alpha.tip[i] - newmark.tip[i]));
        amplitude = std::max(amplitude, std::abs(newmark.tip[i]));
      }
    std::cout << "rho_inf = 1 against newmark: " << difference / amplitude
              << " of the amplitude" << std::endl;
    EXPECT_LT(difference, 1e-10 * amplitude);
  }
} // namespace
