// The single ribbon bridge (scenes/substrate_bridge.prm; Lestringant &
// Kochmann section 4.4, issue 34): a ribbon clamped at both ends to a
// substrate released to the compressive strain eps buckles into the
// clamped-clamped inextensible elastica under the end shortening eps L.
// Its first mode is one period of the pendulum equation EI theta'' + P sin
// theta = 0: with k = sin(alpha / 2), m = k^2 and omega = sqrt(P / EI),
// L = 4 K(m) / omega, the chord 4 (2 E(m) - K(m)) / omega and the rise
// 4 k / omega (Timoshenko & Gere's elastica, sin(theta / 2) =
// k sn(omega s)), so
//   shortening / L = 2 (1 - E(m) / K(m)),   rise / L = sqrt(m) / K(m).
// The first test checks these against a quadrature of the elastica's
// equations from the clamp; the second runs the scene at N = 21 ... 161
// segments over the free length and asserts second-order convergence of
// the apex to them.
#include <common/run_scene_text.h>

#include <array>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The clamped-clamped elastica of length 1 at the end shortening
  /// @p shortening: the parameter m of its first mode and its rise.
  struct BridgeElastica
  {
    double m;
    double rise;
    /// P L^2 / EI = (4 K(m))^2.
    double load;
  };

  BridgeElastica
  bridge_elastica(const double shortening)
  {
    // 2 (1 - E/K) grows from 0 to 2 with m; the standard library's
    // elliptic integrals take the modulus k = sqrt(m).
    double lo = 0, hi = 1 - 1e-15;
    for (int i = 0; i < 200; ++i)
      {
        const double m = 0.5 * (lo + hi);
        const double k = std::sqrt(m);
        (2 * (1 - std::comp_ellint_2(k) / std::comp_ellint_1(k)) < shortening ?
           lo :
           hi)         = m;
      }
    const double m = 0.5 * (lo + hi);
    const double K = std::comp_ellint_1(std::sqrt(m));
    return {m, std::sqrt(m) / K, 16 * K * K};
  }

  TEST(SubstrateBridge, ClosedFormMatchesTheElasticaQuadrature)
  {
    // theta'' = -P sin(theta), x' = cos(theta), z' = sin(theta) from the
    // clamp (theta = 0, theta' = 2 k sqrt(P): the first integral
    // theta'^2 / 2 = P (cos theta - cos alpha)) to mid-span by RK4: there
    // the tangent is level again, the chord is half the shortened span and
    // z is the rise.
    for (const double shortening : {0.05, 0.3, 0.6})
      {
        const BridgeElastica  e = bridge_elastica(shortening);
        std::array<double, 4> y{{0, 2 * std::sqrt(e.m * e.load), 0, 0}};
        const auto            f = [&](const std::array<double, 4> &u) {
          return std::array<double, 4>{
            {u[1], -e.load * std::sin(u[0]), std::cos(u[0]), std::sin(u[0])}};
        };
        const int    n  = 20000;
        const double ds = 0.5 / n;
        for (int i = 0; i < n; ++i)
          {
            std::array<double, 4> k1 = f(y), u = y;
            for (int c = 0; c < 4; ++c)
              u[c] = y[c] + ds / 2 * k1[c];
            std::array<double, 4> k2 = f(u);
            for (int c = 0; c < 4; ++c)
              u[c] = y[c] + ds / 2 * k2[c];
            std::array<double, 4> k3 = f(u);
            for (int c = 0; c < 4; ++c)
              u[c] = y[c] + ds * k3[c];
            std::array<double, 4> k4 = f(u);
            for (int c = 0; c < 4; ++c)
              y[c] += ds / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
          }
        EXPECT_NEAR(y[0], 0, 1e-10) << shortening;
        EXPECT_NEAR(y[2], (1 - shortening) / 2, 1e-12) << shortening;
        EXPECT_NEAR(y[3], e.rise, 1e-12) << shortening;
      }
    // Small shortenings: the clamped Euler load 4 pi^2 and the rise
    // (2 / pi) sqrt(shortening) of the linearized mode (1 - cos 2 pi s) / 2.
    const BridgeElastica small = bridge_elastica(1e-6);
    EXPECT_NEAR(small.load, 4 * M_PI * M_PI, 1e-4);
    EXPECT_NEAR(small.rise, 2 / M_PI * 1e-3, 1e-8);
  }

  /// The bonded ribbon at N segments over its free length 1 (scene
  /// comment): vertices -h/2 + i h, the end segments flat, the bump
  /// a (1 - cos(2 pi (x - h/2) / (1 - h))) / 2 between them.
  std::vector<std::array<double, 2>>
  bonded_ribbon(const unsigned int n)
  {
    const double                       h = 1.0 / n, a = 0.01;
    std::vector<std::array<double, 2>> points;
    for (unsigned int i = 0; i <= n + 1; ++i)
      {
        const double x     = -h / 2 + i * h;
        const bool   inner = i >= 2 && i + 2 <= n + 1;
        points.push_back(
          {{x,
            inner ? a * (1 - std::cos(2 * M_PI * (x - h / 2) / (1 - h))) / 2 :
                    0.}});
      }
    return points;
  }

  /// The ribbon's stress-free length between its bonding sites, the
  /// midpoints of its end segments.
  double
  free_length(const std::vector<std::array<double, 2>> &points)
  {
    std::vector<double> l;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      l.push_back(std::hypot(points[i + 1][0] - points[i][0],
                             points[i + 1][1] - points[i][1]));
    double sum = 0;
    for (const double li : l)
      sum += li;
    return sum - l.front() / 2 - l.back() / 2;
  }

  /// scenes/substrate_bridge.prm with @p points.
  std::string
  bridge_scene(const std::vector<std::array<double, 2>> &points)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/substrate_bridge.prm");
    std::stringstream text;
    text << file.rdbuf() << "\nsubsection Geometry\n  set Points = ";
    text.precision(17);
    for (std::size_t i = 0; i < points.size(); ++i)
      text << (i ? "; " : "") << points[i][0] << ", 0, " << points[i][1];
    text << "\nend\nsubsection Output\n  set Write VTU = false\n"
            "  set Plot = false\nend\n";
    return text.str();
  }

  TEST(SubstrateBridge, ApexConvergesAtSecondOrderToTheElastica)
  {
    const double        strain = 0.6;
    std::vector<double> n_values, errors;
    for (const unsigned int n : {21u, 41u, 81u, 161u})
      {
        const auto       points = bonded_ribbon(n);
        const RunSummary run =
          run_scene_text(bridge_scene(points),
                         "substrate_bridge_" + std::to_string(n));
        const double length = free_length(points);
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        ASSERT_DOUBLE_EQ(run.final_load_factor, 1);
        EXPECT_EQ(run.final_stable, 1) << n;
        const std::vector<double> &last = run.rows.back();
        // The site is the end segment's midpoint, x = 0 bonded, carried
        // towards the centre x = 1/2 by the strain; the end vertex follows
        // rigidly, half a segment behind.
        EXPECT_NEAR(last.at(probe_column(run, "site_x")),
                    strain / 2 - 0.5 / n,
                    1e-12);
        EXPECT_NEAR(last.at(probe_column(run, "apex_x")), 0.5, 1e-8);
        // The sites end (1 - strain) apart; the ribbon keeps its length.
        const double         shortening = 1 - (1 - strain) / length;
        const BridgeElastica elastica   = bridge_elastica(shortening);
        const double         reference  = length * elastica.rise;
        const double         apex       = last.at(probe_column(run, "apex_z"));
        std::cout.precision(10);
        std::cout << "N = " << n << ": apex " << apex << ", reference "
                  << reference << ", error " << apex - reference << std::endl;
        n_values.push_back(n);
        errors.push_back(std::abs(apex - reference));
        // The clamp's reaction at the site is the elastica's thrust
        // P = (4 K)^2 EI2 / l^2 (EI2 = 0.01), second order too: measured
        // -4.4e-2 at N = 21, -7.5e-4 at N = 161.
        const double thrust   = 0.01 * elastica.load / (length * length);
        const double reaction = last.at(probe_column(run, "thrust"));
        std::cout << "  thrust " << reaction << ", reference " << thrust
                  << std::endl;
        if (n == 161)
          EXPECT_NEAR(reaction, thrust, 2e-3 * thrust);
      }
    for (std::size_t i = 1; i < errors.size(); ++i)
      std::cout << "observed order " << n_values[i - 1] << " -> " << n_values[i]
                << ": "
                << std::log(errors[i - 1] / errors[i]) /
                     std::log(n_values[i] / n_values[i - 1])
                << std::endl;
    const double order =
      std::log(errors[2] / errors[3]) / std::log(n_values[3] / n_values[2]);
    EXPECT_GT(order, 1.8);
    EXPECT_LT(order, 2.2);
    // Measured 3.3e-6 L at N = 161.
    EXPECT_LT(errors.back(), 5e-6);
  }
} // namespace
