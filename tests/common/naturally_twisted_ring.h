// The naturally twisted ring of issue 33: an isotropic, naturally straight
// closed rod built as a circle, whose natural twist it cannot take.
#ifndef RODNET_TESTS_COMMON_NATURALLY_TWISTED_RING_H
#define RODNET_TESTS_COMMON_NATURALLY_TWISTED_RING_H

#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <memory>
#include <vector>

namespace rodnet::testing
{
  /// A circle of radius 1 in the xy-plane in @p n segments (d1 = e_z, no
  /// turn of the frame), naturally straight with the natural twist
  /// @p tau0, EI1 = EI2 = GJ = 1, EA = 1e7, its rigid motions held by six
  /// position components (vertex 0 in x, y, z, vertex n/2 in y and z,
  /// vertex n/4 in z), and the dead force @p force at vertex 3n/4.
  inline std::unique_ptr<RodModel>
  naturally_twisted_ring(const double       tau0,
                         const Vector3     &force = Vector3::Zero(),
                         const unsigned int n     = 100)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::ring(Vector3::Zero(),
                                      1.0,
                                      Vector3::UnitX(),
                                      Vector3::UnitY(),
                                      n),
                     true,
                     Vector3::UnitZ(),
                     "simple",
                     NaturalShape::straight);
    network->create_triangulation();
    RodNaturalShape natural;
    natural.twist = tau0;
    auto model    = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
           std::make_shared<LinearElasticRod>(RodStiffness{1e7, 1, 1, 1},
                                           natural)});
    const auto &v = model->network().rods()[0].vertices;
    model->fix_components("origin", v[0], {{true, true, true}});
    model->fix_components("opposite", v[n / 2], {{false, true, true}});
    model->fix_components("quarter", v[n / 4], {{false, false, true}});
    if (force.norm() > 0)
      model->add_point_force(v[3 * n / 4], force);
    model->finalize();
    return model;
  }
} // namespace rodnet::testing

#endif
