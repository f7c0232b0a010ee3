// Convergence of the hinge strains on a uniformly discretized helix
// x(s) = (r cos(s/L), r sin(s/L), c s/L), L = sqrt(r^2 + c^2), of curvature
// K = r / L^2 and torsion T = c / L^2.
//
// The reference configuration is straight along e_3 with identical frames
// (reference twist 0); the current configuration is the helix, framed by
// twist increments phi^j chosen so that the frames of Korner et al. eq. 2.8
// are:
// - Frenet-like: d_1^j the principal normal at the parameter midpoint of
//   segment j (it is orthogonal to the chord). Darboux vector (0, K, T) in
//   the frame: we check |(kappa_1, kappa_2)| / l -> K and kappa_3 / l -> T.
// - Bishop (twist-free): d_1 carried from segment to segment by spatial
//   parallel transport. The material twist vanishes and the curvature
//   vector rotates in the (d_1, d_2) plane: we check
//   |(kappa_1, kappa_2)| / l -> K and kappa_3 = 0 (to round-off).
// l is the (uniform) segment length. The observed order between successive
// resolutions is log2(error(n) / error(2 n)); both kernels are second order
// (asserted > 1.9).

#include <elements/hinge_kernel.h>

#include "hinge_configurations.h"
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double radius      = 1.0;
  constexpr double pitch_scale = 0.5;
  const double     helix_scale = std::hypot(radius, pitch_scale);
  const double     curvature   = radius / (helix_scale * helix_scale);
  const double     torsion     = pitch_scale / (helix_scale * helix_scale);

  Vector3
  helix(const double s)
  {
    return Vector3(radius * std::cos(s / helix_scale),
                   radius * std::sin(s / helix_scale),
                   pitch_scale * s / helix_scale);
  }

  Vector3
  principal_normal(const double s)
  {
    return -Vector3(std::cos(s / helix_scale), std::sin(s / helix_scale), 0);
  }

  enum class Framing
  {
    frenet,
    bishop
  };

  struct Errors
  {
    double curvature;
    double twist;
  };

  /// Max errors over the hinges of one turn discretized by @p n segments.
  Errors
  helix_errors(const HingeKernel &kernel, const unsigned int n, Framing framing)
  {
    const double         h = 2 * pi * helix_scale / n;
    std::vector<Vector3> x(n + 1), t(n), d1(n);
    std::vector<double>  phi(n);
    for (unsigned int k = 0; k <= n; ++k)
      x[k] = helix(k * h);
    for (unsigned int j = 0; j < n; ++j)
      {
        t[j]   = (x[j + 1] - x[j]).normalized();
        d1[j]  = (framing == Framing::frenet || j == 0) ?
                   principal_normal((j + 0.5) * h) :
                   parallel_transport(t[j - 1], t[j]) * d1[j - 1];
        phi[j] = signed_angle(parallel_transport(Vector3::UnitZ(), t[j]) *
                                Vector3::UnitX(),
                              d1[j],
                              t[j]);
      }
    const double length = (x[1] - x[0]).norm();

    const HingeReference straight;
    Errors               errors{0, 0};
    for (unsigned int i = 1; i < n; ++i)
      {
        const Vector3 kappa = kernel.strains(hinge_dofs(x[i],
                                                        x[i] - x[i - 1],
                                                        phi[i - 1],
                                                        x[i + 1] - x[i],
                                                        phi[i]),
                                             straight);
        const double  expected_twist =
          framing == Framing::frenet ? torsion : 0.0;
        errors.curvature =
          std::max(errors.curvature,
                   std::abs(kappa.head<2>().norm() / length - curvature));
        errors.twist =
          std::max(errors.twist, std::abs(kappa[2] / length - expected_twist));
      }
    return errors;
  }

  /**
   * Prints the errors and observed orders (the twist error of a Bishop
   * framing is round-off, so no order is shown for it) and checks the
   * orders of the last refinement; for a Bishop framing it checks kappa_3 = 0
   * instead of an order.
   */
  void
  check_convergence(const std::string &name, const Framing framing)
  {
    const auto kernel = create_hinge_kernel(name);
    const bool frenet = framing == Framing::frenet;
    std::cout << name << ", " << (frenet ? "Frenet" : "Bishop")
              << " framing (K = " << curvature << ", T = " << torsion << "):\n"
              << "     n   curvature error  order      twist error  order\n";
    Errors previous{0, 0}, order{0, 0};
    for (unsigned int n = 16; n <= 512; n *= 2)
      {
        const Errors e = helix_errors(*kernel, n, framing);
        if (n > 16)
          order = {std::log2(previous.curvature / e.curvature),
                   std::log2(previous.twist / e.twist)};
        std::cout << std::setw(6) << n << std::setw(18) << std::setprecision(6)
                  << e.curvature << std::setw(7) << std::setprecision(3)
                  << (n > 16 ? order.curvature : 0.0) << std::setw(17)
                  << std::setprecision(6) << e.twist << std::setw(7)
                  << std::setprecision(3)
                  << (n > 16 && frenet ? order.twist : 0.0) << '\n';
        if (!frenet)
          {
            EXPECT_LT(e.twist * (2 * pi * helix_scale / n), 1e-12);
          }
        previous = e;
      }
    std::cout << std::flush;
    EXPECT_GT(order.curvature, 1.9);
    if (frenet)
      {
        EXPECT_GT(order.twist, 1.9);
      }
  }

  TEST(HelixConvergence, SimpleFrenet)
  {
    check_convergence("simple", Framing::frenet);
  }

  TEST(HelixConvergence, ClassicFrenet)
  {
    check_convergence("classic", Framing::frenet);
  }

  TEST(HelixConvergence, SimpleBishop)
  {
    check_convergence("simple", Framing::bishop);
  }

  TEST(HelixConvergence, ClassicBishop)
  {
    check_convergence("classic", Framing::bishop);
  }
} // namespace
