// balanced_share(): contiguous ranges of the DoFs whose anchored stencils
// cost about as much each, computed for 2 to 5 processes on one process
// (the function depends on the network alone). The reference is a direct
// sum of the costs (ElementFamily::relative_cost()) of the stencils whose
// first DoF lies in each range; stencils_anchored() of the ranges must
// evaluate every stencil once.
#include <common/square_lattice_model.h>
#include <core/rod_model.h>
#include <core/stencil_ownership.h>

#include <algorithm>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  /// The cost of the stencils whose first DoF lies in @p share, summed
  /// directly (each its family's relative_cost()).
  double
  cost_anchored(const RodModel &model, const dealii::IndexSet &share)
  {
    double                        cost = 0;
    std::vector<global_dof_index> dofs;
    for (const auto &family : model.element_families())
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          family->get_dofs(s, dofs);
          if (!dofs.empty() && share.is_element(dofs[0]))
            cost += family->relative_cost();
        }
    return cost;
  }

  /// How often the processes owning @p shares evaluate each stencil of
  /// each family (stencils_anchored()).
  std::vector<std::vector<unsigned int>>
  evaluations(const RodModel                      &model,
              const std::vector<dealii::IndexSet> &shares)
  {
    const auto                            &families = model.element_families();
    std::vector<std::vector<unsigned int>> times(families.size());
    for (unsigned int f = 0; f < families.size(); ++f)
      times[f].assign(families[f]->n_stencils(), 0);
    for (const dealii::IndexSet &share : shares)
      {
        const std::vector<OwnedStencils> own =
          stencils_anchored(families, share);
        for (unsigned int f = 0; f < families.size(); ++f)
          for (const unsigned int s : own[f].stencils)
            ++times[f][s];
      }
    return times;
  }

  TEST(BalancedShare, RangesPartitionTheDofsAndEvaluateAlike)
  {
    // 12 x 12 welded cells: the junctions' quaternions, numbered last
    // (about 7 % of the DoFs), are coupled by every junction stencil
    // (about 15 % of the stencils).
    const auto model =
      rodnet::testing::square_lattice_model(12,
                                            12,
                                            6,
                                            RodStiffness{100, 2, 3, 1.5},
                                            MPI_COMM_SELF);
    model->finalize();
    const auto n_dofs = model->layout().n_dofs();
    for (unsigned int processes = 2; processes <= 5; ++processes)
      {
        double                        most_even = 0;
        std::vector<double>           costs;
        std::vector<dealii::IndexSet> shares;
        global_dof_index              next = 0;
        for (unsigned int rank = 0; rank < processes; ++rank)
          {
            const dealii::IndexSet share =
              balanced_share(model->element_families(),
                             n_dofs,
                             processes,
                             rank);
            ASSERT_GT(share.n_elements(), 0u) << processes << " processes";
            EXPECT_TRUE(share.is_contiguous());
            shares.push_back(share);
            EXPECT_EQ(share.nth_index_in_set(0), next) << "rank " << rank;
            next = share.nth_index_in_set(0) + share.n_elements();
            costs.push_back(cost_anchored(*model, share));
            most_even = std::max(
              most_even,
              cost_anchored(*model, contiguous_share(n_dofs, processes, rank)));
          }
        EXPECT_EQ(next, n_dofs) << processes << " processes";
        const auto [fewest, most] =
          std::minmax_element(costs.begin(), costs.end());
        // Balanced in cost to 2 % (a range's end moves by whole DoFs, and
        // the stencils of one anchor stay together).
        EXPECT_LE(*most, 1.02 * *fewest) << processes << " processes";
        // And better than equal ranges of DoFs, whose last range holds the
        // junctions' quaternions, which anchor no stencil.
        EXPECT_LT(*most, most_even) << processes << " processes";
        // Each stencil with DoFs evaluated by exactly one process.
        const auto                    times = evaluations(*model, shares);
        std::vector<global_dof_index> dofs;
        for (unsigned int f = 0; f < times.size(); ++f)
          for (unsigned int s = 0; s < times[f].size(); ++s)
            {
              model->element_families()[f]->get_dofs(s, dofs);
              ASSERT_EQ(times[f][s], dofs.empty() ? 0u : 1u)
                << "family " << f << ", stencil " << s << ", " << processes
                << " processes";
            }
      }
  }
} // namespace
