// DrProcessShare and the DrModel on several processes: each process's share
// of the elements and DoFs, and what the model and DynamicRelaxation compute
// from it, against the same model on one process (MPI_COMM_SELF), built on
// every process. Runs on 1, 2 and 3 processes (tests/CMakeLists.txt,
// RODNET_MPI_TESTS).
#include <deal.II/base/mpi.h>

#include <common/bent_dr_network.h>
#include <core/dr_model.h>
#include <solvers/relaxation/dynamic_relaxation.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
  using namespace rodnet;
  using rodnet::testing::bent_dr_network;

  /// A state of small random changes, the same on every process.
  DrVector
  random_state(const DrModel &model)
  {
    DrVector u = model.create_vector();
    std::srand(11);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = 0.05 * (2.0 * std::rand() / RAND_MAX - 1);
    model.apply_boundary_values(u, 0.7);
    return u;
  }

  /// Whether DoF @p i is one the share of @p model keeps up to date: touched
  /// by its elements, or fixed.
  bool
  kept(const DrModel &model, const unsigned int i)
  {
    const auto &touched = model.process_share().touched_free_dofs();
    return model.fixed_dof_mask()[i] ||
           std::binary_search(touched.begin(), touched.end(), i);
  }

  // Every DoF has one owner; the element ranges cover the elements once;
  // every free DoF is touched by some process, and a process owns only DoFs
  // it touches (every DoF of this network is in some element's stencil).
  TEST(DrProcessShare, OwnersAndElementsPartitionTheModel)
  {
    const auto          model = bent_dr_network();
    const auto         &share = model->process_share();
    const unsigned int  n     = model->n_dofs();
    std::vector<double> owners(n, 0), touching(n, 0);
    for (unsigned int i = 0; i < n; ++i)
      owners[i] = share.owns(i);
    for (const unsigned int i : share.touched_free_dofs())
      touching[i] = 1;
    for (const unsigned int i : share.owned_free_dofs())
      EXPECT_TRUE(kept(*model, i)) << "owned, not touched: " << i;
    share.sum(owners);
    share.sum(touching);
    for (unsigned int i = 0; i < n; ++i)
      {
        EXPECT_EQ(owners[i], 1.0) << "DoF " << i;
        if (!model->fixed_dof_mask()[i])
          {
            EXPECT_GE(touching[i], 1.0) << "DoF " << i;
          }
      }
    const auto [first, end] = share.elements();
    EXPECT_EQ(share.sum(end - first), double(model->n_elements()));
  }

  // Residual, masses and energies: those of one process, on the DoFs the
  // process keeps, up to the order of the additions.
  TEST(DrProcessShare, ModelEvaluatesAsOneProcess)
  {
    const auto     model = bent_dr_network();
    const auto     alone = bent_dr_network(MPI_COMM_SELF);
    const DrVector u     = random_state(*alone);
    DrVector       r, r_alone, m, m_alone;
    model->residual(u, 0.7, r);
    alone->residual(u, 0.7, r_alone);
    model->fictitious_masses(u, 2, m);
    alone->fictitious_masses(u, 2, m_alone);
    const double scale    = r_alone.linfty_norm();
    unsigned int compared = 0;
    for (unsigned int i = 0; i < model->n_dofs(); ++i)
      if (kept(*model, i))
        {
          EXPECT_NEAR(r[i], r_alone[i], 1e-13 * scale) << "residual " << i;
          EXPECT_NEAR(m[i], m_alone[i], 1e-13 * m_alone[i]) << "mass " << i;
          ++compared;
        }
    EXPECT_GT(compared, 0u);
    const double energy = alone->energy(u, 0.7);
    EXPECT_NEAR(model->energy(u, 0.7), energy, 1e-13 * std::abs(energy));
    EXPECT_NEAR(model->elastic_energy(u, 0.7),
                alone->elastic_energy(u, 0.7),
                1e-13 * std::abs(energy));
  }

  // complete() fills in every entry from its owner: the entries a process
  // does not own start as NaN and come out right.
  TEST(DrProcessShare, CompleteGivesEveryEntryItsOwnersValue)
  {
    const auto  model = bent_dr_network();
    const auto &share = model->process_share();
    DrVector    v     = model->create_vector();
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] = share.owns(i) ? 1.0 + 0.5 * i :
                             std::numeric_limits<double>::quiet_NaN();
    share.complete(v);
    for (unsigned int i = 0; i < v.size(); ++i)
      EXPECT_EQ(v[i], 1.0 + 0.5 * i) << "entry " << i;
  }

  // Dynamic relaxation of the network to 1e-8 of its loads in two load
  // steps (5854 iterations): the positions of one process to 1e-9 of
  // the network's size, every process with the same iterations and the
  // whole state.
  TEST(DrProcessShare, RelaxesAsOneProcess)
  {
    DynamicRelaxation::Parameters parameters;
    parameters.n_steps            = 2;
    parameters.residual_tolerance = 1e-8;
    const auto model              = bent_dr_network();
    const auto alone              = bent_dr_network(MPI_COMM_SELF);
    DrVector   u = model->create_vector(), u_alone = alone->create_vector();
    const auto result = DynamicRelaxation(*model, parameters)
                          .run(u, [](const auto &, const auto &) {});
    const auto result_alone =
      DynamicRelaxation(*alone, parameters)
        .run(u_alone, [](const auto &, const auto &) {});
    EXPECT_EQ(result.total_iterations, result_alone.total_iterations);
    std::cout << result.total_iterations << " iterations" << std::endl;
    EXPECT_EQ(model->process_share().sum(result.total_iterations),
              double(result.total_iterations) *
                dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    for (unsigned int v = 0; v < model->network().n_vertices(); ++v)
      EXPECT_LT((model->position(u, v) - alone->position(u_alone, v)).norm(),
                1e-9)
        << "vertex " << v;
  }
} // namespace
