// The Wunderlich ribbon (Korner et al. eq. 4.7) and its assembly: the
// law's gradient and Hessian in (kappa_1, eta, eta') against central
// finite differences, including eta' w near 0 (where the factor g switches
// from its series to atanh(x)/x) and kappa_1 near 0; the factor g against
// its closed form; and the assembled Lagrangian of developable rods (open,
// closed, closed with a half turn) against finite differences of the
// assembled energy and residual, at random states with random eta and
// multipliers, after a reference reset. The Hessian of the assembly carries
// the drag on eta (DevelopableRibbonFamily::drag()), which the test adds to
// the finite differences.
#include <common/assembled_derivatives.h>
#include <common/ribbon_dofs.h>
#include <core/rod_model.h>
#include <families/developable_ribbon_family.h>
#include <geometry/rod_generators.h>
#include <materials/wunderlich_ribbon.h>
#include <solvers/checks/dof_roles.h>

#include <gtest/gtest.h>
#include <random>

namespace
{
  using namespace rodnet;

  const RibbonConstants constants{2e9, 0.35, 0.1, 1e-3};

  TEST(WunderlichWidthFactor, MatchesItsClosedFormAndTheSeriesAtTheSwitch)
  {
    // g(x) = ln((1 + x) / (1 - x)) / (2 x), Korner eq. 4.7 with x = eta' w/2.
    for (const double x : {0.5, -0.7, 0.9, 0.26})
      EXPECT_NEAR(wunderlich_width_factor(x)[0],
                  std::log((1 + x) / (1 - x)) / (2 * x),
                  1e-15);
    // Series 1 + x^2/3 + x^4/5 at small x; g' = 2x/3, g'' = 2/3 at 0.
    EXPECT_NEAR(wunderlich_width_factor(1e-3)[0],
                1 + 1e-6 / 3 + 1e-12 / 5,
                1e-16);
    EXPECT_NEAR(wunderlich_width_factor(0)[1], 0, 1e-16);
    EXPECT_NEAR(wunderlich_width_factor(0)[2], 2. / 3, 1e-15);
    // Both sides of the switch at |x| = 0.25 agree.
    const Eigen::Vector3d below = wunderlich_width_factor(0.25 - 1e-12);
    const Eigen::Vector3d above = wunderlich_width_factor(0.25 + 1e-12);
    EXPECT_LT((below - above).norm(), 1e-10);
    EXPECT_THROW(wunderlich_width_factor(1.0), std::runtime_error);
  }

  TEST(WunderlichRibbonLaw, GradientAndHessianMatchFiniteDifferences)
  {
    const WunderlichRibbon ribbon(constants);
    const double           l = 0.02;
    // (kappa_1, eta, eta'): eta' w / 2 from 1e-9 to 0.9, kappa_1 down to
    // 1e-9.
    const std::vector<Eigen::Vector3d> points = {{0.05, 0.3, 1e-8},
                                                 {0.05, -0.4, 2.0},
                                                 {-0.03, 1.2, -4.9},
                                                 {1e-9, 0.7, 9.0},
                                                 {0.08, 0.0, 18.0},
                                                 {0.02, 2.0, 5.0}};
    for (const Eigen::Vector3d &z : points)
      {
        const auto   r     = ribbon.energy(z[0], z[1], z[2], l);
        double       err_g = 0, err_h = 0;
        const double scale = r.hessian.cwiseAbs().maxCoeff();
        for (int j = 0; j < 3; ++j)
          {
            const double    h  = 1e-6 * std::max(1e-3, std::abs(z[j]));
            Eigen::Vector3d zp = z, zm = z;
            zp[j] += h;
            zm[j] -= h;
            const auto rp = ribbon.energy(zp[0], zp[1], zp[2], l);
            const auto rm = ribbon.energy(zm[0], zm[1], zm[2], l);
            err_g         = std::max(err_g,
                             std::abs((rp.energy - rm.energy) / (2 * h) -
                                      r.gradient[j]) /
                               (r.gradient.cwiseAbs().maxCoeff() + 1e-300));
            err_h         = std::max(err_h,
                             ((rp.gradient - rm.gradient) / (2 * h) -
                              r.hessian.col(j))
                                 .cwiseAbs()
                                 .maxCoeff() /
                               scale);
          }
        EXPECT_LT(err_g, 1e-7) << z.transpose();
        EXPECT_LT(err_h, 1e-7) << z.transpose();
      }
    // The eta' w -> 0 limit: D w / (2 l) kappa_1^2 (1 + eta^2)^2.
    const double D = 2e9 * 1e-9 / (12 * (1 - 0.35 * 0.35));
    EXPECT_NEAR(ribbon.energy(0.05, 0.3, 0, l).energy,
                D * 0.1 / (2 * l) * 0.0025 * std::pow(1.09, 2),
                1e-15);
  }

