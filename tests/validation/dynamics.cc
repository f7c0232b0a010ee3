// Time stepping against theory: the first bending frequency of a clamped
// cantilever (Euler-Bernoulli, 1.8751^2 sqrt(EI / (rho A L^4)) / 2 pi),
// the energy of a large-amplitude free swing (conserved by the midpoint
// rule to the Newton tolerance, decreasing under backward Euler), and the
// creep of a standard-linear-solid cantilever under a constant tip load
// against P L^3 / (3 I) J(t).
#include <materials/linear_elastic_rod.h>
#include <materials/standard_linear_solid.h>
#include <solvers/time/time_integrator.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <tests/common/cantilever_swing.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  // Euler-Bernoulli: omega_1 = 1.8751^2 sqrt(EI / (rho A L^4)); released
  // from its static deflection under a tip load of 1 % of the tip
  // deflection (small amplitude), both second-order integrators, 100 steps
  // per period, N = 50.
  TEST(Dynamics, FirstFrequencyOfCantilever)
  {
    const double expected = cantilever_period();
    for (const std::string method : {"newmark", "midpoint"})
      {
        auto model =
          cantilever(50,
                     std::make_shared<LinearElasticRod>(swing_stiffness),
                     0.03);
        const SwingHistory h =
          released_swing(*model, method, expected / 100, 4 * expected);
        ASSERT_EQ(h.failure, "");
        const double T = zero_crossing_period(h);
        std::cout << method << ": period " << T << ", expected " << expected
                  << ", relative error " << T / expected - 1 << std::endl;
        EXPECT_NEAR(T / expected, 1, 0.01) << method;
      }
  }

  // A swing of amplitude ~0.5 L (released from P L^2 / EI = 2), 1000 steps
  // of T/200: the midpoint rule conserves the energy to the Newton
  // tolerance, backward Euler loses it at every step, Newmark (no exact
  // conservation for a nonlinear rod; it blows up at T/100, see
  // doc/dynamics.md) is reported.
  TEST(Dynamics, EnergyOfLargeAmplitudeSwing)
  {
    const double                       T = 2 * M_PI / (1.8751 * 1.8751);
    std::map<std::string, SwingHistory> runs;
    for (const std::string method : {"midpoint", "newmark", "backward euler"})
      {
        auto model =
          cantilever(20,
                     std::make_shared<LinearElasticRod>(swing_stiffness),
                     2.0);
        runs[method]          = released_swing(*model, method, T / 200, 5 * T);
        const SwingHistory &h = runs[method];
        ASSERT_EQ(h.failure, "") << method;
        ASSERT_EQ(h.energy.size(), 1000u) << method;
        std::cout << method << ": initial tip deflection " << h.tip.front()
                  << ", energy drift " << energy_drift(h) << std::endl;
      }
    EXPECT_GT(runs["midpoint"].tip.front(), 0.45);
    EXPECT_LT(energy_drift(runs["midpoint"]), 1e-6);

    const SwingHistory &dissipative = runs["backward euler"];
    for (unsigned int i = 1; i < dissipative.energy.size(); ++i)
      ASSERT_LT(dissipative.energy[i], dissipative.energy[i - 1])
        << "step " << i;
    // Backward Euler damps the swing noticeably at 100 steps per period.
    EXPECT_LT(dissipative.energy.back(), 0.5 * dissipative.energy.front());
  }

  // Standard linear solid cantilever under a constant tip load applied at
  // t = 0, quasi-static: delta(t) = P L^3 / (3 I) J(t) with
  // J(t) = 1/E1 - E2 / (E1 (E1 + E2)) exp(-t / t_c) (VALIDATION.md), i.e.
  // P L^3 / (3 E1 I) (1 - r / (1 + r) exp(-t / t_c)), r = E2 / E1,
  // t_c = t_r (1 + r). Small load (delta ~ 1e-3 L), N = 20, t_c / 100 steps.
  TEST(Dynamics, CreepOfViscoelasticCantilever)
  {
    const double P = 3e-3, r = 0.3, t_r = 2.0;
    const auto   material =
      std::make_shared<StandardLinearSolid>(swing_stiffness, r, t_r);
    const double t_c = material->creep_time();
    ASSERT_NEAR(t_c, t_r * (1 + r), 1e-12);
    auto model = cantilever(20, material, P);

    TimeIntegrator::Parameters p;
    p.integrator = "quasi-static";
    p.time_step  = t_c / 100;
    p.end_time   = 10 * t_c;
    TimeIntegrator     integrator(*model, {}, p);
    const unsigned int tip = model->network().rods()[0].vertices.back();
    std::map<unsigned int, double> deflection; // by step
    VectorType u = model->create_vector(), v = model->create_vector();
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &info,
                       const VectorType               &x,
                       const VectorType &) {
                     deflection[info.step] =
                       model->configuration().position(x, tip)[2];
                   });
    ASSERT_EQ(deflection.size(), 1000u);
    for (const unsigned int multiple : {1u, 3u, 10u})
      {
        const double t        = multiple * t_c;
        const double expected = P / (3 * swing_stiffness.EI1) *
                                (1 - r / (1 + r) * std::exp(-t / t_c));
        const double computed = deflection.at(100 * multiple);
        std::cout << "creep at t = " << multiple << " t_c: " << computed
                  << ", expected " << expected << ", relative error "
                  << computed / expected - 1 << std::endl;
        EXPECT_NEAR(computed / expected, 1, 0.01) << multiple << " t_c";
      }
  }
} // namespace
