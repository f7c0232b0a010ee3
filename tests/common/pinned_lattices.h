#ifndef RODNET_TESTS_PINNED_LATTICES_H
#define RODNET_TESTS_PINNED_LATTICES_H

#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>
#include <solvers/newton/tangent_factorization.h>

#include "rod_models.h"
#include <cmath>
#include <memory>

// Welded square lattices pinned at their corners, whose tangents the
// tests of Newton's direct solvers factorize (tests/solvers/
// tangent_factorization.cc, mumps_factorization.cc).
namespace rodnet::testing
{
  /// The finalized model of a welded square lattice of @p cells x @p cells
  /// cells of side @p side, @p segments per beam, of @p stiffness
  /// (@p inextensible rods or not), pinned at its four corners, on
  /// @p communicator.
  inline std::unique_ptr<RodModel>
  pinned_square_lattice(const unsigned int  cells,
                        const double        side,
                        const unsigned int  segments,
                        const RodStiffness &stiffness,
                        const bool          inextensible,
                        const MPI_Comm      communicator = MPI_COMM_WORLD)
  {
    BuiltNetwork built =
      build_rod_network(network_generators::square_lattice(cells, cells, side),
                        segments,
                        "simple");
    for (unsigned int rod = 0; rod < built.network->rods().size(); ++rod)
      built.network->set_inextensible(rod, inextensible);
    auto model = rodnet::testing::elastic_model(std::move(built.network),
                                                stiffness,
                                                communicator);
    for (const unsigned int node :
         {0u, cells, cells * (cells + 1), (cells + 1) * (cells + 1) - 1})
      model->fix_components("corner",
                            built.node_vertex[node],
                            {{true, true, true}});
    model->finalize();
    return model;
  }

  /**
   * A welded square lattice of 30 x 30 cells of side 0.1 (10 segments per
   * beam, EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67: the lattice of issue 33;
   * 83820 DoFs) pinned at its corners, and its tangent where the lattice
   * is rolled into a cylinder of one turn about a line along y, the
   * junction rotations left at the identity: a state far from equilibrium,
   * as Newton's first iterates on a large lattice are, whose tangent is
   * indefinite.
   */
  struct RolledLattice
  {
    static constexpr unsigned int cells = 30;
    static constexpr double       side  = 0.1;

    std::unique_ptr<RodModel> model;
    MatrixType                tangent;

    RolledLattice()
    {
      model =
        pinned_square_lattice(cells, side, 10, {1e5, 400, 100, 67}, false);
      model->initialize_matrix(tangent);
    }

    /// Assembles the tangent, flat (@p turns = 0) or rolled by @p turns.
    void
    assemble_rolled(const double turns)
    {
      VectorType   u      = model->create_vector();
      const double radius = cells * side / (2 * M_PI * turns);
      for (unsigned int v = 0; v < model->network().n_vertices() && turns > 0;
           ++v)
        {
          const Vector3 x = model->network().vertex(v);
          const Vector3 rolled(radius * std::sin(x[0] / radius),
                               x[1],
                               radius * (1 - std::cos(x[0] / radius)));
          for (unsigned int c = 0; c < 3; ++c)
            u[model->layout().vertex_dof(v, c)] = rolled[c] - x[c];
        }
      u.compress(dealii::VectorOperation::insert);
      model->assemble(u, 0.0, nullptr, &tangent);
    }
  };

  /// Initializes @p tangent for @p model and assembles it at a state off
  /// equilibrium: every DoF, the multipliers too, moved by
  /// @p amplitude cos(0.7 i).
  inline void
  assemble_shaken(RodModel &model, MatrixType &tangent, const double amplitude)
  {
    model.initialize_matrix(tangent);
    VectorType u = model.create_vector();
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = amplitude * std::cos(0.7 * i);
    u.compress(dealii::VectorOperation::insert);
    model.assemble(u, 1.0, nullptr, &tangent);
  }

  /// The normwise backward error |b - K x| / (|K|_F |x| + |b|) of the
  /// solution x of K x = b by @p solver.
  inline double
  normwise_backward_error(TangentFactorization &solver,
                          const MatrixType     &tangent,
                          const VectorType     &b)
  {
    VectorType x = b;
    solver.solve(b, x);
    VectorType kx = x;
    tangent.vmult(kx, x);
    kx.add(-1.0, b);
    return kx.l2_norm() /
           (tangent.frobenius_norm() * x.l2_norm() + b.l2_norm());
  }

} // namespace rodnet::testing

#endif
