// The equilibrium checks on several processes (EquilibriumFactorization):
// MUMPS's distributed LDL^T of the KKT tangent in place of a serial LDL^T
// of an imported copy on each process.
//  - The inertia of a straight clamped-free column under compression counts
//    its Euler modes below the load, P_k = (2k - 1)^2 pi^2 EI / (4 L^2) in
//    both planes: 2 negative eigenvalues at 2 P_1, 14 at 200 P_1. So for an
//    extensible rod and for an inextensible one, whose multipliers give MUMPS
//    one negative pivot each besides.
//  - Its solves equal the exact constrained inverse Z (Z^T H Z)^-1 Z^T of
//    MUMPS on one process's KKT tangent to 1e-9, for an extensible and an
//    inextensible rod; on one process, where the multipliers are
//    regularized, to 1e-5.
//  - The checks reuse the Newton solver's MUMPS analysis: a factorization
//    kept for "auto" serves "mumps" on several processes.
// Runs on 1, 2 and 3 processes (RODNET_MPI_TESTS).
#include <deal.II/base/mpi.h>

#include <common/rod_models.h>
#include <core/every_entry.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/equilibrium_factorization.h>
#include <solvers/newton/mumps_factorization.h>

#include <cmath>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double column_EA = 1e4, column_EI = 1;

  /// A column of length 1 along x in 50 segments, clamped at its start,
  /// under the end load @p ratio times its first Euler load, on
  /// @p communicator; inextensible if @p inextensible. Not finalized.
  std::unique_ptr<RodModel>
  compressed_column(const double   ratio,
                    const bool     inextensible,
                    const MPI_Comm communicator = MPI_COMM_WORLD)
  {
    auto network = straight_network(50);
    network->create_triangulation();
    network->set_inextensible(0, inextensible);
    auto model = elastic_model(std::move(network),
                               {column_EA, column_EI, column_EI, column_EI},
                               communicator);
    model->clamp_end("clamp", 0, true);
    const double euler = M_PI * M_PI * column_EI / 4;
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           Vector3(-ratio * euler, 0, 0));
    return model;
  }

  class DistributedChecks : public ::testing::TestWithParam<bool>
  {
  };

  TEST_P(DistributedChecks, InertiaCountsTheEulerModesBelowTheLoad)
  {
    for (const auto &[ratio, expected] :
         std::vector<std::pair<double, unsigned int>>{{0.5, 0},
                                                      {2, 2},
                                                      {200, 14}})
      {
        const auto model = compressed_column(ratio, GetParam());
        // The straight, compressed column: the axial force that the
        // inertia counts against is that of the solved state.
        const VectorType u = solve_in_one_step(*model);
        MatrixType       tangent;
        model->initialize_matrix(tangent);
        EXPECT_EQ(negative_eigenvalues(*model, u, 1.0, tangent), expected)
          << "P / P_1 = " << ratio;
      }
  }

  /// The tangent of @p model at its straight equilibrium and a fixed
  /// right-hand side with a different entry at every DoF.
  struct StraightTangent
  {
    explicit StraightTangent(RodModel &model)
    {
      // After finalize(), which gives each process its share.
      const VectorType u = solve_in_one_step(model);
      b                  = model.create_vector();
      model.initialize_matrix(tangent);
      model.assemble(u, 1.0, nullptr, &tangent, true);
      for (const global_dof_index i : b.locally_owned_elements())
        b[i] = std::sin(0.37 * i + 1.0);
      b.compress(dealii::VectorOperation::insert);
    }
    MatrixType tangent;
    VectorType b;
  };

  /// The exact constrained solve of @p k x = b on one process: MUMPS on
  /// the KKT tangent, b zero and x zeroed at the fixed DoFs and
  /// multipliers.
  VectorType
  kkt_solve(const RodModel &model, const StraightTangent &k)
  {
    std::vector<global_dof_index> held = model.multiplier_dofs();
    for (global_dof_index i = 0; i < k.b.size(); ++i)
      if (model.constraints().is_constrained(i))
        held.push_back(i);
    VectorType rhs = k.b, x = k.b;
    for (const global_dof_index i : held)
      rhs[i] = 0;
    MumpsFactorization mumps(k.tangent);
    mumps.factorize();
    mumps.solve(rhs, x);
    for (const global_dof_index i : held)
      x[i] = 0;
    return x;
  }

  TEST_P(DistributedChecks, SolvesAsTheExactConstrainedInverse)
  {
    const bool inextensible = GetParam();
    const auto model        = compressed_column(0.5, inextensible);
    const auto serial_model =
      compressed_column(0.5, inextensible, MPI_COMM_SELF);
    const StraightTangent k(*model);
    const StraightTangent serial_k(*serial_model);
    VectorType            solved = model->create_vector();
    EquilibriumFactorization::create(*model, k.tangent)->solve(k.b, solved);
    const VectorType  reference = kkt_solve(*serial_model, serial_k);
    const EveryEntry  every_entry(solved);
    const VectorType &x    = *every_entry;
    double            diff = 0;
    for (global_dof_index i = 0; i < x.size(); ++i)
      diff = std::max(diff, std::abs(x[i] - reference[i]));
    const double size = reference.linfty_norm();
    ASSERT_GT(size, 0);
    // On one process the multipliers are regularized (a penalty of 1 / c,
    // c = 1e-2, ConstrainedFactorization), which moves the inextensible
    // rod's solution by 3.3e-6 of its size here; MUMPS's is exact (1e-11).
    const bool several =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    EXPECT_LT(diff / size, inextensible && !several ? 1e-5 : 1e-9)
      << "largest difference " << diff << " of " << size;
  }

  INSTANTIATE_TEST_SUITE_P(ExtensibleAndInextensible,
                           DistributedChecks,
                           ::testing::Values(false, true));

  TEST(DistributedChecksCache, ReuseTheNewtonFactorizationOnSeveralProcesses)
  {
    const auto model = compressed_column(0.5, false);
    model->finalize();
    MatrixType tangent;
    model->initialize_matrix(tangent);
    TangentFactorizationCache cache;
    const auto                newton = cache.get(tangent, "auto");
    const auto                check  = cache.get(tangent, "mumps");
    const bool                several =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    // On one process "auto" takes the band LU of a rod's narrow band.
    EXPECT_EQ(newton->name(), several ? "mumps" : "band");
    EXPECT_EQ(check == newton, several);
    EXPECT_EQ(cache.get(tangent, "auto") == check, several);
  }
} // namespace
