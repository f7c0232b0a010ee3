// Rigid motions that no support stops (describe_free_motions()): each case
// of the issue gets the motion a hand analysis of its supports gives, and a
// held structure gets none; StaticSolver refuses a free one before the
// first step. An elastic foundation holds the motions that move a vertex
// along its springs, and only those. The common turn of an isotropic rod's
// frames, which the energy does not see, is found (free_frame_turns()) so
// that the solvers can hold it.
#include <common/rod_models.h>
#include <solvers/checks/free_motions.h>
#include <solvers/statics/static_solver.h>

#include <families/elastic_foundation.h>
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

  /// Rests the rods of @p model on springs of modulus 1 along
  /// @p direction (none: every direction).
  void
  add_foundation(RodModel &model, const std::optional<Vector3> &direction)
  {
    model.add_element_family(std::make_unique<ElasticFoundation>(
      model.network(),
      model.layout(),
      ElasticFoundationParameters{1, direction, {}}));
  }

  /// A network with a closed ring of radius 1 about @p center in the xy
  /// plane.
  std::unique_ptr<RodNetwork>
  ring_network(const Vector3 &center)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(
      generators::ring(center, 1, Vector3::UnitX(), Vector3::UnitY(), 12),
      true,
      Vector3::UnitZ(),
      "simple");
    return network;
  }

  /// The ring about (2, 1, 0).
  std::unique_ptr<RodModel>
  ring()
  {
    return rodnet::testing::elastic_model(ring_network(Vector3(2, 1, 0)),
                                          RodStiffness{1e4, 1, 1, 1});
  }

  TEST(FreeMotions, FoundationInEveryDirectionHoldsARing)
  {
    // Every rigid motion of a ring moves some vertex, which a spring stops.
    auto model = ring();
    add_foundation(*model, std::nullopt);
    EXPECT_EQ(motions_of(*model), "");
  }

  TEST(FreeMotions, FoundationInEveryDirectionLeavesAStraightRodItsSpin)
  {
    // The spin about the rod's own line moves no vertex, only the twists,
    // which no spring holds: the axis through the midpoint (0.5, 0, 0).
    auto model = straight_rods();
    add_foundation(*model, std::nullopt);
    EXPECT_EQ(motions_of(*model),
              "the structure is not held: rod 0 can rotate about the axis "
              "through (0.5, 0, 0) along (1, 0, 0); add supports "
              "(Supports/Clamped ends, Pinned vertices or Fixed components) "
              "that stop these motions");

    // A clamp holds the twist of its segment, and with it the spin.
    auto clamped = straight_rods();
    add_foundation(*clamped, std::nullopt);
    clamped->clamp_end("clamp", 0, true);
    EXPECT_EQ(motions_of(*clamped), "");
  }

  TEST(FreeMotions, FoundationAlongZLeavesTheMotionsInThePlane)
  {
    // Springs along z stop the translation along z and the rotations about
    // x and y (they lift the ring); they leave the ring sliding in its
    // plane and turning about the normal through any point, reported as
    // the axis through its centre.
    auto model = ring();
    add_foundation(*model, Vector3::UnitZ());
    EXPECT_EQ(motions_of(*model),
              "the structure is not held: rod 0 can translate in the plane "
              "normal to (0, 0, 1) and rotate about the axis through (2, 1, "
              "0) along (0, 0, 1); add supports (Supports/Clamped ends, "
              "Pinned vertices or Fixed components) that stop these motions");
  }

  TEST(FreeMotions, SupportsAndFoundationTogether)
  {
    // Vertex 0, at (3, 1, 0), held in x and y: the in-plane translations
    // go, the rotation about the normal through it stays.
    auto model = ring();
    add_foundation(*model, Vector3::UnitZ());
    model->fix_components("pin", 0, {{true, true, false}});
    const std::string text = motions_of(*model);
    expect_contains(text,
                    "rod 0 can rotate about the axis through vertex 0:start "
                    "along (0, 0, 1);");
    EXPECT_EQ(text.find("translate"), std::string::npos) << text;
  }

  TEST(FreeMotions, FoundationHoldsOnlyTheRodsOnIt)
  {
    // The ring rests on the foundation, a separate straight rod does not:
    // the ring is held, the rod free.
    auto network = ring_network(Vector3::Zero());
    network->add_rod(generators::straight(Vector3(0, 0, 1),
                                          Vector3(1, 0, 1),
                                          4),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    auto model = rodnet::testing::elastic_model(std::move(network),
                                                RodStiffness{1e4, 1, 1, 1});
    model->add_element_family(std::make_unique<ElasticFoundation>(
      model->network(),
      model->layout(),
      ElasticFoundationParameters{1, std::nullopt, {0}}));
    const std::string text = motions_of(*model);
    expect_contains(text,
                    "not held: rod 1 can translate in any direction and "
                    "rotate about any axis");
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

  /// A ring of radius 1 about (2, 1, 0) in 12 segments with EI1 = 1,
  /// EI2 = @p EI2, GJ = 1, naturally straight with the natural curvature
  /// @p kappa0 about d1 (or stress free as built where @p as_built), its
  /// rigid motions held by six components (vertex 0 in x, y, z, vertex 6
  /// in y, z, vertex 3 in z).
  std::unique_ptr<RodModel>
  held_ring(const double EI2,
            const double kappa0   = 0,
            const bool   as_built = false)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::ring(Vector3(2, 1, 0),
                                      1,
                                      Vector3::UnitX(),
                                      Vector3::UnitY(),
                                      12),
                     true,
                     Vector3::UnitZ(),
                     "simple",
                     as_built ? NaturalShape::initial_geometry :
                                NaturalShape::straight);
    RodNaturalShape natural;
    natural.curvature1 = kappa0;
    auto model         = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
                std::make_shared<LinearElasticRod>(RodStiffness{1e4, 1, EI2, 1},
                                           natural)});
    const auto &v = model->network().rods()[0].vertices;
    model->fix_components("origin", v[0], {{true, true, true}});
    model->fix_components("opposite", v[6], {{false, true, true}});
    model->fix_components("quarter", v[3], {{false, false, true}});
    model->finalize();
    return model;
  }

  TEST(FreeMotions, IsotropicRingTurnsItsFramesFreely)
  {
    // EI1 = EI2, naturally straight: turning every frame by the same angle
    // changes no strain energy (the curvature vector turns within an
    // isotropic section, the twists do not change), here at a state bent
    // out of the circle. One twist of the ring holds the turn.
    auto       model = held_ring(1);
    VectorType u     = model->create_vector();
    for (unsigned int k = 0; k < 12; ++k)
      u[model->layout().vertex_dof(model->network().rods()[0].vertices[k], 2)] =
        0.05 * std::sin(2.0 * k);
    u.compress(dealii::VectorOperation::insert);
    model->apply_boundary_values(u, 1.0);
    const std::vector<global_dof_index> turns =
      free_frame_turns(*model, u, 1.0);
    ASSERT_EQ(turns.size(), 1u);
    bool a_twist = false;
    for (unsigned int c = 0; c < 12; ++c)
      a_twist = a_twist || turns[0] == model->layout().twist_dof(c);
    EXPECT_TRUE(a_twist);
  }

  TEST(FreeMotions, AnisotropicOrCurvedRingHoldsItsFrames)
  {
    // EI2 = 1.01 EI1: the turn changes the bending energy by about
    // 2 (EI2 - EI1) / EI1 of it; a natural curvature about d1 ties the
    // frames to the plane of the ring alike, and so does the curvature of
    // a ring stress free as built. A clamped rod holds its twist.
    auto anisotropic = held_ring(1.01);
    EXPECT_TRUE(
      free_frame_turns(*anisotropic, anisotropic->create_vector(), 1.0)
        .empty());
    auto curved = held_ring(1, 0.5);
    EXPECT_TRUE(
      free_frame_turns(*curved, curved->create_vector(), 1.0).empty());
    auto as_built = held_ring(1, 0, true);
    EXPECT_TRUE(
      free_frame_turns(*as_built, as_built->create_vector(), 1.0).empty());
    auto clamped = straight_rods();
    clamped->clamp_end("clamp", 0, true);
    clamped->finalize();
    EXPECT_TRUE(
      free_frame_turns(*clamped, clamped->create_vector(), 1.0).empty());
  }
} // namespace
