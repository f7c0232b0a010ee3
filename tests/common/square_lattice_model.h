#ifndef RODNET_TESTS_COMMON_SQUARE_LATTICE_MODEL_H
#define RODNET_TESTS_COMMON_SQUARE_LATTICE_MODEL_H

// A welded square lattice of cells of side 1 as a RodModel on a given
// communicator, not finalized (the caller adds supports and loads): the
// network of the tests of models on several processes.

#include <common/rod_models.h>
#include <core/rod_model.h>
#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>

#include <memory>

namespace rodnet::testing
{
  /// @p nx x @p ny cells, @p segments segments per beam, every rod of
  /// @p stiffness, on @p communicator.
  inline std::unique_ptr<RodModel>
  square_lattice_model(const unsigned int  nx,
                       const unsigned int  ny,
                       const unsigned int  segments,
                       const RodStiffness &stiffness,
                       const MPI_Comm      communicator)
  {
    auto network = std::move(
      build_rod_network(network_generators::square_lattice(nx, ny, 1.0),
                        segments,
                        "simple")
        .network);
    return elastic_model(std::move(network), stiffness, communicator);
  }
} // namespace rodnet::testing

#endif
