// A beam on an elastic foundation (VALIDATION.md, Hetenyi 1946): a long
// rod (beta L = 30) clamped at both ends on a Winkler foundation of modulus
// k under a point load P at its middle. Reference: the infinite beam,
// deflection w0 = P beta / (2 k) under the load, beta = (k / (4 EI))^(1/4),
// and the profile w0 exp(-beta x)(cos beta x + sin beta x); the clamps,
// 15 / beta away, change them by exp(-15) = 3e-7. The load is small, so
// the rod stays linear (w0 / L = 4e-9). With springs along z only, a load
// along y meets no foundation: the clamped-clamped beam, P l^3 / (192 EI).
// A stiff ring on the foundation alone, without supports, is held by it and
// tilts as a rigid body.
#include <common/solve_model.h>
#include <core/rod_model.h>
#include <families/elastic_foundation.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  const double EI = 1, EA = 100, GJ = 0.8;
  const double beta = 1, k = 4 * EI * std::pow(beta, 4), L = 30 / beta;
  const double P = 1e-6, w0 = P * beta / (2 * k);

  /// Displacements of the vertices of the rod from -L/2 to L/2 in @p n
  /// segments (n even), springs along @p direction (none: all), load
  /// @p load at the middle vertex.
  std::vector<Vector3>
  deflections(const unsigned int            n,
              const std::optional<Vector3> &direction,
              const Vector3                &load)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(-L / 2, 0, 0),
                                          Vector3(L / 2, 0, 0),
                                          n),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(
                     RodStiffness{EA, EI, EI, GJ})});
    model.clamp_end("start", 0, true);
    model.clamp_end("end", 0, false);
    const std::vector<unsigned int> &vertices =
      model.network().rods()[0].vertices;
    model.add_point_force(vertices[n / 2], load);
    model.add_element_family(std::make_unique<ElasticFoundation>(
      model.network(),
      model.layout(),
      ElasticFoundationParameters{k, direction, {}}));
    const VectorType     u = solve(model, 1);
    std::vector<Vector3> result;
    for (const unsigned int v : vertices)
      {
        Vector3 d;
        for (unsigned int c = 0; c < 3; ++c)
          d[c] = u[model.layout().vertex_dof(v, c)];
        result.push_back(d);
      }
    return result;
  }

  // w(0) / w0 - 1 = 9.8e-3, 2.5e-3, 6.2e-4 at beta h = 0.2, 0.1, 0.05
  // (about (beta h)^2 / 4): second order, and the Richardson extrapolation
  // from the last two is within 2.4e-6 of w0.
  TEST(ElasticFoundation, DeflectionUnderTheLoadConvergesToHetenyi)
  {
    std::vector<double> error;
    for (const unsigned int n : {150u, 300u, 600u})
      {
        const double w = deflections(n, {}, Vector3(0, 0, -P))[n / 2][2];
        error.push_back(-w / w0 - 1);
        std::cout << "beta h = " << beta * L / n
                  << ": w(0) / w0 - 1 = " << error.back() << std::endl;
      }
    EXPECT_LT(std::abs(error[2]), 1e-3);
    const double order = std::log2(error[1] / error[2]);
    EXPECT_NEAR(order, 2, 0.1);
    EXPECT_LT(std::abs((4 * error[2] - error[1]) / 3), 1e-5);
  }

  // The profile at beta x = 1, 2, 3 within 2e-4 w0 at beta h = 0.05.
  TEST(ElasticFoundation, ProfileDecaysAsHetenyi)
  {
    const unsigned int         n = 600;
    const std::vector<Vector3> w = deflections(n, {}, Vector3(0, 0, -P));
    for (const unsigned int bx : {1u, 2u, 3u})
      {
        const double x     = bx / beta;
        const double exact = w0 * std::exp(-beta * x) *
                             (std::cos(beta * x) + std::sin(beta * x));
        const unsigned int i = n / 2 + static_cast<unsigned int>(
                                         std::lround(x / (L / n)));
        EXPECT_NEAR(-w[i][2] / w0, exact / w0, 2e-4) << "beta x = " << bx;
      }
  }

  // Springs along z: the z deflection is the foundation's (as with springs
  // in every direction), the y deflection the bare clamped-clamped beam's.
  // A clamp holds the end segment, which clamps the bending at its midpoint
  // (the end hinge sits at its inner vertex, with half a segment of
  // Voronoi length outside it): the span is l = L - h. Measured 5.5e-6 off.
  TEST(ElasticFoundation, SpringsAlongOneDirectionOnly)
  {
    const unsigned int   n = 600;
    const Vector3        load(0, P, -P);
    const auto           along_z = deflections(n, Vector3::UnitZ(), load);
    const auto           all     = deflections(n, {}, Vector3(0, 0, -P));
    const double         span    = L - L / n;
    const double         beam    = P * std::pow(span, 3) / (192 * EI);
    std::cout << "along z: w_y(0) / (P l^3 / 192 EI) - 1 = "
              << along_z[n / 2][1] / beam - 1 << std::endl;
    EXPECT_NEAR(along_z[n / 2][2], all[n / 2][2], 1e-6 * w0);
    EXPECT_NEAR(along_z[n / 2][1] / beam, 1, 1e-4);
    EXPECT_NEAR(along_z[n / 2][0], 0, 1e-6 * w0);
  }

  // A stiff ring (k R^4 / EI = 4e-6) on springs in every direction and no
  // support: the foundation alone holds it (describe_free_motions(), which
  // StaticSolver asks first). A force F normal to its plane at vertex 0
  // moves it as a rigid body: it translates by F / (k L) and tilts about
  // the diameter normal to that vertex by F R / (k R^2 L / 2), with L =
  // 2 n R sin(pi / n) the length the springs are lumped over (the sum of
  // the chords; the tilt's sum of k l_v (R cos phi_v)^2 is k R^2 L / 2).
  // Vertex 0 rises by 3 F / (k L), the opposite vertex sinks by F / (k L).
  TEST(ElasticFoundation, RingOnTheFoundationAloneTiltsRigidly)
  {
    const unsigned int n      = 64;
    const double       radius = 1, force = 1e-3;
    auto               network = std::make_unique<RodNetwork>();
    network->add_rod(generators::ring(Vector3::Zero(),
                                      radius,
                                      Vector3::UnitX(),
                                      Vector3::UnitY(),
                                      n),
                     true,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(
                     RodStiffness{1e8, 1e6, 1e6, 1e6})});
    model.add_point_force(0, Vector3(0, 0, force));
    model.add_element_family(std::make_unique<ElasticFoundation>(
      model.network(),
      model.layout(),
      ElasticFoundationParameters{k, std::nullopt, {}}));
    const VectorType u      = solve(model, 1);
    const double     length = 2 * n * radius * std::sin(M_PI / n);
    const double     lift   = force / (k * length);
    EXPECT_NEAR(u[model.layout().vertex_dof(0, 2)] / (3 * lift), 1, 1e-4);
    EXPECT_NEAR(u[model.layout().vertex_dof(n / 2, 2)] / -lift, 1, 1e-4);
  }
} // namespace
