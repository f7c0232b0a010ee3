// Rigid motions that no support stops (describe_free_motions()): each case
// of the issue gets the motion a hand analysis of its supports gives, and a
// held structure gets none; StaticSolver refuses a free one before the
// first step.
#include <common/rod_models.h>
#include <solvers/free_motions.h>
#include <solvers/static_solver.h>

#include <gtest/gtest.h>
#include <stdexcept>

namespace
{
  using namespace rodnet;

  /// A straight rod from the origin along x (length 1, 10 segments), and a
  /// second, separate one beside it when @p two_rods.
  std::unique_ptr<RodModel>
  straight_rods(const bool two_rods = false)
  {
    auto network = rodnet::testing::straight_network(10);
    if (two_rods)
      network->add_rod(generators::straight(Vector3(0, 1, 0),
                                            Vector3(1, 1, 0),
                                            10),
                       false,
                       Vector3::UnitZ(),
                       "simple");
    return rodnet::testing::elastic_model(std::move(network),
                                          RodStiffness{1e4, 1, 1, 1});
  }

  std::string
  motions_of(RodModel &model)
  {
    model.finalize();
    return describe_free_motions(model, model.create_vector());
  }

  void
  expect_contains(const std::string &text, const std::string &fragment)
  {
    EXPECT_NE(text.find(fragment), std::string::npos)
      << "\"" << fragment << "\" not in: " << text;
  }

  TEST(FreeMotions, UnsupportedRodMovesEveryWay)
  {
    auto              model = straight_rods();
    const std::string text  = motions_of(*model);
    expect_contains(text, "rod 0 can translate in any direction");
    expect_contains(text, "rotate about any axis");
  }

  TEST(FreeMotions, OnePinnedNodeLeavesRotationsAboutIt)
  {
    auto model = straight_rods();
    model->fix_components("pin", 0, {{true, true, true}});
    const std::string text = motions_of(*model);
    expect_contains(text, "rotate about any axis through vertex 0:start");
    EXPECT_EQ(text.find("translate"), std::string::npos) << text;
  }

  TEST(FreeMotions, RodPinnedAtBothEndsSpinsAboutTheirLine)
  {
    // Both ends pinned: every translation and the rotations about y and z
    // move a pin; the spin about x moves only the (free) twists.
    auto model = straight_rods();
    model->fix_components("a", 0, {{true, true, true}});
    model->fix_components("b", 10, {{true, true, true}});
    const std::string text = motions_of(*model);
    expect_contains(text, "rotate about the axis through vertex 0:");
    expect_contains(text, "along (1, 0, 0)");
    EXPECT_EQ(text.find("translate"), std::string::npos) << text;
  }

  TEST(FreeMotions, RollerLeavesOneTranslation)
  {
    // Clamped in y and z only (two vertices and the twist): the rod can
    // still slide along x.
    auto model = straight_rods();
    model->fix_components("a", 0, {{false, true, true}});
    model->fix_components("b", 1, {{false, true, true}});
    model->fix_components("c", 5, {{false, true, true}});
    const std::string text = motions_of(*model);
    expect_contains(text, "translate along (1, 0, 0)");
  }

  TEST(FreeMotions, HeldStructuresHaveNone)
  {
    auto cantilever = straight_rods();
    cantilever->clamp_end("clamp", 0, true);
    EXPECT_EQ(motions_of(*cantilever), "");

    // Pinned at both ends with the twist held at one: the spin is gone.
    auto model = straight_rods();
    model->fix_components("a", 0, {{true, true, true}});
    model->fix_components("b", 10, {{true, true, true}});
    model->clamp_end("twist", 0, true);
    EXPECT_EQ(motions_of(*model), "");
  }

  TEST(FreeMotions, EachPartIsJudgedOnItsOwn)
  {
    // Two separate rods, only the first clamped: the second is free.
    auto model = straight_rods(true);
    model->clamp_end("clamp", 0, true);
    const std::string text = motions_of(*model);
    expect_contains(text, "rod 1 can translate in any direction");
    EXPECT_EQ(text.find("rod 0"), std::string::npos) << text;
  }

  TEST(FreeMotions, StaticSolverRefusesBeforeTheFirstStep)
  {
    auto model = straight_rods();
    model->fix_components("pin", 0, {{true, true, true}});
    model->add_point_force(10, Vector3(0, 0, 1));
    model->finalize();
    VectorType   u = model->create_vector();
    StaticSolver solver(*model, StaticSolver::Parameters());
    unsigned int steps = 0;
    try
      {
        solver.run(u, [&](const auto &, const auto &) { ++steps; });
        ADD_FAILURE() << "a free structure was solved";
      }
    catch (const std::invalid_argument &e)
      {
        expect_contains(e.what(), "the structure is not held");
      }
    EXPECT_EQ(steps, 0u);
  }
} // namespace
