// A straight bar clamped at its start with its end moved: the small model
// of the solver tests.
#ifndef RODNET_TESTS_COMMON_HELD_BAR_H
#define RODNET_TESTS_COMMON_HELD_BAR_H

#include <core/rod_model.h>
#include <geometry/rod_generators.h>

#include <memory>
#include <vector>

namespace rodnet::testing
{
  /// A straight bar from the origin to e_x of @p n segments, clamped at
  /// its start, its end moved by @p end_displacement at load factor 1.
  inline std::unique_ptr<RodModel>
  held_bar(const std::shared_ptr<const RodMaterial> &material,
           const unsigned int                        n,
           const Vector3                            &end_displacement)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          n),
                     false,
                     Vector3::UnitY(),
                     "simple");
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{material});
    model->clamp_end("left", 0, true);
    model->fix_components("right", n, {{true, true, true}}, end_displacement);
    model->finalize();
    return model;
  }
} // namespace rodnet::testing

#endif
