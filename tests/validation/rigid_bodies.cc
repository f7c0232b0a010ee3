// Rigid bodies (Loads/Rigid bodies) on the natural frequencies of rods,
// each against an analytic frequency equation of Euler-Bernoulli or
// torsion theory: a cantilever with a tip mass (the classical equation,
// several mass ratios, convergence with N), with the tip body's rotary
// inertia J_p and a centre offset (the frequency determinant derived in
// doc/theory.md, "Rigid bodies"), a tip disc on a twisted shaft (J_t), and
// a free-free shaft through a hub of isotropic inertia j (a welded network
// junction and a rotation handle); the weight of an offset body.
#include <common/natural_frequencies.h>
#include <common/scene_text.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// Rod data: EI = rho A = L = 1 throughout; EA, GJ and rho J as given.
  struct Shaft
  {
    double EA, GJ, rho_J;
  };

  /// The material subsection of @p s with EI = rho A = 1 and no rotary
  /// inertia of the sections: the references are Euler-Bernoulli beams.
  std::string
  material(const Shaft &s)
  {
    std::ostringstream t;
    t.precision(17);
    t << "subsection Material\n  set Mass per length = 1\n"
      << "  set Twist inertia per length = " << s.rho_J
      << "\n  set Rotary inertia per length = 0"
      << "\n  subsection linear elastic\n    set Stiffness input = direct\n"
      << "    set EA = " << s.EA << "\n    set EI1 = 1\n    set EI2 = 1\n"
      << "    set GJ = " << s.GJ << "\n  end\nend\n";
    return t.str();
  }

  /// Time stepping (the inertia is read for a dynamic integrator).
  const std::string dynamic_solver =
    "subsection Solver\n  set Method = time stepping\n"
    "  subsection Time stepping\n    set Integrator = midpoint\n"
    "    set Time step = 0.01\n  end\nend\n";

  /// A cantilever of length 1 along x, clamped at the first segment's
  /// midpoint (free length exactly 1), @p n segments, the rigid bodies
  /// @p bodies.
  std::string
  cantilever(const unsigned int n, const Shaft &s, const std::string &bodies)
  {
    return "subsection Geometry\n  set Segments = " + std::to_string(n) +
           "\n  set Clamp at first segment midpoint = true\nend\n" +
           material(s) +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Loads\n  set Rigid bodies = " +
           bodies + "\nend\n" + dynamic_solver;
  }

  /// The first @p count roots of @p f in (0, @p up_to), by bisection of
  /// the sign changes on a fine grid.
  std::vector<double>
  roots(const std::function<double(double)> &f,
        const unsigned int                   count,
        const double                         up_to)
  {
    std::vector<double> found;
    const double        step = 1e-3;
    for (double a = step; a < up_to && found.size() < count; a += step)
      {
        double lo = a, hi = a + step;
        if (f(lo) * f(hi) > 0)
          continue;
        for (unsigned int i = 0; i < 100; ++i)
          {
            const double mid                = (lo + hi) / 2;
            (f(lo) * f(mid) <= 0 ? hi : lo) = mid;
          }
        found.push_back((lo + hi) / 2);
      }
    return found;
  }

  /// The published frequency equation of a cantilever with a tip mass of
  /// ratio alpha = m / (rho A L), in beta = b L (omega = beta^2 sqrt(EI /
  /// (rho A L^4))): 1 + cos cosh + alpha beta (cos sinh - sin cosh).
  double
  tip_mass_equation(const double beta, const double alpha)
  {
    return 1 + std::cos(beta) * std::cosh(beta) +
           alpha * beta *
             (std::cos(beta) * std::sinh(beta) -
              std::sin(beta) * std::cosh(beta));
  }

  /**
   * The frequency determinant of a cantilever with a tip body of mass
   * ratio alpha, rotary inertia ratio gamma = J_p / (rho A L^3) about its
   * centre, the centre at delta = c / L beyond the tip on the tangent
   * (doc/theory.md, "Rigid bodies"): W = A (cosh - cos) + B (sinh - sin)
   * in xi = x / L with W''' = -alpha beta^4 (W + delta W') and W'' =
   * beta^4 [alpha delta (W + delta W') + gamma W'] at xi = 1, divided by
   * cosh beta to stay of order 1.
   */
  double
  tip_body_determinant(const double beta,
                       const double alpha,
                       const double gamma,
                       const double delta)
  {
    const double    ch = std::cosh(beta), c = std::cos(beta);
    const double    sh = std::sinh(beta), s = std::sin(beta);
    const double    b2 = beta * beta, b3 = b2 * beta, b4 = b2 * b2;
    Eigen::Vector2d W(ch - c, sh - s), W1(beta * (sh + s), beta * (ch - c));
    Eigen::Vector2d W2(b2 * (ch + c), b2 * (sh + s));
    Eigen::Vector2d W3(b3 * (sh - s), b3 * (ch + c));
    const Eigen::Vector2d centre = W + delta * W1;
    Eigen::Matrix2d       rows;
    rows.row(0) = W3 + alpha * b4 * centre;
    rows.row(1) = W2 - b4 * (alpha * delta * centre + gamma * W1);
    return rows.determinant() / (ch * ch * b4);
  }

  /// The distinct frequencies of a rod whose bending comes in equal pairs
  /// (EI1 = EI2): every other one of @p omega.
  std::vector<double>
  bending_pairs(const Eigen::VectorXd &omega, const unsigned int count)
  {
    std::vector<double> distinct;
    for (unsigned int k = 0; k < count; ++k)
      distinct.push_back(omega[2 * k]);
    return distinct;
  }

  // Mass ratios 0.2, 1, 5; rho J = 1e-4 puts the torsion (157 / s) above
  // the second bending mode. The first two bending frequencies against the
  // classical equation, N = 10, 20, 40.
  TEST(RigidBodies, CantileverWithTipMass)
  {
    const Shaft shaft{1e6, 1, 1e-4};
    for (const double alpha : {0.2, 1.0, 5.0})
      {
        const std::vector<double> beta =
          roots([alpha](double b) { return tip_mass_equation(b, alpha); },
                2,
                10);
        ASSERT_EQ(beta.size(), 2u);
        std::vector<double> errors;
        for (const unsigned int n : {10u, 20u, 40u})
          {
            std::ostringstream body;
            body.precision(17);
            body << "end: mass " << alpha;
            const std::vector<double> omega =
              bending_pairs(natural_frequencies(
                              cantilever(n, shaft, body.str())),
                            2);
            double error = 0;
            for (unsigned int k = 0; k < 2; ++k)
              {
                const double expected = beta[k] * beta[k];
                const double relative = omega[k] / expected - 1;
                std::cout << "tip mass ratio " << alpha << ", N = " << n
                          << ", mode " << k + 1 << ": omega " << omega[k]
                          << ", expected " << expected << ", relative error "
                          << relative << std::endl;
                error = std::max(error, std::abs(relative));
              }
            errors.push_back(error);
          }
        EXPECT_LT(errors.back(), 2e-3) << "mass ratio " << alpha;
        const double order = std::log2(errors[1] / errors[2]);
        std::cout << "observed order " << order << std::endl;
        EXPECT_NEAR(order, 2, 0.3) << "mass ratio " << alpha;
      }
  }

  // The reference determinant reduces to the published equation without
  // rotary inertia and offset, and to the clamped-guided beam (tan beta =
  // -tanh beta, beta_1 = 2.36502) for an infinite rotary inertia.
  TEST(RigidBodies, TipBodyDeterminantLimits)
  {
    const auto published =
      roots([](double b) { return tip_mass_equation(b, 1.0); }, 2, 10);
    const auto derived =
      roots([](double b) { return tip_body_determinant(b, 1.0, 0, 0); }, 2, 10);
    ASSERT_EQ(derived.size(), 2u);
    for (unsigned int k = 0; k < 2; ++k)
      EXPECT_NEAR(derived[k], published[k], 1e-10);
    // (A huge inertia adds a slow rocking mode below it.)
    const auto guided =
      roots([](double b) { return tip_body_determinant(b, 0, 1e8, 0); }, 5, 10);
    double nearest = 1e9;
    for (const double b : guided)
      nearest = std::min(nearest, std::abs(b - 2.36502));
    EXPECT_LT(nearest, 1e-4);
  }

  /// The first two bending frequencies of the cantilever with the tip
  /// body @p body (mass ratio 1, J_p / (rho A L^3) = @p gamma, offset
  /// @p delta L), N = 20 and 40, against the determinant; their largest
  /// relative errors.
  std::vector<double>
  tip_body_errors(const std::string &body,
                  const double       gamma,
                  const double       delta,
                  const Shaft       &shaft)
  {
    const std::vector<double> beta =
      roots([&](
              double b) { return tip_body_determinant(b, 1.0, gamma, delta); },
            2,
            10);
    std::vector<double> errors;
    for (const unsigned int n : {20u, 40u})
      {
        const std::vector<double> omega =
          bending_pairs(natural_frequencies(cantilever(n, shaft, body)), 2);
        double error = 0;
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double expected = beta[k] * beta[k];
            const double relative = omega[k] / expected - 1;
            std::cout << "\"" << body << "\", N = " << n << ", mode " << k + 1
                      << ": omega " << omega[k] << ", expected " << expected
                      << ", relative error " << relative << std::endl;
            error = std::max(error, std::abs(relative));
          }
        errors.push_back(error);
      }
    return errors;
  }

  // An isotropic tip body (J_p / (rho A L^3) = 0.01, 0.05) turns with a
  // rotation handle at the end: second order. GJ = 1e4, rho J = 1 keep the
  // torsion (156 / s with the body's J_t) above the second bending mode.
  TEST(RigidBodies, CantileverWithTipRotaryInertia)
  {
    const Shaft shaft{1e6, 1e4, 1};
    for (const double gamma : {0.01, 0.05})
      {
        std::ostringstream body;
        body << "end: mass 1 inertia " << gamma;
        const std::vector<double> errors =
          tip_body_errors(body.str(), gamma, 0, shaft);
        const double order = std::log2(errors[0] / errors[1]);
        std::cout << "observed order " << order << std::endl;
        EXPECT_LT(errors[1], 2e-3);
        EXPECT_NEAR(order, 2, 0.3);
      }
  }

  // A body welded to the end segment, J_p / (rho A L^3) = 0.01 and its
  // centre c = 0.1 L beyond the tip: the end segment's tangent sits l/2
  // inside the end, first order (+1.1 %, +0.50 % at N = 20, 40).
  TEST(RigidBodies, CantileverWithOffsetTipBody)
  {
    const Shaft               shaft{1e6, 1, 1e-4};
    const std::vector<double> errors =
      tip_body_errors("end: mass 1 inertia 1e-6,0.01 offset 0.1",
                      0.01,
                      0.1,
                      shaft);
    const double order = std::log2(errors[0] / errors[1]);
    std::cout << "observed order " << order << std::endl;
    EXPECT_LT(errors[1], 1e-2);
    EXPECT_NEAR(order, 1, 0.3);
  }

  // A disc of inertia 0.5 rho J L on the tip of a clamped shaft (GJ =
  // 0.01, rho J = 1, bending far above): kL tan kL = rho J L / J_t,
  // omega = k sqrt(GJ / (rho J)), the first two modes, N = 20 and 40:
  // isotropic on a rotation handle (second order) and axisymmetric J_t on
  // the end segment's twist (first order).
  TEST(RigidBodies, ShaftWithTipDisc)
  {
    const Shaft shaft{1e6, 0.01, 1};
    const auto  k =
      roots([](double x) { return x * std::sin(x) - 2 * std::cos(x); }, 2, 10);
    for (const std::string disc : {"0.5", "0.5,1e-6"})
      {
        std::vector<double> errors;
        for (const unsigned int n : {20u, 40u})
          {
            const Eigen::VectorXd omega = natural_frequencies(
              cantilever(n, shaft, "end: mass 1e-6 inertia " + disc));
            double error = 0;
            for (unsigned int m = 0; m < 2; ++m)
              {
                const double expected =
                  k[m] * std::sqrt(shaft.GJ / shaft.rho_J);
                std::cout << "tip disc " << disc << ", N = " << n << ", mode "
                          << m + 1 << ": omega " << omega[m] << ", expected "
                          << expected << ", relative error "
                          << omega[m] / expected - 1 << std::endl;
                error = std::max(error, std::abs(omega[m] / expected - 1));
              }
            errors.push_back(error);
          }
        const double order = std::log2(errors[0] / errors[1]);
        std::cout << "observed order " << order << std::endl;
        const bool handle = disc == "0.5";
        EXPECT_LT(errors[1], handle ? 2e-3 : 1e-2) << disc;
        EXPECT_NEAR(order, handle ? 2 : 1, 0.3) << disc;
      }
  }

  /// The nonzero natural frequencies (omega^2 above 1e-4) of @p text.
  std::vector<double>
  nonzero_frequencies(const std::string &text)
  {
    const Eigen::VectorXd omega2 = squared_natural_frequencies(text);
    std::vector<double>   omega;
    for (unsigned int i = 0; i < omega2.size(); ++i)
      if (omega2[i] > 1e-4)
        omega.push_back(std::sqrt(omega2[i]));
    return omega;
  }

  /// A free-free shaft from (-1, 0, 0) to (1, 0, 0) through a hub of
  /// isotropic inertia @p j at its middle: two rods welded at the network
  /// node "hub", or with @p handle one rod and the body at "mid" (a
  /// rotation handle there); @p n segments per half.
  std::string
  shaft_with_hub(const double j, const unsigned int n, const bool handle)
  {
    std::ostringstream s;
    s.precision(17);
    const Shaft shaft{1e3, 0.01, 1};
    if (handle)
      s << "subsection Geometry\n  set Start = -1, 0, 0\n  set End = 1, 0, 0\n"
        << "  set Segments = " << 2 * n << "\nend\n";
    else
      {
        const std::string file = RODNET_BINARY_DIR "/rigid_body_hub.net";
        std::ofstream(file) << "node left -1 0 0\nnode hub 0 0 0\n"
                               "node right 1 0 0\nbeam left hub d1 0 0 1\n"
                               "beam hub right d1 0 0 1\n";
        s << "subsection Geometry\n  set Generator = network file\n"
          << "  set Network file = " << file << "\n  set Segments = " << n
          << "\nend\n";
      }
    s << material(shaft)
      << "subsection Loads\n  set Rigid bodies = " << (handle ? "mid" : "@hub")
      << ": mass 1e-6 inertia " << j << "\nend\n"
      << dynamic_solver;
    return s.str();
  }

  // GJ = 0.01, rho J = 1, halves of L = 1, EI = rho A = 1, EA = 1e3: in
  // the modes symmetric about the hub each half is a shaft free at its far
  // end and loaded by half the hub, tan kL = -(j / (2 rho J L)) kL; the
  // antisymmetric ones leave the hub still, kL = (2n - 1) pi / 2;
  // omega = 0.1 k. With j = 1: kL = 1.5708, 2.2889, 4.7124, 5.0870, all
  // far below the bending modes.
  TEST(RigidBodies, FreeShaftThroughAHub)
  {
    const double j = 1;
    const auto   symmetric =
      roots([j](double x) { return std::sin(x) + j / 2 * x * std::cos(x); },
            2,
            10);
    const std::vector<double> expected = {0.1 * M_PI / 2,
                                          0.1 * symmetric[0],
                                          0.1 * 3 * M_PI / 2,
                                          0.1 * symmetric[1]};
    for (const bool handle : {false, true})
      {
        const std::vector<double> omega =
          nonzero_frequencies(shaft_with_hub(j, 40, handle));
        ASSERT_GE(omega.size(), 4u);
        for (unsigned int k = 0; k < 4; ++k)
          {
            std::cout << (handle ? "handle" : "junction") << " hub, mode "
                      << k + 1 << ": omega " << omega[k] << ", expected "
                      << expected[k] << ", relative error "
                      << omega[k] / expected[k] - 1 << std::endl;
            EXPECT_NEAR(omega[k] / expected[k], 1, 2e-3) << k;
          }
      }
  }

  // The weight of a body at c = 0.2 L beyond the tip of a cantilever
  // (N = 40, linear range): the tip deflection of the force m g and the
  // moment m g c, w = m g L^3 / (3 EI) + m g c L^2 / (2 EI); the body
  // welded to the end segment ("offset 0.2"), and on a rotation handle at
  // the tip with its centre off it ("centre 0.2,0,0", the weight's lever
  // BodyWeightFamily: without it w is 23% short).
  TEST(RigidBodies, WeightActsAtTheCentre)
  {
    for (const std::string body : {"offset 0.2", "centre 0.2,0,0"})
      {
        const std::string scene =
          "subsection Geometry\n  set Segments = 40\n"
          "  set Clamp at first segment midpoint = true\n"
          "  set Director d1 = 0, 0, 1\nend\n" +
          direct_material(1e6, 1, 1, 1) +
          "subsection Supports\n  set Clamped ends = start\nend\n"
          "subsection Loads\n  set Steps = 1\n  set Mass per length = 1e-12\n"
          "  set Gravity = 0, 0, -1e-4\n"
          "  set Rigid bodies = end: mass 2 " +
          body + "\nend\n" + end_position_output();
        const RunSummary run = run_scene_text(scene, "rigid_body_weight");
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        const double P        = 2e-4;
        const double expected = -(P / 3 + P * 0.2 / 2);
        const double w        = run.rows.back()[probe_column(run, "z")];
        std::cout << body << ": tip deflection " << w << ", expected "
                  << expected << ", relative error " << w / expected - 1
                  << std::endl;
        EXPECT_NEAR(w / expected, 1, 1e-3) << body;
      }
  }
} // namespace
