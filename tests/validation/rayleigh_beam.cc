// Rotary inertia of the sections on the Rayleigh beam: the bending
// frequencies of a simply supported (pinned-pinned) straight rod from the
// generalized eigenproblem K x = omega^2 M x of the scene's model
// (tests/common/natural_frequencies.h), against the exact Rayleigh-beam
// frequencies omega_n^2 = EI k^4 / (rho A + rho I_b k^2), k = n pi / L
// (Timoshenko, Vibration Problems in Engineering, "effect of rotatory
// inertia"; the Euler-Bernoulli beam is rho I_b = 0), n = 1, 2, 3, for a
// slender (L / r = 100) and a stocky (L / r = 10) rod, r^2 = I_b / A. The
// discrete frequencies converge to Rayleigh's at second order and stay far
// from Euler-Bernoulli's; "Rotary inertia per length = 0" gives
// Euler-Bernoulli's.
#include <common/natural_frequencies.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using rodnet::testing::natural_frequencies;

  /// L = 1, EI = 1, rho A = 1; rho I_b = r^2 for the slenderness L / r.
  /// The twist inertia rho J = 0.02 (so "auto" is the stocky rod's
  /// rho I_b) with GJ = 200 puts the free twisting modes at 100 pi n / s.
  constexpr double EI = 1, rho_A = 1, rho_J = 0.02;

  /// A rod of length 1 along x, pinned at both ends (twist free), @p n
  /// segments, rotary inertia @p rho_Ib ("auto" where negative). By
  /// default EA and GJ put the stretching and twisting modes far above the
  /// third bending mode (88.8 / s): the six lowest non-zero frequencies are
  /// the first three bending ones, twice each (EI1 = EI2).
  std::string
  pinned_pinned_rod(const unsigned int n,
                    const double       rho_Ib,
                    const double       EA       = 1e6,
                    const double       EI_scene = EI)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Geometry\n  set Segments = " << n << "\nend\n"
      << "subsection Material\n  set Mass per length = " << rho_A
      << "\n  set Twist inertia per length = " << rho_J
      << "\n  set Rotary inertia per length = "
      << (rho_Ib < 0 ? std::string("auto") : std::to_string(rho_Ib))
      << "\n  subsection linear elastic\n"
         "    set Stiffness input = direct\n    set EA = "
      << EA << "\n    set EI1 = " << EI_scene << "\n    set EI2 = " << EI_scene
      << "\n    set GJ = " << 1e4 * rho_J << "\n  end\nend\n"
      << "subsection Supports\n  set Pinned vertices = start, end\nend\n"
         "subsection Solver\n  set Method = time stepping\n"
         "  subsection Time stepping\n    set Integrator = midpoint\n"
         "    set Time step = 0.01\n  end\nend\n";
    return s.str();
  }

  /// omega_n of the Rayleigh beam (rho I_b = 0: Euler-Bernoulli).
  double
  rayleigh_frequency(const unsigned int n, const double rho_Ib)
  {
    const double k = n * M_PI;
    return std::sqrt(EI * std::pow(k, 4) / (rho_A + rho_Ib * k * k));
  }

  /// The first three bending frequencies of the scene: the lowest six
  /// frequencies above 1 / s pairwise (the rigid twist has omega = 0 up to
  /// the round-off of EA = 1e6, 2e-3 / s at N = 160; the lowest bending
  /// mode is 9.4 / s).
  std::vector<double>
  bending_frequencies(const std::string &scene)
  {
    const Eigen::VectorXd omega = natural_frequencies(scene);
    std::vector<double>   nonzero;
    for (Eigen::Index i = 0; i < omega.size(); ++i)
      if (omega[i] > 1)
        nonzero.push_back(omega[i]);
    std::vector<double> bending;
    for (unsigned int n = 0; n < 3; ++n)
      {
        EXPECT_NEAR(nonzero[2 * n + 1] / nonzero[2 * n], 1, 1e-6)
          << "mode " << n + 1 << " is not a double bending mode";
        bending.push_back(nonzero[2 * n]);
      }
    return bending;
  }

  struct Slenderness
  {
    double L_over_r;
    /// The segment counts of the convergence study.
    std::vector<unsigned int> segments;
    /// Bound on the largest relative error to Rayleigh at the finest N.
    double tolerance;
  };

  class RayleighBeam : public ::testing::TestWithParam<Slenderness>
  {
  };

  // Rayleigh's third mode is 0.44 % below Euler-Bernoulli's for the slender
  // rod, 27 % below for the stocky one. The error to Rayleigh falls as
  // N^-2 (third mode at N = 40, 80, 160: -2.3e-5, -5.2e-6, -1.3e-6 slender,
  // -1.1e-3, -2.7e-4, -6.8e-5 stocky), and at the finest N the third mode's
  // distance to Euler-Bernoulli is more than 100 times that error.
  TEST_P(RayleighBeam, FrequenciesConvergeToRayleighNotEulerBernoulli)
  {
    const Slenderness   c      = GetParam();
    const double        rho_Ib = std::pow(1 / c.L_over_r, 2);
    std::vector<double> errors, distances;
    for (const unsigned int n : c.segments)
      {
        const std::vector<double> omega =
          bending_frequencies(pinned_pinned_rod(n, rho_Ib));
        double error = 0;
        for (unsigned int k = 1; k <= 3; ++k)
          {
            const double rayleigh = rayleigh_frequency(k, rho_Ib);
            const double euler    = rayleigh_frequency(k, 0);
            const double relative = omega[k - 1] / rayleigh - 1;
            std::cout << "L/r = " << c.L_over_r << ", N = " << n << ", mode "
                      << k << ": omega " << omega[k - 1] << ", Rayleigh "
                      << rayleigh << " (error " << relative
                      << "), Euler-Bernoulli " << euler << " (distance "
                      << omega[k - 1] / euler - 1 << ")" << std::endl;
            error = std::max(error, std::abs(relative));
          }
        errors.push_back(error);
        distances.push_back(std::abs(omega[2] / rayleigh_frequency(3, 0) - 1));
      }
    EXPECT_LT(errors.back(), c.tolerance);
    EXPECT_GT(distances.back(), 100 * errors.back());
    for (unsigned int i = 1; i < errors.size(); ++i)
      {
        const double order = std::log2(errors[i - 1] / errors[i]);
        std::cout << "L/r = " << c.L_over_r << ": observed order " << order
                  << std::endl;
        EXPECT_NEAR(order, 2, 0.2);
      }
  }

  INSTANTIATE_TEST_SUITE_P(
    Slenderness,
    RayleighBeam,
    ::testing::Values(Slenderness{100, {40, 80, 160}, 1e-5},
                      Slenderness{10, {40, 80, 160}, 1e-4}),
    [](const ::testing::TestParamInfo<Slenderness> &info) {
      return "L_over_r_" + std::to_string(int(info.param.L_over_r));
    });

  // "Rotary inertia per length = 0" is the Euler-Bernoulli rod: its
  // frequencies at N = 160 within 1e-8 of Euler-Bernoulli's (where the
  // stocky rod's rotary inertia moves the third mode by 27 %); the default
  // ("auto": half the twist inertia, here the stocky rod's rho I_b) is the
  // same as stating rho I_b.
  TEST(RayleighBeamEntry, ZeroIsEulerBernoulliAndAutoIsHalfTheTwistInertia)
  {
    const double              rho_Ib = 1e-2;
    const std::vector<double> euler =
      bending_frequencies(pinned_pinned_rod(160, 0));
    for (unsigned int k = 1; k <= 3; ++k)
      {
        std::cout << "rotary inertia 0, mode " << k << ": omega "
                  << euler[k - 1] << ", Euler-Bernoulli "
                  << rayleigh_frequency(k, 0) << " (error "
                  << euler[k - 1] / rayleigh_frequency(k, 0) - 1 << ")"
                  << std::endl;
        EXPECT_NEAR(euler[k - 1] / rayleigh_frequency(k, 0), 1, 1e-6);
      }
    const std::vector<double> stated =
      bending_frequencies(pinned_pinned_rod(40, rho_Ib));
    const std::vector<double> automatic =
      bending_frequencies(pinned_pinned_rod(40, -rho_Ib));
    for (unsigned int k = 0; k < 3; ++k)
      EXPECT_NEAR(automatic[k] / stated[k], 1, 1e-12);
  }

  // The price of a rotary inertia that is constant in the chord rates: it
  // acts on stretching rates as well, rho I_b l0 / 2 epsdot^2 per segment,
  // the form of Love's lateral inertia of axial waves (rho nu^2 (I1 + I2)
  // in place of rho I_b). On the stocky rod with its physical EA = EI /
  // r^2 = 100 (and EI = 1e6 to put the bending modes above), the first
  // axial frequency is pi sqrt(EA / (rho A + rho I_b pi^2)), 4.6 % below
  // pi sqrt(EA / rho A) (Love's for a circle with nu = 0.3: 0.9 %).
  TEST(RayleighBeamEntry, StretchingCarriesTheRotaryInertia)
  {
    const double          rho_Ib = 1e-2, EA = 1e2;
    const Eigen::VectorXd omega =
      natural_frequencies(pinned_pinned_rod(160, rho_Ib, EA, 1e6));
    double axial = 0;
    for (Eigen::Index i = 0; i < omega.size() && axial == 0; ++i)
      if (omega[i] > 1)
        axial = omega[i];
    const double with_rotary =
      M_PI * std::sqrt(EA / (rho_A + rho_Ib * M_PI * M_PI));
    const double without = M_PI * std::sqrt(EA / rho_A);
    std::cout << "first axial frequency " << axial << ", with the rotary "
              << "inertia " << with_rotary << " (error "
              << axial / with_rotary - 1 << "), without " << without
              << " (shift " << with_rotary / without - 1 << ")" << std::endl;
    EXPECT_NEAR(axial / with_rotary, 1, 1e-4);
    EXPECT_LT(axial / without, 0.96);
  }
} // namespace
