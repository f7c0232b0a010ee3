// balanced_share(): contiguous ranges of the DoFs that evaluate about as
// many stencils each, computed for 2 to 5 processes on one process (the
// function depends on the network alone). The reference is a direct count:
// stencils_coupling() of each range, the stencils a process evaluates.
#include <common/square_lattice_model.h>
#include <core/rod_model.h>
#include <core/stencil_ownership.h>

#include <algorithm>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  /// The stencils a process owning @p share evaluates (stencils_coupling()).
  std::size_t
  stencils_evaluated(const RodModel &model, const dealii::IndexSet &share)
  {
    std::size_t count = 0;
    for (const OwnedStencils &s :
         stencils_coupling(model.element_families(), share))
      count += s.stencils.size();
    return count;
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
        std::size_t              most_even = 0;
        std::vector<std::size_t> counts;
        global_dof_index         next = 0;
        for (unsigned int rank = 0; rank < processes; ++rank)
          {
            const dealii::IndexSet share =
              balanced_share(model->element_families(),
                             n_dofs,
                             processes,
                             rank);
            ASSERT_GT(share.n_elements(), 0u) << processes << " processes";
            EXPECT_TRUE(share.is_contiguous());
            EXPECT_EQ(share.nth_index_in_set(0), next) << "rank " << rank;
            next = share.nth_index_in_set(0) + share.n_elements();
            counts.push_back(stencils_evaluated(*model, share));
            most_even = std::max(
              most_even,
              stencils_evaluated(*model,
                                 contiguous_share(n_dofs, processes, rank)));
          }
        EXPECT_EQ(next, n_dofs) << processes << " processes";
        const auto [fewest, most] =
          std::minmax_element(counts.begin(), counts.end());
        // Balanced to 2 % (a range's end moves by whole DoFs; the stencils
        // on a border count for both ranges).
        EXPECT_LE(*most, 1.02 * *fewest) << processes << " processes";
        // And better than equal ranges of DoFs, whose last range evaluates
        // every junction stencil.
        EXPECT_LT(*most, most_even) << processes << " processes";
      }
  }
} // namespace
