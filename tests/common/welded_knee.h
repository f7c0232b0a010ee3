// A small network of the assembly tests: two rods welded at a knee and a
// third rod of one segment far from them.
#ifndef RODNET_TESTS_COMMON_WELDED_KNEE_H
#define RODNET_TESTS_COMMON_WELDED_KNEE_H

#include <core/rod_model.h>
#include <materials/linear_elastic_rod.h>

#include <memory>

namespace rodnet::testing
{
  /// Rod 0: (0,0,0)-(1,0,0)-(3,0,0); rod 1: (3,0,0)-(3,2,0)-(3,2.5,0),
  /// welded to rod 0 at (3,0,0) (junction "knee"); rod 2 far away:
  /// (0,5,0)-(1,5,0). All of EA = 100, EI1 = 2, EI2 = 3, GJ = 1.5.
  inline std::unique_ptr<RodModel>
  welded_knee_model()
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod({Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(3, 0, 0)},
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->add_rod({Vector3(3, 0, 0), Vector3(3, 2, 0), Vector3(3, 2.5, 0)},
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->add_rod({Vector3(0, 5, 0), Vector3(1, 5, 0)},
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->add_junction("knee",
                          JunctionKind::welded,
                          {{0, false}, {1, true}});
    auto material =
      std::make_shared<LinearElasticRod>(RodStiffness{100, 2, 3, 1.5});
    return std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>(3, material));
  }
} // namespace rodnet::testing

#endif
