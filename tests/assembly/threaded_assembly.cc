// Assembly on several threads (RodModel::assemble_families with the
// colored stencil blocks): no two blocks of a color share a DoF, every
// stencil is in one block and every block in one color, and two threads
// give the residual and tangent of one thread
// up to the order of the additions (1e-13 relative) and exactly its energy,
// on a welded honeycomb (hinges, stretching, junction elements) in a
// random state.
#include <deal.II/base/multithread_info.h>

#include <core/rod_model.h>
#include <core/stencil_coloring.h>
#include <geometry/network_generators.h>
#include <geometry/rod_generators.h>
#include <geometry/rod_graph.h>
#include <materials/linear_elastic_rod.h>

#include <gtest/gtest.h>
#include <random>
#include <set>

namespace
{
  using namespace rodnet;

  std::unique_ptr<RodModel>
  honeycomb()
  {
    auto network = std::move(
      build_rod_network(network_generators::hexagonal_lattice(3, 2, 1.0),
                        4,
                        "simple")
        .network);
    const unsigned int n_rods = network->rods().size();
    auto               model  = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>(
        n_rods,
        std::make_shared<LinearElasticRod>(RodStiffness{100, 2, 3, 1.5})));
    model->add_point_force(0, Vector3(0.1, -0.2, 0.3));
    model->finalize();
    return model;
  }

  TEST(StencilColoring, ColorsShareNoDofAndHoldEveryStencil)
  {
    const auto model = honeycomb();
    for (const unsigned int block_size : {1u, 3u, 16u})
      for (const auto &family : model->element_families())
        {
          const StencilBlocks blocks =
            color_stencil_blocks(*family, model->layout().n_dofs(), block_size);
          ASSERT_FALSE(blocks.empty()) << family->name();
          const unsigned int n_blocks = blocks.first.size() - 1;
          EXPECT_EQ(blocks.first.front(), 0u);
          EXPECT_EQ(blocks.first.back(), family->n_stencils());
          std::vector<unsigned int> seen(n_blocks, 0);
          for (const auto &color : blocks.colors)
            {
              std::set<global_dof_index>    dofs_of_color;
              std::vector<global_dof_index> dofs;
              for (const unsigned int b : color)
                {
                  ++seen[b];
                  EXPECT_LE(blocks.first[b + 1] - blocks.first[b], block_size);
                  std::set<global_dof_index> dofs_of_block;
                  for (unsigned int s = blocks.first[b];
                       s < blocks.first[b + 1];
                       ++s)
                    {
                      family->get_dofs(s, dofs);
                      dofs_of_block.insert(dofs.begin(), dofs.end());
                    }
                  for (const global_dof_index d : dofs_of_block)
                    EXPECT_TRUE(dofs_of_color.insert(d).second)
                      << family->name() << ": DoF " << d
                      << " in two blocks of a color";
                }
            }
          for (unsigned int b = 0; b < n_blocks; ++b)
            EXPECT_EQ(seen[b], 1u) << family->name() << " block " << b;
          // Greedy coloring of a graph of bounded degree: a few colors.
          EXPECT_LE(blocks.colors.size(), 12u) << family->name();
        }
  }

  TEST(StencilColoring, AChainOfHingesNeedsThreeColorsTwoInBlocks)
  {
    // Hinge s sees vertices s-1..s+1 and segments s-1, s: hinges three
    // apart share nothing; blocks of at least two hinges share DoFs with
    // their neighbours only.
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(
      generators::straight(Vector3::Zero(), Vector3::UnitX(), 30, false),
      false,
      Vector3::UnitZ(),
      "simple");
    network->create_triangulation();
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(
                     RodStiffness{100, 2, 3, 1.5})});
    model.finalize();
    for (const auto &family : model.element_families())
      if (family->name().find("hinge") != std::string::npos)
        {
          const global_dof_index n = model.layout().n_dofs();
          EXPECT_EQ(color_stencil_blocks(*family, n, 1).colors.size(), 3u);
          EXPECT_EQ(color_stencil_blocks(*family, n, 2).colors.size(), 2u);
          EXPECT_EQ(color_stencil_blocks(*family, n, 8).colors.size(), 2u);
        }
  }

  /// Residual, tangent and energy at @p u on @p threads threads.
  struct Assembled
  {
    Assembled(const RodModel &model, const VectorType &u, unsigned int threads)
        : residual(model.create_vector())
    {
      dealii::MultithreadInfo::set_thread_limit(threads);
      EXPECT_EQ(dealii::MultithreadInfo::n_threads(), threads);
      model.initialize_matrix(tangent);
      energy = model.assemble(u, 0.7, &residual, &tangent);
      dealii::MultithreadInfo::set_thread_limit(1);
    }
    VectorType residual;
    MatrixType tangent;
    double     energy;
  };

  TEST(ThreadedAssembly, TwoThreadsGiveWhatOneGives)
  {
    if (dealii::MultithreadInfo::n_cores() < 2)
      GTEST_SKIP() << "one core: no second thread to compare with";
    const auto                             model = honeycomb();
    VectorType                             u     = model->create_vector();
    std::mt19937                           random(3);
    std::uniform_real_distribution<double> small(-0.05, 0.05);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = small(random);
    u.compress(dealii::VectorOperation::insert);
    const Assembled one(*model, u, 1), two(*model, u, 2);
    EXPECT_EQ(one.energy, two.energy);
    VectorType difference = two.residual;
    difference -= one.residual;
    EXPECT_LE(difference.linfty_norm(), 1e-13 * one.residual.linfty_norm());
    MatrixType k_difference;
    model->initialize_matrix(k_difference);
    k_difference.copy_from(two.tangent);
    k_difference.add(-1.0, one.tangent);
    EXPECT_LE(k_difference.frobenius_norm(),
              1e-13 * one.tangent.frobenius_norm());
    EXPECT_GT(one.tangent.frobenius_norm(), 0);
  }
} // namespace
