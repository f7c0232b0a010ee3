#ifndef RODNET_TESTS_COMMON_BENT_DR_NETWORK_H
#define RODNET_TESTS_COMMON_BENT_DR_NETWORK_H

#include <core/dr_model.h>
#include <geometry/rod_generators.h>

#include <memory>
#include <vector>

namespace rodnet::testing
{
  /**
   * A bent network of four rods of three elements for the dynamic-relaxation
   * element, with all it has: a welded junction of three rods, a pinned one
   * of two, a clamped end (an anchor), a roller whose height moves with the
   * load factor, a point force and a distributed force. Its processes are
   * those of @p communicator.
   */
  inline std::unique_ptr<DrModel>
  bent_dr_network(const MPI_Comm communicator = MPI_COMM_WORLD)
  {
    auto          owned   = std::make_unique<RodNetwork>();
    RodNetwork   &network = *owned; // owned by the model from its construction
    const Vector3 hint(0.1, 0.2, 1);
    const auto    add = [&](const Vector3 &a, const Vector3 &b) {
      network.add_rod(generators::straight(a, b, 3), false, hint, "simple");
    };
    add(Vector3(0, 0, 0), Vector3(1, 0, 0));
    add(Vector3(1, 0, 0), Vector3(1, 1, 0.3));
    add(Vector3(1, 0, 0), Vector3(2, -0.2, 0.1));
    add(Vector3(1, 1, 0.3), Vector3(2, 1, 0.3));
    network.add_junction("weld",
                         JunctionKind::welded,
                         {{0, false}, {1, true}, {2, true}});
    network.add_junction("pin", JunctionKind::pinned, {{1, false}, {3, true}});
    auto model = std::make_unique<DrModel>(
      std::move(owned),
      std::vector<RodStiffness>(4, RodStiffness{10, 1, 2, 0.7}),
      communicator);
    model->clamp_end("clamp", 0, true);
    model->fix_components("roller",
                          network.rods()[3].vertices.back(),
                          {{false, false, true}},
                          Vector3(0, 0, 0.1));
    model->add_point_force(network.named_vertex("pin"),
                           Vector3(0.3, -0.2, 0.5));
    model->add_distributed_force(2, Vector3(0, 0.4, -0.1));
    model->finalize();
    return model;
  }
} // namespace rodnet::testing

#endif