  enum class Shape
  {
    open,
    closed,
    moebius,
    /// A Möbius ring with eta' partly coupled across its closure.
    moebius_partly_coupled
  };

  std::unique_ptr<RodModel>
  ribbon_model(const Shape shape, const double coupling = 0.4)
  {
    auto network = std::make_unique<RodNetwork>();
    if (shape == Shape::open)
      network->add_rod(generators::helix(0.5, 0.1, 0.5, 12),
                       false,
                       Vector3(0.3, 0.2, 1.0),
                       "simple",
                       NaturalShape::straight);
    else
      network->add_rod(generators::ring(Vector3::Zero(),
                                        0.5,
                                        Vector3::UnitX(),
                                        Vector3::UnitY(),
                                        10),
                       true,
                       Vector3::UnitZ(),
                       "simple",
                       NaturalShape::straight);
    network->create_triangulation();
    if (shape == Shape::moebius || shape == Shape::moebius_partly_coupled)
      network->set_frame_half_turns(0, 1);
    if (shape == Shape::moebius_partly_coupled)
      network->set_closure_coupling(0, coupling);
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
        std::make_shared<WunderlichRibbon>(constants)});
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           Vector3(0.1, -0.2, 0.3));
    model->finalize();
    return model;
  }

  class RibbonAssembly : public ::testing::TestWithParam<Shape>
  {
  };

  /// A state of @p model off its reference: small random displacements,
  /// random etas and multipliers (eta' w / 2 = 0.1 (eta_{i+1} - eta_{i-1})
  /// / l_v stays below 1).
  VectorType
  random_state(RodModel &model)
  {
    const DofLayout                       &layout = model.layout();
    VectorType                             u      = model.create_vector();
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> small(-0.02, 0.02);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = small(random);
    model.reset_reference(u);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] += small(random);
    for (unsigned int h = 0; h < layout.hinges().size(); ++h)
      for (unsigned int c = 0; c < 3; ++c)
        u[rodnet::testing::ribbon_dof(model, h, c)] = 0.2 * unit(random);
    return u;
  }

  TEST_P(RibbonAssembly, ResidualAndTangentMatchFiniteDifferences)
  {
    const auto       model  = ribbon_model(GetParam());
    const DofLayout &layout = model->layout();
    ASSERT_GT(rodnet::testing::declared_block(*model, "developable ribbons")
                .dofs.size(),
              0u);
    const VectorType u = random_state(*model);

    // The drag on each eta: factor D w / l_v.
    const double D =
      constants.young_modulus * std::pow(constants.thickness, 3) /
      (12 * (1 - constants.poisson_ratio * constants.poisson_ratio));
    std::vector<double> drag(u.size(), 0.0);
    for (unsigned int h = 0; h < layout.hinges().size(); ++h)
      drag[rodnet::testing::ribbon_dof(*model, h, 0)] =
        DevelopableRibbonFamily::drag_factor * D * constants.width /
        model->configuration().voronoi_length(h);

    const auto errors =
      rodnet::testing::assembled_derivative_errors(*model, u, 1.0, 1e-7, drag);
    std::cout << "shape " << static_cast<int>(GetParam()) << ": residual error "
              << errors.residual << ", tangent error " << errors.tangent
              << std::endl;
    EXPECT_LT(errors.residual, 1e-6);
    EXPECT_LT(errors.tangent, 1e-6);
  }

  INSTANTIATE_TEST_SUITE_P(DevelopableRods,
                           RibbonAssembly,
                           ::testing::Values(Shape::open,
                                             Shape::closed,
                                             Shape::moebius,
                                             Shape::moebius_partly_coupled));

  // With the closure uncoupled (Rod::closure_coupling = 0) no stencil ties
  // the etas on either side of the closure: the tangent entry between the
  // closing hinge's eta and the next hinge's vanishes exactly; coupled, it
  // does not (4.6e-4 of the diagonal entry in this small-strain state).
  TEST(RibbonClosureCoupling, UncoupledClosureTiesNoEtaAcrossIt)
  {
    for (const double coupling : {0.0, 1.0})
      {
        const auto model =
          ribbon_model(Shape::moebius_partly_coupled, coupling);
        const DofLayout &layout  = model->layout();
        unsigned int     closing = layout.hinges().size();
        for (unsigned int h = 0; h < layout.hinges().size(); ++h)
          if (model->configuration().closes_with_a_flip(layout.hinges()[h]))
            closing = h;
        ASSERT_LT(closing, layout.hinges().size());
        const unsigned int next_vertex = layout.hinges()[closing].vertices[2];
        unsigned int       next        = layout.hinges().size();
        for (unsigned int h = 0; h < layout.hinges().size(); ++h)
          if (layout.hinges()[h].vertices[1] == next_vertex)
            next = h;
        ASSERT_LT(next, layout.hinges().size());

        const VectorType u = random_state(*model);
        MatrixType       k;
        model->initialize_matrix(k);
        model->assemble(u, 1.0, nullptr, &k, false);
        const double across =
          std::abs(k.el(rodnet::testing::ribbon_dof(*model, closing, 0),
                        rodnet::testing::ribbon_dof(*model, next, 0)));
        const double own =
          std::abs(k.el(rodnet::testing::ribbon_dof(*model, closing, 0),
                        rodnet::testing::ribbon_dof(*model, closing, 0)));
        std::cout << "coupling " << coupling << ": across " << across
                  << ", own " << own << std::endl;
        if (coupling == 0)
          EXPECT_LT(across, 1e-14 * own);
        else
          EXPECT_GT(across, 1e-6 * own);
      }
  }

  TEST(RibbonClosureCoupling, RefusesAnOpenRodAndCouplingsOutsideTheRange)
  {
    RodNetwork network;
    network.add_rod(generators::helix(0.5, 0.1, 0.5, 6),
                    false,
                    Vector3::UnitX(),
                    "simple");
    network.add_rod(generators::ring(Vector3::Zero(),
                                     0.5,
                                     Vector3::UnitX(),
                                     Vector3::UnitY(),
                                     6),
                    true,
                    Vector3::UnitZ(),
                    "simple");
    EXPECT_THROW(network.set_closure_coupling(0, 0.5), std::invalid_argument);
    EXPECT_THROW(network.set_closure_coupling(1, 1.5), std::invalid_argument);
    EXPECT_THROW(network.set_closure_coupling(1, -0.1), std::invalid_argument);
    network.set_closure_coupling(1, 0.5);
    EXPECT_EQ(network.rods()[1].closure_coupling, 0.5);
  }

  TEST(RibbonLayout, OneSlopeAndTwoMultipliersPerHinge)
  {
    // 12 segments, 13 vertices, 11 hinges; 12 segment multipliers.
    const auto       model  = ribbon_model(Shape::open);
    const DofLayout &layout = model->layout();
    EXPECT_EQ(rodnet::testing::declared_block(*model, "developable ribbons")
                .dofs.size(),
              33u);
    EXPECT_EQ(
      rodnet::testing::declared_block(*model, "inextensibility").dofs.size(),
      12u);
    EXPECT_EQ(model->multiplier_dofs().size(), 12u + 22u);
    EXPECT_EQ(layout.n_dofs(), layout.n_field_dofs() + 12 + 33);
    // The blocks follow the positions and twists (no junction here): the
    // multipliers of the segments first, then the ribbon DoFs.
    EXPECT_EQ(rodnet::testing::declared_block(*model, "inextensibility").first,
              layout.n_field_dofs());
    EXPECT_EQ(
      rodnet::testing::declared_block(*model, "developable ribbons").first,
      layout.n_field_dofs() + 12);
    // Their roles and labels, as the solvers' messages give them.
    const DofRoles roles(*model);
    EXPECT_EQ(roles.kind(rodnet::testing::ribbon_dof(*model, 3, 0)),
              DofRoles::Kind::shape);
    EXPECT_EQ(roles.kind(rodnet::testing::ribbon_dof(*model, 3, 2)),
              DofRoles::Kind::multiplier);
    EXPECT_EQ(roles.describe(rodnet::testing::ribbon_dof(*model, 3, 0)),
              "rod 0 vertex 4 (its generatrix slope)");
    EXPECT_EQ(roles.describe(rodnet::testing::ribbon_dof(*model, 3, 1)),
              "rod 0 vertex 4 (its developability)");
    EXPECT_EQ(roles.describe(layout.n_field_dofs() + 5),
              "rod 0 segment 5 (its length)");
  }
} // namespace
