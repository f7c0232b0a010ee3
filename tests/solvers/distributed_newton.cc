// Newton on several processes: the model's DoFs in contiguous shares
// (RodModel::finalize), assembled per process, solved by MUMPS on the
// distributed tangent (each process gives it its rows). A welded square
// lattice clamped at one junction and pinned at its far corner, bent out
// of its plane by a distributed load, reaches the equilibrium of the same
// solve on one process (MPI_COMM_SELF) to 1e-10 relative in the same
// number of iterations, with NOX's full steps and with the energy line
// search. Runs on 1, 2 and 3 processes (RODNET_MPI_TESTS).
#include <deal.II/base/mpi.h>

#include <common/square_lattice_model.h>
#include <core/rod_model.h>
#include <solvers/newton/newton_solver.h>

#include <cmath>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  /// A 3 x 3 lattice clamped at a corner junction, pinned at the far
  /// corner, under a distributed load out of its plane.
  std::unique_ptr<RodModel>
  bent_lattice(const MPI_Comm communicator)
  {
    auto model =
      rodnet::testing::square_lattice_model(3,
                                            3,
                                            4,
                                            RodStiffness{1e3, 1, 1, 0.8},
                                            communicator);
    const unsigned int n_rods     = model->network().rods().size();
    const unsigned int n_vertices = model->network().n_vertices();
    model->clamp_junction("corner", 0);
    model->fix_components("far corner", n_vertices - 1, {true, true, true});
    for (unsigned int r = 0; r < n_rods; ++r)
      model->add_distributed_force(r, Vector3(0, 0, 0.05));
    model->finalize();
    return model;
  }

  struct Solved
  {
    Solved(const RodModel &model, const std::string &line_search)
        : u(model.create_vector())
    {
      NewtonSolver::Problem problem;
      problem.set_potential([&](const VectorType &x, VectorType *r) {
        return model.assemble(x, 1.0, r, nullptr);
      });
      problem.tangent = [&](const VectorType &x, MatrixType &k) {
        model.assemble(x, 1.0, nullptr, &k);
      };
      NewtonSolver::Parameters parameters;
      parameters.linear_solver = "mumps";
      parameters.line_search   = line_search;
      parameters.tolerance     = 1e-9;
      model.initialize_matrix(tangent);
      result = NewtonSolver(parameters).solve(problem, u, tangent);
    }
    VectorType           u;
    MatrixType           tangent;
    NewtonSolver::Result result;
  };

  class DistributedNewton : public ::testing::TestWithParam<std::string>
  {
  };

  TEST_P(DistributedNewton, ReachesTheEquilibriumOfOneProcess)
  {
    const auto   serial_model      = bent_lattice(MPI_COMM_SELF);
    const auto   distributed_model = bent_lattice(MPI_COMM_WORLD);
    const Solved serial(*serial_model, GetParam());
    const Solved distributed(*distributed_model, GetParam());
    ASSERT_TRUE(serial.result.converged) << serial.result.failure;
    ASSERT_TRUE(distributed.result.converged) << distributed.result.failure;
    EXPECT_EQ(distributed.result.iterations, serial.result.iterations);
    // Large rotations: the loaded vertex moves by a good part of a cell.
    const double scale = serial.u.linfty_norm();
    EXPECT_GT(scale, 0.2);
    for (const global_dof_index i : distributed_model->locally_owned_dofs())
      EXPECT_NEAR(distributed.u[i], serial.u[i], 1e-10 * scale) << "DoF " << i;
  }

  INSTANTIATE_TEST_SUITE_P(Globalizations,
                           DistributedNewton,
                           ::testing::Values("full step", "energy"),
                           [](const auto &info) {
                             return info.param == "full step" ? "FullStep" :
                                                                "Energy";
                           });
} // namespace
