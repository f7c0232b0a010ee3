// The units of the residual's parts (ResidualCriterion): a quaternion
// residual is the moment it stands for, forces and moments get the scales
// of the loads and reactions (of the internal forces where the loads
// vanish), and the round-off floor tracks the stiffness of the stiffest
// segment.
#include <common/naturally_twisted_ring.h>
#include <common/rod_models.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <gtest/gtest.h>
#include <sstream>

namespace
{
  using namespace rodnet;

  /// A cantilever of length 1 along x (20 segments, EA = @p EA, EI = GJ =
  /// 1) clamped by a junction at its start, with a welded rotation handle
  /// "tip" at its end.
  std::unique_ptr<RodModel>
  cantilever_with_EA(const double EA = 1e4)
  {
    auto network = rodnet::testing::straight_network(20);
    network->add_junction("clamp", JunctionKind::clamped, {{0, true}});
    network->add_junction("tip", JunctionKind::welded, {{0, false}});
    return rodnet::testing::elastic_model(std::move(network),
                                          RodStiffness{EA, 1, 1, 1});
  }

  TEST(ResidualCriterion, QuaternionResidualIsTheAppliedMoment)
  {
    // Unloaded state, moment M at the tip: the residual is -M grad theta
    // on the handle's quaternion rows, 2 M in their own units, and M in
    // N m; the forces are zero.
    const double M     = 0.3;
    auto         model = cantilever_with_EA();
    model->add_moment(1, Vector3(0, 0.6, 0.8), M);
    model->finalize();
    const ResidualCriterion criterion(*model);
    const VectorType        u = model->create_vector();
    VectorType              r = model->create_vector();
    model->assemble(u, 1.0, &r, nullptr);
    const ResidualParts parts = criterion.norms(u, r);
    EXPECT_NEAR(parts.moment, M, 1e-12);
    EXPECT_NEAR(parts.force, 0, 1e-12);
    EXPECT_NEAR(r.l2_norm(), 2 * M, 1e-12);

    // No force, no reaction yet: the force scale is M / L and the moment
    // scale M (L the length scale of the model, 1 here).
    const ResidualParts scale = criterion.load_scale(u, 1.0);
    EXPECT_NEAR(scale.moment, M, 1e-12);
    EXPECT_NEAR(scale.force, M / model->length_scale(), 1e-12);
  }

