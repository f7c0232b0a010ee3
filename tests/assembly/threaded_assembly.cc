// Assembly on several threads (RodModel::assemble_families with the
// stencil colors): no two stencils of a color share a DoF, every stencil is
// in one color, and two threads give the residual and tangent of one thread
// up to the order of the additions (1e-13 relative) and exactly its energy,
// on a welded honeycomb (hinges, stretching, junction elements) in a
// random state.
#include <deal.II/base/multithread_info.h>

#include <core/network_generators.h>
#include <core/rod_generators.h>
#include <core/rod_graph.h>
#include <core/rod_model.h>
#include <core/stencil_coloring.h>
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
    for (const auto &family : model->element_families())
      {
        const auto colors =
          color_stencils(*family, model->layout().n_dofs());
        ASSERT_FALSE(colors.empty()) << family->name();
        std::vector<unsigned int> seen(family->n_stencils(), 0);
        for (const auto &color : colors)
          {
            std::set<global_dof_index>    dofs_of_color;
            std::vector<global_dof_index> dofs;
            for (const unsigned int s : color)
              {
                ++seen[s];
                dofs.clear();
                family->get_dofs(s, dofs);
                for (const global_dof_index d : dofs)
                  EXPECT_TRUE(dofs_of_color.insert(d).second)
                    << family->name() << ": DoF " << d << " twice in a color";
              }
          }
        for (unsigned int s = 0; s < seen.size(); ++s)
          EXPECT_EQ(seen[s], 1u) << family->name() << " stencil " << s;
        // Greedy coloring of a graph of bounded degree: a few colors.
        EXPECT_LE(colors.size(), 12u) << family->name();
      }
  }

  TEST(StencilColoring, AChainOfHingesNeedsThreeColors)
  {
    // Hinge s sees vertices s-1..s+1 and segments s-1, s: hinges three
    // apart share nothing.
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3::Zero(),
                                          Vector3::UnitX(),
                                          30,
                                          false),
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
          EXPECT_EQ(color_stencils(*family, model.layout().n_dofs()).size(),
                    3u);
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
