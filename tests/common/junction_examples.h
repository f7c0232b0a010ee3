// The two junction examples of Lestringant & Kochmann (section 3, Fig. 3),
// with their stiffnesses and supports, for the junction validation
// (tests/validation/junctions.cc) and the mesh convergence study
// (bench/junction_convergence.cc). Each model is returned with its load at
// load factor 1, not finalized.
#ifndef RODNET_TESTS_COMMON_JUNCTION_EXAMPLES_H
#define RODNET_TESTS_COMMON_JUNCTION_EXAMPLES_H

#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <cmath>
#include <memory>
#include <string>

namespace rodnet::testing
{
  /// A linear elastic rod with EI1 = EI2 = @p EI.
  inline std::shared_ptr<const RodMaterial>
  isotropic_elastic_rod(const double EA, const double EI, const double GJ)
  {
    return std::make_shared<LinearElasticRod>(RodStiffness{EA, EI, EI, GJ});
  }

  /// The frame of Fig. 3a with @p n segments per leg and the hinge kernel
  /// @p kernel: legs of length 1 along x and then y in the plane z = 0,
  /// clamped at the origin (junction "clamp"), welded at the corner; EI = 1,
  /// mu J = 2/3, A L^2/I = 400. Its tip is moved out of plane by u_z = @p uz
  /// (the support "tip").
  inline std::unique_ptr<RodModel>
  fig3a_frame(const std::string &kernel, const unsigned int n, const double uz)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          n),
                     false,
                     Vector3::UnitZ(),
                     kernel);
    network->add_rod(generators::straight(Vector3(1, 0, 0),
                                          Vector3(1, 1, 0),
                                          n),
                     false,
                     Vector3::UnitZ(),
                     kernel);
    network->add_junction("clamp", JunctionKind::clamped, {{0, true}});
    network->add_junction("corner",
                          JunctionKind::welded,
                          {{0, false}, {1, true}});
    const auto material = isotropic_elastic_rod(400, 1, 2.0 / 3);
    auto       model    = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{material, material});
    const unsigned int tip = model->network().rods()[1].vertices.back();
    model->fix_components("tip",
                          tip,
                          {{false, false, true}},
                          Vector3(0, 0, uz));
    return model;
  }

  /// The windmill of fig3b_windmill() and the junction at its top.
  struct Fig3bWindmill
  {
    std::unique_ptr<RodModel> model;
    unsigned int              top;
  };

  /// The windmill of Fig. 3b with @p n segments per blade, 2n on the shaft,
  /// and the hinge kernel @p kernel: shaft of length 1 along z, three blades
  /// of length 1/2 at 120 degrees in the plane z = 0, welded at the hub,
  /// blade tips pinned, shaft top clamped and turned by @p twist about e_z.
  /// I = 1, E = 1, mu = E/3: shaft J = 200 I, A L_a^2/I = 400; blades
  /// J = I, A L_b^2/I = 100.
  inline Fig3bWindmill
  fig3b_windmill(const std::string &kernel,
                 const unsigned int n,
                 const double       twist)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(0, 0, 1),
                                          2 * n),
                     false,
                     Vector3::UnitX(),
                     kernel);
    for (const double degrees : {90.0, 210.0, 330.0})
      {
        const double angle = degrees * M_PI / 180;
        network->add_rod(generators::straight(
                           Vector3(0, 0, 0),
                           0.5 * Vector3(std::cos(angle), std::sin(angle), 0),
                           n),
                         false,
                         Vector3::UnitZ(),
                         kernel);
      }
    network->add_junction("hub",
                          JunctionKind::welded,
                          {{0, true}, {1, true}, {2, true}, {3, true}});
    const unsigned int top =
      network->add_junction("top", JunctionKind::clamped, {{0, false}});
    const auto blade = isotropic_elastic_rod(400, 1, 1.0 / 3);
    auto       model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
              isotropic_elastic_rod(400, 1, 200.0 / 3),
              blade,
              blade,
              blade});
    for (unsigned int b = 1; b <= 3; ++b)
      model->fix_components("blade" + std::to_string(b),
                            model->network().rods()[b].vertices.back(),
                            {{true, true, true}});
    model->prescribe_rotation(top, Vector3::UnitZ(), twist);
    return {std::move(model), top};
  }
} // namespace rodnet::testing

#endif