  TEST(ResidualCriterion, ReactionsSetTheScaleOfATipForce)
  {
    // At the solved state of a tip force P the clamp carries P and P L:
    // the scales are P and P L, whatever the (tiny) deflection.
    const double P     = 1e-3;
    auto         model = cantilever_with_EA();
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           Vector3(0, 0, P));
    model->finalize();
    VectorType u = model->create_vector();
    StaticSolver(*model, StaticSolver::Parameters())
      .run(u, [](const auto &, const auto &) {});
    const ResidualCriterion criterion(*model);
    const ResidualParts     scale = criterion.load_scale(u, 1.0);
    EXPECT_NEAR(scale.force, P, 1e-9);
    EXPECT_NEAR(scale.moment, P * model->length_scale(), 1e-9);
  }

  TEST(ResidualCriterion, FloorGrowsWithTheAxialStiffness)
  {
    // A bent state (positions off the axes): the force noise is that of
    // strains rounded to eps |x| / l, times EA / l, so it grows in
    // proportion to EA; the estimate stays within an order of magnitude
    // of eps |x| EA / l times sqrt(n).
    for (const double EA : {1e4, 1e8})
      {
        auto model = cantilever_with_EA(EA);
        model->add_point_force(model->network().rods()[0].vertices.back(),
                               Vector3(0, 0.5, 0.5));
        model->finalize();
        VectorType u = model->create_vector();
        StaticSolver(*model, StaticSolver::Parameters())
          .run(u, [](const auto &, const auto &) {});
        const ResidualCriterion criterion(*model);
        const double floor    = criterion.roundoff_noise(u, 1.0).floor.force;
        const double l        = 1.0 / 20,
                     estimate = std::numeric_limits<double>::epsilon() * EA /
                                l * std::sqrt(20.0);
        std::cout << "EA = " << EA << ": force floor " << floor
                  << ", eps EA / l sqrt(n) " << estimate << std::endl;
        EXPECT_GT(floor, 0.1 * estimate);
        EXPECT_LT(floor, 10 * estimate);
      }
  }

  TEST(ResidualCriterion, StateBelowTheFloorIsNotAccepted)
  {
    // A floppy cantilever (L = 2000, 2000 segments, EA = 1e4, EI = 1) under
    // a tip force of 1e-9 N, below the force floor (about eps |x| EA / l
    // sqrt(n), 2e-7 N): its unloaded state passes the residual test at
    // iteration 0, but the Newton correction of that residual is of the
    // order of the floor times the compliance L^3 / 3 EI, 1e2 to 1e3 model
    // sizes, so the step must fail, naming where rounding weighs most.
    auto model = rodnet::testing::elastic_model(
      rodnet::testing::straight_network(2000,
                                        Vector3(0, 0, 0),
                                        Vector3(2000, 0, 0)),
      RodStiffness{1e4, 1, 1, 1});
    model->clamp_end("start", 0, true);
    model->add_point_force(2000, Vector3(0, 1e-9, 0));
    model->finalize();
    VectorType               u = model->create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = 1;
    std::ostringstream log;
    try
      {
        StaticSolver(*model, parameters, &log)
          .run(u, [](const auto &, const auto &) {
            ADD_FAILURE() << "a step was accepted";
          });
        ADD_FAILURE() << "no failure";
      }
    catch (const SolverFailure &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("the state at load factor 1.000000 is not "
                               "determined"),
                  std::string::npos)
          << message;
        EXPECT_NE(message.find("segment"), std::string::npos) << message;
      }
  }

  TEST(ResidualCriterion, InternalForcesOfABarThatCannotExpand)
  {
    // A straight bar of 10 segments pinned at both ends with an axial
    // eigenstrain eps0: it stays straight, every segment pushes with
    // N = EA eps0, and each inner vertex carries N from either side, 2 N
    // without signs (no bending, no twist). The reactions, N at each pin
    // (sqrt(2) N together), are the loads, and they do not vanish: the
    // scale stays theirs.
    const double    EA = 1e4, eps0 = 1e-3;
    RodNaturalShape natural;
    natural.axial_eigenstrain = eps0;
    auto              network = rodnet::testing::straight_network(10);
    const std::size_t n_rods  = network->rods().size();
    RodModel          model(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>(
        n_rods,
        std::make_shared<LinearElasticRod>(RodStiffness{EA, 1, 1, 1},
                                           natural)));
    model.fix_components("start", 0, {{true, true, true}});
    model.fix_components("end", 10, {{true, true, true}});
    model.finalize();
    const ResidualCriterion criterion(model);
    const VectorType        u        = model.create_vector();
    const ResidualParts     internal = criterion.internal_scale(u, 1.0);
    EXPECT_NEAR(internal.force, 2 * EA * eps0, 1e-12 * EA * eps0);
    EXPECT_NEAR(internal.moment,
                2 * EA * eps0 * model.length_scale(),
                1e-12 * EA * eps0);

    const ResidualParts loads = criterion.load_scale(u, 1.0);
    EXPECT_NEAR(loads.force, std::sqrt(2.0) * EA * eps0, 1e-12 * EA * eps0);
    const ResidualParts judged =
      criterion.judging_scale(u, 1.0, criterion.roundoff_noise(u, 1.0).floor);
    EXPECT_EQ(judged.force, loads.force);
    EXPECT_EQ(judged.moment, loads.moment);
  }

  TEST(ResidualCriterion, UnloadedPrestressedRingIsJudgedByItsInternalForces)
  {
    // The circle of a naturally twisted ring is an equilibrium without
    // loads: its supports carry rounding (3e-13 N), below the residual's
    // floor (6e-7 N), while its hinges and twists exert forces of order
    // EI / (R l) on every vertex and moments GJ tau0 on every twist. The
    // residual is judged against those, and far below them it shows
    // equilibrium by itself (not rounding-limited). Any applied load, even
    // one below the floor, keeps the loads' scales.
    const double tau0  = 0.99 * std::sqrt(3.0);
    const auto   model = rodnet::testing::naturally_twisted_ring(tau0);
    const ResidualCriterion criterion(*model);
    const VectorType        u     = model->create_vector();
    const ResidualParts     floor = criterion.roundoff_noise(u, 1.0).floor;
    const ResidualParts     loads = criterion.load_scale(u, 1.0);
    EXPECT_LT(loads.force, floor.force);
    const ResidualParts internal = criterion.internal_scale(u, 1.0);
    const ResidualParts judged   = criterion.judging_scale(u, 1.0, floor);
    EXPECT_EQ(judged.force, internal.force);
    EXPECT_EQ(judged.moment, internal.moment);
    // Each twist row carries the twisting moment GJ tau0 of the hinges on
    // either side of it; the vertices' hinge forces are larger.
    EXPECT_GE(internal.moment, 2 * tau0 * (1 - 1e-12));
    EXPECT_FALSE(ResidualCriterion::inconclusive(floor, judged, 1e-3));
    VectorType r = model->create_vector();
    model->assemble(u, 1.0, &r, nullptr);
    EXPECT_TRUE(ResidualCriterion::within(
      criterion.norms(u, r),
      ResidualCriterion::tolerance(judged, floor, 1e-9)));

    const auto loaded =
      rodnet::testing::naturally_twisted_ring(tau0, Vector3(0, 0, 1e-12));
    const ResidualCriterion loaded_criterion(*loaded);
    const ResidualParts     tiny =
      loaded_criterion
        .judging_scale(u, 1.0, loaded_criterion.roundoff_noise(u, 1.0).floor);
    EXPECT_EQ(tiny.force, loaded_criterion.load_scale(u, 1.0).force);
    EXPECT_LT(tiny.force, 1e-9);
  }

  TEST(ResidualCriterion, ClampsOfANaturallyCurvedBeamSetTheMomentScale)
  {
    // A straight beam of natural curvature k0 (EI = 1) clamped at both
    // ends is in equilibrium unloaded: each clamp holds the bending moment
    // EI k0 as a couple of its end segment's vertex forces, with no net
    // force. Nothing is applied, so the scales are those of the reactions:
    // the moment sqrt(2) EI k0 of the two clamps (the moment of a couple
    // about the support's first vertex, not its two vertex forces), and
    // the force that moment over the model's length (1).
    const double    k0 = 0.7;
    RodNaturalShape natural;
    natural.curvature1 = k0;
    auto model         = std::make_unique<RodModel>(
      rodnet::testing::straight_network(20),
      std::vector<std::shared_ptr<const RodMaterial>>{
        std::make_shared<LinearElasticRod>(RodStiffness{1e4, 1, 1, 1},
                                           natural)});
    model->clamp_end("start", 0, true);
    model->clamp_end("end", 0, false);
    model->finalize();
    const VectorType        u = model->create_vector();
    const ResidualCriterion criterion(*model);
    VectorType              r = model->create_vector();
    model->assemble(u, 1.0, &r, nullptr);
    EXPECT_LT(criterion.norms(u, r).force, 1e-12 * k0);
    const ResidualParts scale = criterion.load_scale(u, 1.0);
    EXPECT_NEAR(scale.moment, std::sqrt(2.0) * k0, 1e-10 * k0);
    EXPECT_NEAR(scale.force, scale.moment / model->length_scale(), 1e-12);
  }
} // namespace
