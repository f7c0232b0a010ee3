// Lateral-torsional buckling of a cantilever under a tip load in its stiff
// plane (Timoshenko & Gere, Theory of Elastic Stability, 6.4): with the
// in-plane stiffness EI1 a million times the lateral EI2, the critical load
// is gamma sqrt(EI2 GJ) / L^2, with gamma from the twist equation
//   beta'' + gamma^2 s^2 beta = 0,  beta'(0) = 0 (free end), beta(L) = 0
// (s from the tip), which the test solves by shooting. A stiff tangent
// (EI1 / l^3 = 8e12 at N = 200) once made N = 200 worse than N = 100: the
// round-off floor let steps pass without iterating, and the dense lowest
// eigenvalue is only accurate to eps |K|. Now N = 200 must be at least as
// accurate as N = 100.
#include <common/rod_models.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;

  /// beta(1) for beta'' = -gamma^2 s^2 beta from beta(0) = 1, beta'(0) = 0
  /// (classical Runge-Kutta, 4000 steps: error far below 1e-9).
  double
  twist_at_clamp(const double gamma)
  {
    const unsigned int n    = 4000;
    const double       h    = 1.0 / n;
    double             beta = 1, slope = 0, s = 0;
    const auto         curvature = [gamma](const double at, const double b) {
      return -gamma * gamma * at * at * b;
    };
    for (unsigned int i = 0; i < n; ++i, s += h)
      {
        const double k1 = slope, l1 = curvature(s, beta);
        const double k2 = slope + h / 2 * l1,
                     l2 = curvature(s + h / 2, beta + h / 2 * k1);
        const double k3 = slope + h / 2 * l2,
                     l3 = curvature(s + h / 2, beta + h / 2 * k2);
        const double k4 = slope + h * l3, l4 = curvature(s + h, beta + h * k3);
        beta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        slope += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
      }
    return beta;
  }

  /// The lowest gamma with beta(1) = 0, by bisection in [3.5, 4.5].
  double
  critical_gamma()
  {
    double low = 3.5, high = 4.5;
    while (high - low > 1e-12)
      {
        const double mid = (low + high) / 2;
        (twist_at_clamp(low) * twist_at_clamp(mid) <= 0 ? high : low) = mid;
      }
    return (low + high) / 2;
  }

  /// P_cr L^2 / sqrt(EI2 GJ) of the discrete cantilever with @p n segments:
  /// L = 1, EI2 = GJ = 1, EI1 = 1e6 (bending in the xy-plane, d1 = e_z),
  /// tip load along -y ramped to 5 in 10 steps.
  double
  discrete_critical_load(const unsigned int n)
  {
    auto model = rodnet::testing::elastic_model(
      rodnet::testing::straight_network(n,
                                        Vector3(0, 0, 0),
                                        Vector3(1, 0, 0),
                                        true),
      RodStiffness{1e7, 1e6, 1, 1});
    model->clamp_end("clamp", 0, true);
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           Vector3(0, -5, 0));
    model->finalize();
    StaticSolver::Parameters parameters;
    parameters.n_steps            = 10;
    parameters.find_critical_load = true;
    StaticSolver solver(*model, parameters);
    VectorType   u = model->create_vector();
    solver.run(u, [](const auto &, const auto &) {});
    return 5 * solver.critical_load_factor();
  }

  TEST(LateralTorsionalBuckling, FinerIsAtLeastAsAccurate)
  {
    const double gamma        = critical_gamma();
    const double coarse       = discrete_critical_load(100);
    const double fine         = discrete_critical_load(200);
    const double error_coarse = (coarse - gamma) / gamma;
    const double error_fine   = (fine - gamma) / gamma;
    std::cout << "gamma " << gamma << "; N = 100: " << coarse << " (error "
              << error_coarse << "), N = 200: " << fine << " (error "
              << error_fine << ")" << std::endl;
    EXPECT_NEAR(gamma, 4.0126, 1e-4); // Timoshenko & Gere's 4.013
    EXPECT_LT(std::abs(error_coarse), 2e-4);
    EXPECT_LE(std::abs(error_fine), std::abs(error_coarse));
  }
} // namespace
