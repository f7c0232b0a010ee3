// Supports that do what they say (issue 11): a clamp moves rigidly with
// its end vertex and turns about it, and moments and prescribed rotations
// act at any vertex through rotation handles, without stub beams. The
// references are beam theory: a uniform stretch EA d/L, the guided
// clamped-clamped beam 12 EI d/L^3, pure bending EI theta/L and torsion
// GJ phi/L, the circle of radius EI/M that an end moment rolls a
// cantilever into, and the piecewise circular shape under a moment inside.
#include <common/run_scene_text.h>
#include <common/scene_text.h>
#include <common/solve_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  const double EA = 100, EI = 1, GJ = 0.5;

  /// A rod along x through @p points (d1 = e_z, kernel @p kernel) with
  /// both ends clamped, called "start" and "end".
  std::unique_ptr<RodModel>
  clamped_clamped(const std::vector<Vector3> &points, const std::string &kernel)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(points, false, Vector3::UnitZ(), kernel);
    network->create_triangulation();
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
        std::make_shared<LinearElasticRod>(RodStiffness{EA, EI, EI, GJ})});
    model->clamp_end("start", 0, true);
    model->clamp_end("end", 0, false);
    return model;
  }

  class Supports : public ::testing::TestWithParam<std::string>
  {
  };

  // The clamps hold vertices (0, 1) and (n + 1, n + 2); the inner ones sit
  // at x = 0 and x = L. The end clamp pulled by d along the rod moves as a
  // whole: its segment keeps its length, and the n segments between the
  // clamps share the stretch, strain d/L, reaction EA d/L.
  TEST_P(Supports, ClampPulledAlongTheRodStretchesUniformly)
  {
    const unsigned int n = 10;
    const double       L = 1, h = L / n, d = 0.01;
    auto       model = clamped_clamped(generators::straight(Vector3(-h, 0, 0),
                                                      Vector3(L + h, 0, 0),
                                                      n + 2),
                                 GetParam());
    const Rod &rod   = model->network().rods()[0];
    model->fix_components("pull",
                          rod.vertices.back(),
                          {{true, false, false}},
                          Vector3(d, 0, 0));
    const VectorType u = solve(*model, 1);
    for (unsigned int j = 0; j < rod.segments.size(); ++j)
      {
        const double length =
          (model->configuration().position(u, rod.vertices[j + 1]) -
           model->configuration().position(u, rod.vertices[j]))
            .norm();
        const bool   clamped = j == 0 || j + 1 == rod.segments.size();
        const double strain  = length / h - 1;
        EXPECT_NEAR(strain, clamped ? 0 : d / L, 1e-10) << "segment " << j;
      }
    const double force = model->reaction(model->support("end"), u, 1)[0];
    std::cout << GetParam() << ": clamp pulled by " << d << ": reaction "
              << force << ", EA d/L " << EA * d / L << std::endl;
    EXPECT_NEAR(force, EA * d / L, 1e-8 * EA * d / L);
    EXPECT_NEAR(model->reaction(model->support("start"), u, 1)[0],
                -EA * d / L,
                1e-8 * EA * d / L);
  }

  // The clamps act at the midpoints of their segments, here x = 0 and
  // x = L. The end clamp moved by d across the rod keeps its tangent: the
  // guided beam, shear force 12 EI d / L^3.
  TEST_P(Supports, ClampMovedAcrossTheRodIsAGuidedBeam)
  {
    const unsigned int n = 40;
    const double       L = 1, h = L / n, d = 1e-4;
    auto model = clamped_clamped(generators::straight(Vector3(-h / 2, 0, 0),
                                                      Vector3(L + h / 2, 0, 0),
                                                      n + 1),
                                 GetParam());
    model->fix_components("move",
                          model->network().rods()[0].vertices.back(),
                          {{false, true, false}},
                          Vector3(0, d, 0));
    const VectorType u      = solve(*model, 1);
    const double     force  = model->reaction(model->support("end"), u, 1)[1];
    const double     theory = 12 * EI * d / std::pow(L, 3);
    std::cout << GetParam() << ": clamp moved across by " << d
              << ": shear force " << force << ", 12 EI d/L^3 " << theory
              << std::endl;
    EXPECT_NEAR(force, theory, 2e-3 * theory);
  }

  // Clamps at x = 0 and x = L as above; the end clamp turned by theta
  // about e_z and moved to where a regular polygon of n equal turns
  // alpha = theta/n puts its end vertex: the discrete pure bending
  // equilibrium, the circular arc of radius L/theta. The clamps carry the
  // end moments +-EI theta/L and no force; the discrete curvature differs
  // from alpha/h by O(alpha^2), 3.3e-4 at most here.
  TEST_P(Supports, ClampTurnedIntoACircularArc)
  {
    const unsigned int n = 100;
    const double       L = 1, h = L / n;
    for (const double theta : {M_PI / 2, M_PI})
      {
        const auto points = generators::straight(Vector3(-h / 2, 0, 0),
                                                 Vector3(L + h / 2, 0, 0),
                                                 n + 1);
        auto       model  = clamped_clamped(points, GetParam());
        // Segment k of the polygon points at angle k alpha.
        Vector3 end = points.front();
        for (unsigned int k = 0; k <= n; ++k)
          end +=
            h * Vector3(std::cos(k * theta / n), std::sin(k * theta / n), 0);
        model->fix_components("move",
                              model->network().rods()[0].vertices.back(),
                              {{true, true, true}},
                              end - points.back());
        model->rotate_clamp("end", Vector3::UnitZ(), theta);
        const VectorType u = solve(*model, 10);
        const Vector3    moment =
          model->reaction_moment(model->support("end"), u, 1);
        const Vector3 force  = model->reaction(model->support("end"), u, 1);
        const double  theory = EI * theta / L;
        std::cout << GetParam() << ": clamp turned by " << theta
                  << ": end moment " << moment.transpose() << ", EI theta/L "
                  << theory << ", force " << force.transpose() << std::endl;
        EXPECT_NEAR(moment[2], theory, 1e-3 * theory);
        EXPECT_NEAR(moment.head<2>().norm(), 0, 1e-9);
        EXPECT_NEAR(force.norm(), 0, 1e-6 * EI / (L * L));
        EXPECT_NEAR(model->reaction_moment(model->support("start"), u, 1)[2],
                    -theory,
                    1e-3 * theory);
      }
  }

  /// The scene of a straight rod of length 1 along x, @p segments
  /// segments, the clamp at the first segment's midpoint if
  /// @p midpoint_clamp, the rigidities above, clamped at its start, with
  /// the further entries @p supports of subsection Supports, @p loads of
  /// subsection Loads, and @p probes; run silently.
  RunSummary
  run_rod(const std::string &kernel,
          const unsigned int segments,
          const bool         midpoint_clamp,
          const std::string &supports,
          const std::string &loads,
          const std::string &probes)
  {
    return run_scene_text("subsection Geometry\n"
                          "  set Segments = " +
                            std::to_string(segments) +
                            "\n"
                            "  set Clamp at first segment midpoint = " +
                            (midpoint_clamp ? "true" : "false") +
                            "\n"
                            "  set Director d1 = 0, 0, 1\n"
                            "  set Hinge kernel = " +
                            kernel + "\nend\n" +
                            direct_material(EA, EI, EI, GJ) +
                            "subsection Supports\n"
                            "  set Clamped ends = start\n" +
                            supports + "end\nsubsection Loads\n" + loads +
                            "end\n" + probes_only(probes),
                          "out_supports_" + kernel);
  }

  /// The value of probe @p name at the last step of @p run.
  double
  last(const RunSummary &run, const std::string &name)
  {
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    return run.rows.back()[probe_column(run, name)];
  }

  // A scene clamps both ends and turns the end clamp by phi = 1 rad about
  // the rod: the n - 1 hinges between the clamped segments, Voronoi length
  // (n - 1) h together, twist by tau = phi/(n - 1) each; the torque is
  // GJ phi/((n - 1) h). The classic twist measure is the angle tau, the
  // simple one agrees with it to O(tau^2). The end is clamped twice and
  // pinned too, which holds nothing at another value and is accepted.
  TEST_P(Supports, SceneClampTurnedAboutTheRodTwistsIt)
  {
    const unsigned int n   = 20;
    const double       tau = 1.0 / (n - 1);
    const RunSummary   run =
      run_rod(GetParam(),
              n,
              false,
              "  set Clamped ends = start, end, 0:end\n"
              "  set Pinned vertices = end\n"
              "  set Prescribed rotations = end: 1,0,0 57.29577951308232\n",
              "  set Steps = 4\n",
              "torque: moment end x; far: moment start x; tip_y: position "
              "end y");
    const double theory = GJ * 1.0 / ((n - 1) * (1.0 / n));
    std::cout << GetParam() << ": torque " << last(run, "torque")
              << ", GJ phi/L " << theory << std::endl;
    EXPECT_NEAR(last(run, "torque"), theory, tau * tau * theory);
    EXPECT_NEAR(last(run, "far"), -theory, tau * tau * theory);
    EXPECT_NEAR(last(run, "tip_y"), 0, 1e-12);
  }

  // The same clamp turned by a whole turn, and by 240 degrees, in ONE
  // load step. The clamp's frame alone cannot tell a turn of 360 degrees
  // from none, nor 240 from -120: the step is halved until each part
  // turns by less than half a turn (RodModel::check_rotation_step()), and
  // the torque is that of the whole turn, GJ phi/((n - 1) h) to O(tau^2)
  // as above, and that of the same scene in 4 steps to rounding. A turn
  // no step the solver may take can follow fails, naming the clamp.
  TEST_P(Supports, SceneClampTurnedByMoreThanHalfATurnInOneStep)
  {
    const unsigned int n = 20;
    const auto twist     = [&](const double degrees, const unsigned int steps) {
      return run_rod(GetParam(),
                     n,
                     false,
                     "  set Clamped ends = start, end\n"
                         "  set Pinned vertices = end\n"
                         "  set Prescribed rotations = end: 1,0,0 " +
                       std::to_string(degrees) + "\n",
                     "  set Steps = " + std::to_string(steps) + "\n",
                     "torque: moment end x");
    };
    for (const double degrees : {360.0, 240.0})
      {
        const double phi    = degrees * M_PI / 180;
        const double tau    = phi / (n - 1);
        const double theory = GJ * phi / ((n - 1) * (1.0 / n));
        const double torque = last(twist(degrees, 1), "torque");
        std::cout << GetParam() << ": clamp turned by " << degrees
                  << " degrees in one load step: torque " << torque
                  << ", GJ phi/L " << theory << std::endl;
        EXPECT_NEAR(torque, theory, tau * tau * theory);
        EXPECT_NEAR(torque, last(twist(degrees, 4), "torque"), 1e-8 * theory);
      }
    const RunSummary too_far = twist(360000, 1);
    EXPECT_NE(too_far.failure.find("the prescribed rotation of the clamp "
                                   "\"Clamped ends: end\" turns by"),
              std::string::npos)
      << too_far.failure;
  }

  // A moment M = 2 pi EI/L at the free end of a cantilever (a rotation
  // handle there, no stub beam) rolls it into the circle of radius EI/M
  // centred at (0, EI/M): the tip comes back to the clamp.
  TEST_P(Supports, EndMomentRollsTheCantileverUp)
  {
    const double     R   = 1 / (2 * M_PI);
    const RunSummary run = run_rod(GetParam(),
                                   200,
                                   true,
                                   "",
                                   "  set Steps = 20\n"
                                   "  set Moments = end: 0,0,1 " +
                                     std::to_string(2 * M_PI) + "\n",
                                   "tip_x: position end x; tip_y: position "
                                   "end y; q_x: position 0:50 x; q_y: "
                                   "position 0:50 y");
    const Vector3    tip(last(run, "tip_x"), last(run, "tip_y"), 0);
    const Vector3    quarter(last(run, "q_x"), last(run, "q_y"), 0);
    std::cout << GetParam() << ": rolled-up tip " << tip.transpose()
              << ", vertex 50 at " << (quarter - Vector3(0, R, 0)).norm()
              << " from the centre, R = " << R << std::endl;
    EXPECT_LT(tip.norm(), 5e-4);
    EXPECT_NEAR((quarter - Vector3(0, R, 0)).norm(), R, 5e-4 * R);
  }

  // The same kind of moment at vertex 50 (arc length a = 49.5 h, with
  // M a/EI = pi/2) bends the part up to it into a quarter circle of radius
  // EI/M; beyond it the rod carries no moment and stays straight.
  TEST_P(Supports, InteriorMomentBendsThePartBeforeIt)
  {
    const double     h = 1 / 99.5, a = 49.5 * h, R = a / (M_PI / 2);
    const RunSummary run =
      run_rod(GetParam(),
              100,
              true,
              "",
              "  set Steps = 10\n"
              "  set Moments = 0:50: 0,0,1 " +
                std::to_string(1 / R) + "\n",
              "a_x: position 0:50 x; a_y: position 0:50 y; tip_x: position "
              "end x; tip_y: position end y");
    const Vector3 at_a(last(run, "a_x"), last(run, "a_y"), 0);
    const Vector3 tip(last(run, "tip_x"), last(run, "tip_y"), 0);
    const Vector3 exact_a(R, R, 0);
    const Vector3 exact_tip = exact_a + (1 - a) * Vector3::UnitY();
    std::cout << GetParam() << ": vertex 50 at " << at_a.transpose()
              << " (exact " << exact_a.transpose() << "), tip "
              << tip.transpose() << " (exact " << exact_tip.transpose() << ")"
              << std::endl;
    EXPECT_LT((at_a - exact_a).norm(), 5e-4);
    EXPECT_LT((tip - exact_tip).norm(), 5e-4);
  }

  // The free end of a cantilever turned by theta = 90 degrees (a handle
  // with a prescribed rotation, its position free) bends it into an arc
  // of radius L/theta under the end moment EI theta/L.
  TEST_P(Supports, PrescribedEndRotationBendsIntoAnArc)
  {
    const double     theta = M_PI / 2, R = 1 / theta;
    const RunSummary run =
      run_rod(GetParam(),
              100,
              true,
              "  set Prescribed rotations = end: 0,0,1 90\n",
              "  set Steps = 10\n",
              "m: moment end z; tip_x: position end x; tip_y: position end y");
    std::cout << GetParam() << ": end turned by 90 degrees: moment "
              << last(run, "m") << ", EI theta/L " << EI * theta << "; tip ("
              << last(run, "tip_x") << ", " << last(run, "tip_y")
              << "), exact (" << R << ", " << R << ")" << std::endl;
    EXPECT_NEAR(last(run, "m"), EI * theta, 5e-4 * EI * theta);
    EXPECT_NEAR(last(run, "tip_x"), R, 1e-4);
    EXPECT_NEAR(last(run, "tip_y"), R, 1e-4);
  }

  INSTANTIATE_TEST_SUITE_P(HingeKernels,
                           Supports,
                           ::testing::Values("simple", "classic"));
} // namespace
