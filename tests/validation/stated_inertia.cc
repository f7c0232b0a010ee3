// Inertia stated independently of the stiffness ("Mass per length",
// "Twist inertia per length" with "Stiffness input = direct"), checked on
// the natural frequencies of a clamped-free rod: the generalized
// eigenproblem K x = omega^2 M x of the scene's model and inertia, K the
// tangent of the straight unloaded rod, M its mass matrix (consistent), on
// the free DoFs. Torsion: omega_n = (2n - 1) pi / (2L) sqrt(GJ / (rho J)),
// the first three modes, with the observed convergence in the number of
// segments; bending: the Euler-Bernoulli cantilever,
// omega_1 = 1.8751^2 sqrt(EI / (rho A L^4)).
#include <common/natural_frequencies.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
  using namespace rodnet;
  using rodnet::testing::natural_frequencies;

  /// Rigidities and inertia per length of the rod, each stated directly.
  struct RodData
  {
    double EA, EI, GJ, rho_A, rho_J;
  };

  /// A rod of length 1 along x clamped at x = 0 (at the first segment's
  /// midpoint), @p n segments, the rigidities and inertia of @p d.
  std::string
  clamped_free_rod(const unsigned int n, const RodData &d)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Geometry\n  set Segments = " << n
      << "\n  set Clamp at first segment midpoint = true\nend\n"
      << "subsection Material\n  set Mass per length = " << d.rho_A
      << "\n  set Twist inertia per length = " << d.rho_J
      << "\n  subsection linear elastic\n"
         "    set Stiffness input = direct\n    set EA = "
      << d.EA << "\n    set EI1 = " << d.EI << "\n    set EI2 = " << d.EI
      << "\n    set GJ = " << d.GJ << "\n  end\nend\n"
      << "subsection Supports\n  set Clamped ends = start\nend\n"
         "subsection Solver\n  set Method = time stepping\n"
         "  subsection Time stepping\n    set Integrator = midpoint\n"
         "    set Time step = 0.01\n  end\nend\n";
    return s.str();
  }

  // GJ = 1 and rho J = 1 (a circle with that rho J would have GJ / (rho J)
  // = G / rho, ~3e7 m^2/s^2 for steel: here 1), rho A = 3: the first three
  // torsional modes are the three lowest, the bending (omega_1 = 20 / s)
  // and stretching far above. N = 10, 20, 40: the error falls as N^-2
  // (-2.8e-2, -6.7e-3, -1.6e-3 for the third mode).
  TEST(StatedInertia, TorsionalVibrationOfClampedFreeRod)
  {
    const RodData       d{1e6, 1e3, 1, 3, 1};
    std::vector<double> errors;
    for (const unsigned int n : {10u, 20u, 40u})
      {
        const Eigen::VectorXd omega =
          natural_frequencies(clamped_free_rod(n, d));
        double error = 0;
        for (unsigned int k = 1; k <= 3; ++k)
          {
            const double expected =
              (2 * k - 1) * M_PI / 2 * std::sqrt(d.GJ / d.rho_J);
            const double relative = omega[k - 1] / expected - 1;
            std::cout << "N = " << n << ", mode " << k << ": omega "
                      << omega[k - 1] << ", expected " << expected
                      << ", relative error " << relative << std::endl;
            error = std::max(error, std::abs(relative));
          }
        errors.push_back(error);
      }
    // The third mode at N = 40 within 0.3 %; observed order near 2.
    EXPECT_LT(errors.back(), 3e-3);
    for (unsigned int i = 1; i < errors.size(); ++i)
      {
        const double order = std::log2(errors[i - 1] / errors[i]);
        std::cout << "observed order " << order << std::endl;
        EXPECT_NEAR(order, 2, 0.3);
      }
  }

  // rho A = 2 with EA = 1e6, EI = 1: omega_1 = 1.8751^2 sqrt(EI /
  // (rho A L^4)) = 2.486 / s, the lowest (twist: rho J = 1e-4, pi / 2 *
  // 100 / s). N = 40: +1.5e-4.
  TEST(StatedInertia, FirstBendingFrequencyOfCantilever)
  {
    const RodData         d{1e6, 1, 1, 2, 1e-4};
    const Eigen::VectorXd omega = natural_frequencies(clamped_free_rod(40, d));
    const double expected       = 1.8751 * 1.8751 * std::sqrt(d.EI / (d.rho_A));
    std::cout << "bending: omega " << omega[0] << ", expected " << expected
              << ", relative error " << omega[0] / expected - 1 << std::endl;
    EXPECT_NEAR(omega[0] / expected, 1, 1e-3);
    // The pair of equal bending rigidities gives a double eigenvalue.
    EXPECT_NEAR(omega[1] / expected, 1, 1e-3);
  }
} // namespace
