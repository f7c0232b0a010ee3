#ifndef RODNET_TESTS_ROD_MODELS_H
#define RODNET_TESTS_ROD_MODELS_H

#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/statics/static_solver.h>

#include <memory>

namespace rodnet::testing
{
  /// A network with one straight rod from @p start to @p end in @p n
  /// segments (d1 = e_z, the simple kernel), the chain started half a
  /// segment behind @p start where @p midpoint_clamp.
  inline std::unique_ptr<RodNetwork>
  straight_network(const unsigned int n,
                   const Vector3     &start          = Vector3(0, 0, 0),
                   const Vector3     &end            = Vector3(1, 0, 0),
                   const bool         midpoint_clamp = false)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(start, end, n, midpoint_clamp),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    return network;
  }

  /// The network of cantilever_with_handle() and its tip junction.
  struct CantileverWithHandle
  {
    std::unique_ptr<RodNetwork> network;
    unsigned int                tip;
  };

  /// A cantilever of length @p length along x in @p n segments, clamped at
  /// the origin (junction "clamp"), with a stub of @p stub_length in
  /// @p stub_segments welded at its tip (junction "tip") as a rotation
  /// handle; d1 = e_z, the simple kernel.
  inline CantileverWithHandle
  cantilever_with_handle(const double       length,
                         const unsigned int n,
                         const double       stub_length,
                         const unsigned int stub_segments)
  {
    const Vector3 tip(length, 0, 0);
    auto          network = straight_network(n, Vector3(0, 0, 0), tip);
    network->add_rod(generators::straight(tip,
                                          tip + Vector3(stub_length, 0, 0),
                                          stub_segments),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->add_junction("clamp", JunctionKind::clamped, {{0, true}});
    const unsigned int junction =
      network->add_junction("tip",
                            JunctionKind::welded,
                            {{0, false}, {1, true}});
    return {std::move(network), junction};
  }

  /// A RodModel of @p network whose rods all have the linear elastic
  /// rigidities @p stiffness, its vectors and matrices on @p communicator.
  inline std::unique_ptr<RodModel>
  elastic_model(std::unique_ptr<RodNetwork> network,
                const RodStiffness         &stiffness,
                const MPI_Comm              communicator = MPI_COMM_WORLD)
  {
    const std::size_t n_rods = network->rods().size();
    return std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>(
        n_rods,
        std::make_shared<LinearElasticRod>(stiffness)),
      GhostSpin::exact,
      communicator);
  }

  /// The equilibrium of @p model (finalized here) under its whole load,
  /// by Newton in one load step from the undeformed state.
  inline VectorType
  solve_in_one_step(RodModel &model)
  {
    model.finalize();
    VectorType               u = model.create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = 1;
    StaticSolver(model, parameters).run(u, [](const auto &, const auto &) {});
    return u;
  }
} // namespace rodnet::testing

#endif
