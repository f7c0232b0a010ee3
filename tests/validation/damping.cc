// Damping a user states (TimeIntegrator::Parameters::rayleigh_mass,
// rayleigh_stiffness, viscous_drag) against the modal damping ratio of
// Rayleigh damping, zeta = alpha / (2 omega) + beta omega / 2 (Chopra,
// Dynamics of Structures, section 11.4): the cantilever of
// tests/common/cantilever_swing.h (N = 20) started at rest in its first
// discrete mode (omega from the same discrete K phi = omega^2 M phi), so
// that the tip decays as exp(-zeta omega t) in one mode only; the
// logarithmic decrement per period, ln(A_k / A_{k+1}) = 2 pi zeta /
// sqrt(1 - zeta^2), from the tip's positive peaks over four periods.
// Tip amplitude 1e-4 L: beta K_0 (K_0 frozen at the start) also damps the
// stretch rates the rotation of the segments induces, second order in the
// amplitude, which at 0.01 L (EA w'^2 / EI ~ 2 here) tripled the decrement.
#include <materials/linear_elastic_rod.h>
#include <solvers/time/time_integrator.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <tests/common/cantilever_swing.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The damping of a run: alpha, beta, c.
  struct Damping
  {
    double alpha = 0, beta = 0, drag = 0;
  };

  /// Peaks of the tip deflection, each from the parabola through a local
  /// maximum and its neighbours.
  std::vector<double>
  positive_peaks(const SwingHistory &h)
  {
    std::vector<double> peaks;
    for (unsigned int i = 1; i + 1 < h.tip.size(); ++i)
      if (h.tip[i] > h.tip[i - 1] && h.tip[i] >= h.tip[i + 1] && h.tip[i] > 0)
        {
          const double a = h.tip[i - 1], b = h.tip[i], c = h.tip[i + 1];
          peaks.push_back(b + (a - c) * (a - c) / (8 * (2 * b - a - c)));
        }
    return peaks;
  }

  /// The mean logarithmic decrement per period of the first mode's free
  /// vibration with @p damping by @p method, 200 steps per period.
  double
  measured_decrement(const std::string &method, const Damping &damping)
  {
    auto model =
      cantilever(20, std::make_shared<LinearElasticRod>(swing_stiffness), 0);
    const auto [omega, shape] = first_mode(*model);
    const unsigned int tip    = model->network().rods()[0].vertices.back();
    const double amplitude = 1e-4 / shape[model->layout().vertex_dof(tip, 2)];
    const double period    = 2 * M_PI / omega;
    const SwingHistory h   = free_vibration(*model,
                                          shape,
                                          amplitude,
                                          method,
                                          period / 200,
                                          4.6 * period,
                                          [&](TimeIntegrator::Parameters &p) {
                                            p.rayleigh_mass = damping.alpha;
                                            p.rayleigh_stiffness = damping.beta;
                                            p.viscous_drag       = damping.drag;
                                          });
    EXPECT_EQ(h.failure, "") << method;
    const std::vector<double> peaks = positive_peaks(h);
    EXPECT_EQ(peaks.size(), 4u) << method;
    if (peaks.size() < 2)
      return std::nan("");
    return std::log(peaks.front() / peaks.back()) / (peaks.size() - 1);
  }

  /// 2 pi zeta / sqrt(1 - zeta^2).
  double
  analytic_decrement(const double zeta)
  {
    return 2 * M_PI * zeta / std::sqrt(1 - zeta * zeta);
  }

  double
  first_omega()
  {
    auto model =
      cantilever(20, std::make_shared<LinearElasticRod>(swing_stiffness), 0);
    return first_mode(*model).first;
  }

  // zeta = 0.02 from alpha alone (alpha = 2 zeta omega) and from beta alone
  // (beta = 2 zeta / omega): the decrement within 1% of 2 pi zeta /
  // sqrt(1 - zeta^2), for every integrator that keeps the amplitude
  // (Newmark, midpoint; backward Euler's own numerical damping adds to it).
  TEST(Damping, RayleighModalDampingRatio)
  {
    const double omega = first_omega();
    const double zeta  = 0.02;
    for (const std::string method : {"newmark", "midpoint"})
      for (const bool mass_proportional : {true, false})
        {
          Damping d;
          if (mass_proportional)
            d.alpha = 2 * zeta * omega;
          else
            d.beta = 2 * zeta / omega;
          const double computed = measured_decrement(method, d);
          const double expected = analytic_decrement(zeta);
          std::cout << method << (mass_proportional ? ", alpha" : ", beta")
                    << ": decrement " << computed << ", expected " << expected
                    << ", relative error " << computed / expected - 1
                    << std::endl;
          EXPECT_NEAR(computed / expected, 1, 0.01)
            << method << (mass_proportional ? " alpha" : " beta");
        }
  }

  // Viscous drag c per length on a uniform rod of rho A = 1 is mass-
  // proportional damping alpha = c / (rho A) on the positions (the twist
  // carries no drag, and the first bending mode no twist): the same
  // decrement, zeta = c / (2 rho A omega), within 1%.
  TEST(Damping, ViscousDragIsMassProportional)
  {
    const double omega = first_omega();
    const double zeta  = 0.02;
    Damping      d;
    d.drag                = 2 * zeta * omega * swing_inertia.mass_per_length;
    const double computed = measured_decrement("newmark", d);
    const double expected = analytic_decrement(zeta);
    std::cout << "drag: decrement " << computed << ", expected " << expected
              << ", relative error " << computed / expected - 1 << std::endl;
    EXPECT_NEAR(computed / expected, 1, 0.01);
  }

  // The midpoint rule with C = alpha M + beta K_0 (K_0 the tangent at the
  // start) at the midpoint velocity vbar = (u_{n+1} - u_n) / h: the total
  // energy falls in every step by exactly the work of the damping force,
  // h vbar.C vbar = d.C d / h (d = u_{n+1} - u_n), to the Newton
  // tolerance. C is formed here from the integrator's mass matrix and the
  // model's (condensed) tangent, independently of the integrator's own;
  // the work is that of the force on the free rows.
  TEST(Damping, MidpointEnergyFallsByDissipatedWork)
  {
    auto model =
      cantilever(20, std::make_shared<LinearElasticRod>(swing_stiffness), 0);
    const auto [omega, shape] = first_mode(*model);
    const double h = 2 * M_PI / omega / 50, alpha = 0.04 * omega,
                 beta = 0.04 / omega;
    TimeIntegrator::Parameters p;
    p.integrator         = "midpoint";
    p.time_step          = h;
    p.end_time           = 100 * h;
    p.load_factor        = [](double) { return 0.0; };
    p.relative_tolerance = 1e-11;
    p.rayleigh_mass      = alpha;
    p.rayleigh_stiffness = beta;
    TimeIntegrator integrator(*model, {swing_inertia}, p);
    VectorType     u = shape, v = model->create_vector();
    u *= 0.01 /
         shape[model->layout()
                 .vertex_dof(model->network().rods()[0].vertices.back(), 2)];
    MatrixType damping;
    model->initialize_matrix(damping);
    model->assemble(u, 0.0, nullptr, &damping, true);
    damping *= beta;
    damping.add(alpha, integrator.mass_matrix());
    VectorType   previous = u, d = u, cd = u;
    double       energy  = model->assemble(u, 0.0, nullptr, nullptr);
    const double initial = energy;
    double       worst = 0, dissipated = 0;
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &info,
                       const VectorType               &x,
                       const VectorType &) {
                     d = x;
                     d -= previous;
                     damping.vmult(cd, d);
                     model->constraints().set_zero(cd);
                     const double work = (d * cd) / info.time_step;
                     const double next =
                       info.kinetic_energy + info.potential_energy;
                     worst = std::max(worst, std::abs(energy - next - work));
                     dissipated += work;
                     energy   = next;
                     previous = x;
                   });
    std::cout << "midpoint: energy " << initial << " -> " << energy
              << ", dissipated " << dissipated << ", largest per-step mismatch "
              << worst / initial << " of the initial energy" << std::endl;
    // The run dissipates about 1 - exp(-2 (2 zeta) omega t) = 64% of it.
    EXPECT_GT(dissipated, 0.5 * initial);
    EXPECT_LT(worst, 1e-8 * initial);
  }

  // Without damping the decrement vanishes (the schemes themselves do not
  // damp): what the two tests above measure is the stated damping.
  TEST(Damping, UndampedHasNoDecrement)
  {
    for (const std::string method : {"newmark", "midpoint"})
      EXPECT_LT(std::abs(measured_decrement(method, Damping())), 1e-3)
        << method;
  }
} // namespace
