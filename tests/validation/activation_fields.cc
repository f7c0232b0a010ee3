// Activation fields of rod groups (issue 34, doc/morphing.md): an unloaded
// rod, clamped at its start, takes its natural shape. L = 1, EA = 1e4,
// EI1 = EI2 = GJ = 1, d1 = e_z: a natural curvature about d1 bends it in
// the x-y plane, and its tip lies where the plane curve of that curvature
// ends:
//  - curvature kappa_0 on [a, b] (straight, circular arc, straight): the
//    closed form, second order in the segment length with region ends
//    between vertices (the hinges take the field integrated over their
//    Voronoi cells);
//  - axial eigenstrain eps on [a, b]: the rod grows by eps (b - a) to
//    rounding (each segment takes the field's mean over it); at the first
//    of four load steps by a quarter of that if ramped, by all if fixed;
//    in time stepping with the load factor t^2, by t^2 eps (b - a);
//  - kappa(s) = k s / L, a clothoid: against a quadrature of its tangent
//    angle k s^2 / (2 L), second order;
//  - curvature 2 about d1 and twist rate 3 sin(pi s / L) along a rod
//    clamped at its first segment's midpoint: against an RK4 integration
//    of the Kirchhoff frame equations, second order;
//  - the eigenstrain column of scenes/eigenstrain_column.prm with its
//    eigenstrain a field that the continuation parameter ramps: the
//    published bifurcation and deflections;
//  - two items of one group, and the fields of two groups on a network's
//    beam (its clamp a junction element, which takes the field over the
//    half segment beside the node), add: piecewise circular arcs;
//  - fields of their own functions of time in quasi-static time stepping,
//    and two of them with a ramped one: at every step the arcs of their
//    sum; switched on slowly under Newmark's rule: near the quasi-static
//    arc; on a viscoelastic rod clamped at both ends: the stored energy of
//    its relaxing Maxwell branch; a ramped curvature under continuation:
//    the arc of lambda times it at lambda = 0.5 and 1.
#include <common/run_scene_text.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// A piece of a plane curve: its length and its constant curvature.
  struct Piece
  {
    double length, curvature;
  };

  /// The end of the plane curve of @p pieces from the origin along e_x.
  std::array<double, 2>
  curve_end(const std::vector<Piece> &pieces)
  {
    double x = 0, y = 0, angle = 0;
    for (const Piece &p : pieces)
      {
        const double turned = angle + p.curvature * p.length;
        if (p.curvature == 0)
          {
            x += p.length * std::cos(angle);
            y += p.length * std::sin(angle);
          }
        else
          {
            x += (std::sin(turned) - std::sin(angle)) / p.curvature;
            y += (std::cos(angle) - std::cos(turned)) / p.curvature;
          }
        angle = turned;
      }
    return {{x, y}};
  }

  /// The scene text of the unloaded rod from (0,0,0) to (1,0,0) (or the
  /// network @p network) with @p segments segments and the group
  /// subsections @p groups, its start clamped, 4 load steps.
  std::string
  rod_scene(const unsigned int segments,
            const std::string &groups,
            const std::string &network = "")
  {
    std::ostringstream s;
    s << "subsection Geometry\n";
    if (!network.empty())
      s << "  set Generator = network file\n  set Network file = " << network
        << "\n";
    else
      s << "  set Director d1 = 0, 0, 1\n";
    s << "  set Segments = " << segments
      << "\nend\n"
         "subsection Material\n  subsection linear elastic\n"
         "    set Stiffness input = direct\n    set EA = 1e4\n"
         "    set EI1 = 1\n    set EI2 = 1\n    set GJ = 1\n  end\nend\n"
      << groups;
    if (network.empty())
      s << "subsection Supports\n  set Clamped ends = start\nend\n";
    s << "subsection Loads\n  set Steps = 4\nend\n"
         "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
         "  set Probes = x: position "
      << (network.empty() ? "end" : "@tip") << " x; y: position "
      << (network.empty() ? "end" : "@tip") << " y\nend\n";
    return s.str();
  }

  /// The tip of the run of @p scene at load factor 1.
  std::array<double, 2>
  tip_of(const std::string &scene, const std::string &directory)
  {
    const RunSummary run = run_scene_text(scene, directory);
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    EXPECT_DOUBLE_EQ(run.rows.back()[0], 1.0);
    return {{run.rows.back()[probe_column(run, "x")],
             run.rows.back()[probe_column(run, "y")]}};
  }

  /// The distances of the tips of @p groups at 20, 80 and 320 segments
  /// from @p exact; asserts the last is below @p tolerance and that they
  /// fall at an observed order above 1.9. Where a region ends inside a
  /// cell the error depends on where in the cell: refined by 4, the ends of
  /// the regions below (a multiple of 1/30 plus 1/3 of a cell, or
  /// multiples of 0.1) stay where they are in their cells.
  void
  expect_second_order(const std::string           &groups,
                      const std::array<double, 2> &exact,
                      const double                 tolerance,
                      const std::string           &network = "")
  {
    std::vector<double> errors;
    for (const unsigned int n : {20u, 80u, 320u})
      {
        const std::array<double, 2> tip =
          tip_of(rod_scene(n, groups, network),
                 "activation_" + std::to_string(n));
        errors.push_back(std::hypot(tip[0] - exact[0], tip[1] - exact[1]));
        std::cout << n << " segments: tip error " << errors.back() << "\n";
      }
    for (std::size_t i = 1; i < errors.size(); ++i)
      {
        const double order = std::log(errors[i - 1] / errors[i]) / std::log(4.);
        EXPECT_GT(order, 1.9)
          << "errors " << errors[i - 1] << ", " << errors[i];
      }
    EXPECT_LT(errors.back(), tolerance);
  }

  TEST(ActivationFields, NaturalCurvatureOnAnInterval)
  {
    // Region ends 2/3 of a cell past a vertex.
    const double       a = 7. / 30, b = 22. / 30, kappa0 = 2.;
    std::ostringstream groups;
    groups << std::setprecision(17)
           << "subsection Group all\n  set Natural curvature = 2, 0 on " << a
           << " to " << b << "\nend\n";
    expect_second_order(groups.str(),
                        curve_end({{a, 0.}, {b - a, kappa0}, {1 - b, 0.}}),
                        1.5e-6); // 9.4e-7 measured
  }

  TEST(ActivationFields, AxialEigenstrainLengthensItsRegion)
  {
    for (const unsigned int n : {20u, 37u})
      {
        const std::array<double, 2> tip =
          tip_of(rod_scene(n,
                           "subsection Group all\n  set Axial eigenstrain = "
                           "0.01 on 0.23 to 0.71\nend\n"),
                 "activation_eigenstrain");
        EXPECT_NEAR(tip[0], 1 + 0.01 * (0.71 - 0.23), 1e-12) << n;
        EXPECT_NEAR(tip[1], 0., 1e-12) << n;
      }
  }

  TEST(ActivationFields, FixedFieldsAreThereFromTheStart)
  {
    // At load factor 0.25 (the first of 4 steps) a ramped eigenstrain has
    // grown the rod by a quarter of eps (b - a), a fixed one by all of it.
    for (const bool fixed : {false, true})
      {
        const RunSummary run =
          run_scene_text(rod_scene(20,
                                   std::string(
                                     "subsection Group all\n  set Axial "
                                     "eigenstrain = 0.01 on 0.23 to 0.71") +
                                     (fixed ? " fixed" : "") + "\nend\n"),
                         "activation_fixed");
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        ASSERT_DOUBLE_EQ(run.rows[1][0], 0.25);
        EXPECT_NEAR(run.rows[1][probe_column(run, "x")],
                    1 + (fixed ? 1. : 0.25) * 0.01 * (0.71 - 0.23),
                    1e-12)
          << fixed;
      }
  }

  TEST(ActivationFields, FieldsFollowTheLoadFactorInTime)
  {
    // Quasi-static time stepping, load factor t^2: a ramped eigenstrain
    // grows the rod by t^2 eps (b - a) at every time.
    std::string scene = rod_scene(
      20,
      "subsection Group all\n  set Axial eigenstrain = 0.01 on 0.23 to "
      "0.71\nend\n"
      "subsection Solver\n  set Method = time stepping\n"
      "  subsection Time stepping\n    set Integrator = quasi-static\n"
      "    set Time step = 0.25\n    set Load factor = t^2\n  end\nend\n");
    scene.erase(scene.find("subsection Loads"), 37);
    const RunSummary run = run_scene_text(scene, "activation_in_time");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 5u);
    for (const std::vector<double> &row : run.rows)
      EXPECT_NEAR(row[probe_column(run, "x")],
                  1 + row[0] * row[0] * 0.01 * (0.71 - 0.23),
                  1e-12)
        << "t = " << row[0];
  }

  /// rod_scene() of @p segments segments in quasi-static time stepping
  /// from 0 to @p end_time in steps of 0.25 s (@p solver: more entries of
  /// the Time stepping subsection).
  std::string
  time_stepping_scene(const unsigned int segments,
                      const std::string &groups,
                      const double       end_time,
                      const std::string &solver = "")
  {
    std::string scene = rod_scene(segments, groups);
    scene.erase(scene.find("subsection Loads"), 37);
    std::ostringstream s;
    s << "subsection Solver\n  set Method = time stepping\n"
         "  subsection Time stepping\n    set Integrator = quasi-static\n"
         "    set Time step = 0.25\n    set End time = "
      << end_time << "\n"
      << solver << "  end\nend\n";
    return scene + s.str();
  }

  TEST(ActivationFields, FunctionOfTimeBendsTheRodAtEveryStep)
  {
    // Curvature 2 f(t) on [7/30, 22/30], f(t) = 1 - exp(-t/2), of its own
    // function of time while the load factor stays 0: quasi-statically the
    // free end takes the straight-arc-straight shape of curvature 2 f(t) at
    // every time (80 segments: 1.5e-5 of tip error at full curvature 2,
    // NaturalCurvatureOnAnInterval).
    const double       a = 7. / 30, b = 22. / 30;
    std::ostringstream groups;
    groups << std::setprecision(17)
           << "subsection Group all\n  set Natural curvature = 2, 0 on " << a
           << " to " << b << " in time 1 - exp(-t/2)\nend\n";
    const RunSummary run = run_scene_text(
      time_stepping_scene(80, groups.str(), 3., "    set Load factor = 0\n"),
      "activation_of_time");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 13u);
    for (const std::vector<double> &row : run.rows)
      {
        const double                kappa = 2 * (1 - std::exp(-row[0] / 2));
        const std::array<double, 2> exact =
          curve_end({{a, 0.}, {b - a, kappa}, {1 - b, 0.}});
        EXPECT_NEAR(row[probe_column(run, "x")], exact[0], 2e-5)
          << "t = " << row[0];
        EXPECT_NEAR(row[probe_column(run, "y")], exact[1], 2e-5)
          << "t = " << row[0];
      }
  }

  TEST(ActivationFields, FunctionOfTimeInDynamics)
  {
    // The same arc switched on smoothly over T = 5 s, f(t) = (1 -
    // cos(pi t / T)) / 2, under Newmark's rule: steel-like rod of radius
    // 0.01, E = 1e9, rho = 1000 (first period 2 pi / (1.875^2
    // sqrt(EI / (rho A L^4))) = 0.36 s, far below T), so that inertia
    // lags the quasi-static shape by about (pi / T)^2 / omega_1^2 = 1.3e-3
    // of it. At every step from T on the tip is within 2e-3 of the arc of
    // curvature 2 (the spatial error at 20 segments is 2.4e-4). The
    // energy grows under the constant load factor while the field moves:
    // no false alarm of instability.
    const double       a = 7. / 30, b = 22. / 30;
    std::ostringstream scene;
    scene << std::setprecision(17)
          << "subsection Geometry\n  set Director d1 = 0, 0, 1\n"
             "  set Segments = 20\nend\n"
             "subsection Material\n  set Density = 1000\n"
             "  subsection linear elastic\n    set Young's modulus = 1e9\n"
             "    set Cross section = circle\n    set Radius = 0.01\n"
             "  end\nend\n"
             "subsection Group all\n  set Natural curvature = 2, 0 on "
          << a << " to " << b
          << " in time if(t < 5, (1 - cos(pi*t/5))/2, 1)\nend\n"
             "subsection Supports\n  set Clamped ends = start\nend\n"
             "subsection Solver\n  set Method = time stepping\n"
             "  subsection Time stepping\n    set Time step = 0.01\n"
             "    set End time = 6\n  end\nend\n"
             "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
             "  set Probes = x: position end x; y: position end y\nend\n";
    const RunSummary run = run_scene_text(scene.str(), "activation_dynamics");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_NEAR(run.rows.back()[0], 6., 1e-9);
    const std::array<double, 2> arc =
      curve_end({{a, 0.}, {b - a, 2.}, {1 - b, 0.}});
    double largest = 0;
    for (const std::vector<double> &row : run.rows)
      if (row[0] >= 5)
        largest = std::max(largest,
                           std::hypot(row[probe_column(run, "x")] - arc[0],
                                      row[probe_column(run, "y")] - arc[1]));
    std::cout << "largest distance from the arc after T: " << largest << "\n";
    EXPECT_LT(largest, 2e-3);
  }

  TEST(ActivationFields, FunctionOfTimeRelaxesAViscoelasticRod)
  {
    // A standard linear solid rod (E1 = 1e6, E2 = 0.5 E1, relaxation time
    // t_r = 0.3 s, circle of radius 0.01: EI = E1 pi r^4 / 4), clamped at
    // both ends, under the natural curvature k0 t about d1 along it,
    // quasi-static steps h = 0.05 s: it stays straight, so every hinge's
    // bending strain is e = -k0 t, and its viscous strain alpha follows the
    // backward-Euler step of t_r alpha' = e - alpha
    // (materials/standard_linear_solid.h), alpha_n = (h e_n + t_r
    // alpha_n-1) / (h + t_r). The stored energy of the 19 hinges (Voronoi
    // lengths 0.05, L - 0.05 in all) is then
    // (L - 0.05) / 2 EI [e^2 + (E2/E1) (e - alpha)^2]: the Maxwell branch
    // relaxes as the field grows (measured: within 1e-9 relative).
    const double k0 = 2, tr = 0.3, ratio = 0.5, h = 0.05, segment = 0.05;
    const double EI = 1e6 * M_PI * std::pow(0.01, 4) / 4;
    std::string  scene =
      "subsection Geometry\n  set Director d1 = 0, 0, 1\n"
      "  set Segments = 20\nend\n"
      "subsection Material\n  set Model = standard linear solid\n"
      "  subsection standard linear solid\n"
      "    set Young's modulus E1 = 1e6\n    set Cross section = circle\n"
      "    set Radius = 0.01\n    set Modulus ratio E2/E1 = 0.5\n"
      "    set Relaxation time = 0.3\n  end\nend\n"
      "subsection Group all\n  set Natural curvature = 2, 0 in time t\nend\n"
      "subsection Supports\n  set Clamped ends = start, end\nend\n"
      "subsection Solver\n  set Method = time stepping\n"
      "  subsection Time stepping\n    set Integrator = quasi-static\n"
      "    set Time step = 0.05\n    set End time = 1\n  end\nend\n"
      "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
      "  set Probes = energy: energy; y: position mid y\nend\n";
    const RunSummary run = run_scene_text(scene, "activation_viscoelastic");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 21u);
    double alpha = 0;
    for (std::size_t n = 1; n < run.rows.size(); ++n)
      {
        const double t = run.rows[n][0], e = -k0 * t;
        alpha = (h * e + tr * alpha) / (h + tr);
        const double exact =
          (1 - segment) / 2 * EI * (e * e + ratio * (e - alpha) * (e - alpha));
        EXPECT_NEAR(run.rows[n][probe_column(run, "energy")],
                    exact,
                    1e-9 * exact)
          << "t = " << t;
        EXPECT_NEAR(run.rows[n][probe_column(run, "y")], 0, 1e-12);
      }
  }

  TEST(ActivationFields, FieldsOfTwoFunctionsOfTimeAdd)
  {
    // 2 t on [0.2, 0.6] and 1 - t on [0.4, 0.8]: the arcs 2 t, 1 + t,
    // 1 - t; with a third field ramped by the load factor t^2 on
    // [0.2, 0.4], 2 t + 3 t^2 on the first (320 segments, region ends on
    // vertices; measured at t = 1: 7.6e-5 at 80 segments, 4.8e-6 at 320).
    const RunSummary run = run_scene_text(
      time_stepping_scene(320,
                          "subsection Group all\n  set Natural curvature = "
                          "2, 0 on 0.2 to 0.6 in time t; 1, 0 on 0.4 to 0.8 "
                          "in time 1 - t; 3, 0 on 0.2 to 0.4\nend\n",
                          1.,
                          "    set Load factor = t^2\n"),
      "activation_of_two_times");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 5u);
    // Row 0 is the initial state, straight, not an equilibrium.
    for (std::size_t i = 1; i < run.rows.size(); ++i)
      {
        const std::vector<double>  &row   = run.rows[i];
        const double                t     = row[0];
        const std::array<double, 2> exact = curve_end({{0.2, 0.},
                                                       {0.2, 2 * t + 3 * t * t},
                                                       {0.2, 1 + t},
                                                       {0.2, 1 - t},
                                                       {0.2, 0.}});
        EXPECT_NEAR(row[probe_column(run, "x")], exact[0], 1e-5) << "t = " << t;
        EXPECT_NEAR(row[probe_column(run, "y")], exact[1], 1e-5) << "t = " << t;
      }
  }

  TEST(ActivationFields, ContinuationRampsTheCurvature)
  {
    // Ramped fields follow the load factor, continuation's parameter: the
    // free end reaches the arc of curvature 2 lambda at lambda = 0.5 (an
    // output point) and 1 (the end of the range); 320 segments (1.3e-5 of
    // tip error at 80).
    std::string scene =
      rod_scene(320,
                "subsection Group all\n  set Natural curvature = 2, 0 on "
                "0.2 to 0.6\nend\n"
                "subsection Solver\n  set Method = continuation\n"
                "  subsection Continuation\n"
                "    set Load factor range = -0.1, 1\n"
                "    set Output load factors = 0.5\n  end\nend\n");
    scene.erase(scene.find("subsection Loads"), 37);
    const RunSummary run = run_scene_text(scene, "activation_continuation");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    for (const double lambda : {0.5, 1.})
      {
        const auto row =
          std::find_if(run.rows.begin(), run.rows.end(), [&](const auto &r) {
            return std::abs(r[0] - lambda) < 1e-12;
          });
        ASSERT_NE(row, run.rows.end()) << lambda;
        const std::array<double, 2> exact =
          curve_end({{0.2, 0.}, {0.4, 2 * lambda}, {0.4, 0.}});
        EXPECT_NEAR((*row)[probe_column(run, "x")], exact[0], 2e-6) << lambda;
        EXPECT_NEAR((*row)[probe_column(run, "y")], exact[1], 2e-6) << lambda;
      }
  }

  TEST(ActivationFields, ClothoidOfAnExpression)
  {
    // Tangent angle k s^2 / (2 L), k = 3, L = 1: Simpson's rule on 2000
    // intervals (error about 1e-14) for the exact tip.
    const double          k = 3.;
    const unsigned int    m = 2000;
    std::array<double, 2> exact{{0., 0.}};
    for (unsigned int i = 0; i <= m; ++i)
      {
        const double s = double(i) / m, w = (i == 0 || i == m ? 1. :
                                             i % 2            ? 4. :
                                                                2.) /
                                            (3. * m);
        exact[0] += w * std::cos(0.5 * k * s * s);
        exact[1] += w * std::sin(0.5 * k * s * s);
      }
    expect_second_order(
      "subsection Group all\n  set Natural curvature = 3*s/L, 0\nend\n",
      exact,
      5e-6); // 3.6e-6 measured
  }

  /// The tip of the rod from the origin along e_x, d1 = e_z, of natural
  /// curvature @p kappa1 about d1 and twist rate tau(s): the Kirchhoff
  /// frame equations d_i' = Omega x d_i, x' = d3 with
  /// Omega = kappa1 d1 + tau d3, by RK4 in 20000 steps.
  Eigen::Vector3d
  kirchhoff_tip(const double kappa1, const std::function<double(double)> &tau)
  {
    using State     = Eigen::Matrix<double, 12, 1>; // x, d1, d2, d3
    const auto rate = [&](const double s, const State &y) {
      const Eigen::Vector3d omega =
        kappa1 * y.segment<3>(3) + tau(s) * y.segment<3>(9);
      State dy;
      dy.segment<3>(0) = y.segment<3>(9);
      for (unsigned int i = 1; i < 4; ++i)
        dy.segment<3>(3 * i) = omega.cross(y.segment<3>(3 * i));
      return dy;
    };
    State y;
    y << 0, 0, 0, 0, 0, 1, 0, -1, 0, 1, 0, 0;
    const unsigned int m = 20000;
    const double       h = 1. / m;
    for (unsigned int i = 0; i < m; ++i)
      {
        const double s  = i * h;
        const State  k1 = rate(s, y), k2 = rate(s + h / 2, y + h / 2 * k1),
                    k3 = rate(s + h / 2, y + h / 2 * k2),
                    k4 = rate(s + h, y + h * k3);
        y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      }
    return y.head<3>();
  }

  TEST(ActivationFields, TwistAndCurvatureFromAMidpointClamp)
  {
    // Curvature 2 about d1 along the whole rod and the twist rate
    // 3 sin(pi s / L): a twisted arc out of the plane. The curvature
    // reaches the clamped start: the clamp at the first segment's midpoint
    // holds the tangent there, and the arc length starts at the clamp, half
    // a segment past the first vertex.
    const Eigen::Vector3d exact =
      kirchhoff_tip(2., [](const double s) { return 3 * std::sin(M_PI * s); });
    std::vector<double> errors;
    for (const unsigned int n : {20u, 80u, 320u})
      {
        std::string scene =
          rod_scene(n,
                    "subsection Group all\n  set Natural curvature = 2, 0\n"
                    "  set Natural twist = 3*sin(pi*s/L)\nend\n");
        scene.insert(scene.find("  set Segments"),
                     "  set Clamp at first segment midpoint = true\n");
        scene.replace(scene.find("y: position end y"),
                      17,
                      "y: position end y; z: position end z");
        const RunSummary run = run_scene_text(scene, "activation_twist");
        ASSERT_TRUE(run.failure.empty()) << run.failure;
        const std::vector<double> &last = run.rows.back();
        errors.push_back((Eigen::Vector3d(last[probe_column(run, "x")],
                                          last[probe_column(run, "y")],
                                          last[probe_column(run, "z")]) -
                          exact)
                           .norm());
        std::cout << n << " segments: tip error " << errors.back() << "\n";
      }
    for (std::size_t i = 1; i < errors.size(); ++i)
      EXPECT_GT(std::log(errors[i - 1] / errors[i]) / std::log(4.), 1.9);
    EXPECT_LT(errors.back(), 1e-5); // 5.6e-6 measured
  }

  TEST(ActivationFields, ItemsOfOneGroupAdd)
  {
    // 1 on [0.2, 0.6] and 1 on [0.4, 0.8]: 1, 2, 1 on three pieces.
    expect_second_order(
      "subsection Group all\n  set Natural curvature = 1, 0 on 0.2 to 0.6; "
      "1, 0 on 0.4 to 0.8\nend\n",
      curve_end({{0.2, 0.}, {0.2, 1.}, {0.2, 2.}, {0.2, 1.}, {0.2, 0.}}),
      1e-6); // 5.0e-7 measured
  }

  TEST(ActivationFields, GroupsOfOneBeamAdd)
  {
    // A beam clamped at the node "clamp", in group "bent" and in "all":
    // 1 along it and 0.5 within 0.3 of its ends, 1.5, 1, 1.5.
    const std::string network =
      std::filesystem::absolute("activation_beam.net").string();
    std::ofstream(network) << "node clamp 0 0 0 clamped\nnode tip 1 0 0\n"
                              "beam clamp tip group bent d1 0 0 1\n";
    expect_second_order(
      "subsection Group all\n  set Natural curvature = 1, 0\nend\n"
      "subsection Group bent\n  set Natural curvature = 0.5, 0 on near ends "
      "0.3\nend\n",
      curve_end({{0.3, 1.5}, {0.4, 1.}, {0.3, 1.5}}),
      1.2e-6, // 7.4e-7 measured
      network);
  }

  TEST(ActivationFields, EigenstrainColumnDrivenByItsField)
  {
    // scenes/eigenstrain_column.prm (continuation, Lestringant & Kochmann
    // Fig. 8c) with its eigenstrain an activation field of "Group all"
    // instead of the material's, ramped by the continuation parameter: the
    // bifurcation at e_cr = pi^2 I / (A L^2) and the table's midspan
    // deflections over L (1 + e0) at e0 / e_cr = 2, 5, 10
    // (../shared/VALIDATION.md), to the tolerances of
    // validation/eigenstrain_column at 200 segments.
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/eigenstrain_column.prm");
    std::stringstream text;
    text << file.rdbuf();
    std::string scene = text.str();
    for (const std::string line :
         {"    set Axial eigenstrain = 0.0098696044010894\n",
          "  set Ramped natural shape = eigenstrain\n"})
      {
        const std::size_t at = scene.find(line);
        ASSERT_NE(at, std::string::npos) << line;
        scene.erase(at, line.size());
      }
    scene.replace(scene.find("set Segments = 100"), 18, "set Segments = 200");
    scene += "subsection Group all\n  set Axial eigenstrain = "
             "0.0098696044010894\nend\n";
    const RunSummary run = run_scene_text(scene, "activation_column");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double critical = M_PI * M_PI * 1e-4, e0 = 10 * critical;
    EXPECT_NEAR(run.critical_load_factor * 10, 1.0, 1e-4);
    const std::size_t w = probe_column(run, "w_mid");
    for (const auto &[ratio, expected] :
         {std::pair{2.0, 0.019979}, {5.0, 0.039862}, {10.0, 0.059556}})
      {
        const auto row =
          std::find_if(run.rows.begin(), run.rows.end(), [&](const auto &r) {
            return std::abs(r[0] - ratio * critical / e0) < 1e-12;
          });
        ASSERT_NE(row, run.rows.end()) << ratio;
        EXPECT_NEAR(std::abs((*row)[w]) / (1 + ratio * critical) / expected,
                    1.0,
                    2e-4)
          << ratio;
      }
  }
} // namespace
