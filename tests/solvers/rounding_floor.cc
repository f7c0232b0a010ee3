// The rounding floor measured again where Newton stalls
// (ResidualCriterion::stall_aware_test()): a stall on noise above a floor
// measured at the step's start is accepted once the floor measured where
// Newton stands allows it; a stall above that floor is refused. And the
// case that needed it: P1 of BENCHMARKS.md (gravity cantilever, 1000
// segments) in one load step, against the elastica's tip.
#include <common/rod_models.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/statics/static_solver.h>

#include <bench/p1_problem.h>
#include <gtest/gtest.h>
#include <sstream>

namespace
{
  using namespace rodnet;

  /// A bent cantilever (20 segments, EA = 1e6) at its solved state: the
  /// force floor is well above zero there.
  struct BentCantilever
  {
    BentCantilever()
    {
      model =
        rodnet::testing::elastic_model(rodnet::testing::straight_network(20),
                                       RodStiffness{1e6, 1, 1, 1});
      model->clamp_end("start", 0, true);
      model->add_point_force(20, Vector3(0, 0.5, 0.5));
      model->finalize();
      u = model->create_vector();
      StaticSolver(*model, StaticSolver::Parameters())
        .run(u, [](const auto &, const auto &) {});
    }

    /// A residual of force norm @p force on a free vertex's y row.
    VectorType
    residual(const double force) const
    {
      VectorType r                         = model->create_vector();
      r[model->layout().vertex_dof(10, 1)] = force;
      return r;
    }

    std::unique_ptr<RodModel> model;
    VectorType                u;
  };

  /// What stall_aware_test() reads, for a step whose floor is @p noise and
  /// whose loads are negligible (the floor alone sets the tolerance).
  struct FloorOnlyStep
  {
    explicit FloorOnlyStep(const RoundoffNoise &start_noise)
        : noise(start_noise)
        , tolerance(ResidualCriterion::tolerance(scale, noise.floor, rtol))
        , step{noise, tolerance, scale, rtol, 1.0, nullptr}
    {
    }

    static constexpr double          rtol = 1e-12;
    const ResidualParts              scale{1e-30, 1e-30};
    RoundoffNoise                    noise;
    ResidualParts                    tolerance;
    ResidualCriterion::StepTolerance step;
    ResidualParts                    reached;
  };

  /// Calls @p test three times with the same residual (a stall) and
  /// returns the answers.
  std::vector<bool>
  stall(const std::function<bool(const VectorType &, const VectorType &)> &test,
        const VectorType                                                  &u,
        const VectorType                                                  &r)
  {
    std::vector<bool> answers;
    for (unsigned int i = 0; i < 3; ++i)
      answers.push_back(test(u, r));
    return answers;
  }

  TEST(StallAwareTest, AcceptsAStallWithinTheFloorWhereNewtonStands)
  {
    // The step's floor was measured a tenth of what it is here; Newton
    // stalls at half the floor of its iterate: refused twice, then, the
    // stall seen, the floor is measured again and the iterate accepted.
    BentCantilever          c;
    const ResidualCriterion criterion(*c.model);
    const RoundoffNoise     here = criterion.roundoff_noise(c.u, 1.0);
    ASSERT_GT(here.floor.force, 0);
    RoundoffNoise low = here;
    low.floor.force /= 10;
    low.floor.moment /= 10;
    FloorOnlyStep s(low);
    const auto    answers = stall(criterion.stall_aware_test(s.step, s.reached),
                               c.u,
                               c.residual(0.5 * here.floor.force));
    EXPECT_EQ(answers, (std::vector<bool>{false, false, true}));
    EXPECT_TRUE(s.step.measured_again);
    EXPECT_NEAR(s.tolerance.force, here.floor.force, 1e-12 * here.floor.force);
  }

  TEST(StallAwareTest, RefusesAStallAboveTheFloorWhereNewtonStands)
  {
    // The floor is right; Newton stalls at 100 times it (a wrong tangent,
    // a true non-convergence): measured again once, still refused.
    BentCantilever          c;
    const ResidualCriterion criterion(*c.model);
    FloorOnlyStep           s(criterion.roundoff_noise(c.u, 1.0));
    const double            floor = s.noise.floor.force;
    EXPECT_EQ(stall(criterion.stall_aware_test(s.step, s.reached),
                    c.u,
                    c.residual(100 * floor)),
              (std::vector<bool>{false, false, false}));
    EXPECT_TRUE(s.step.measured_again);
    EXPECT_NEAR(s.tolerance.force, floor, 1e-12 * floor);
    EXPECT_NEAR(s.reached.force, 100 * floor, 1e-12 * floor);
  }

  TEST(StallAwareTest, LeavesAFarResidualAlone)
  {
    // More than 1e3 times the tolerance is no rounding stall: the floor is
    // not measured again.
    BentCantilever          c;
    const ResidualCriterion criterion(*c.model);
    FloorOnlyStep           s(criterion.roundoff_noise(c.u, 1.0));
    EXPECT_EQ(stall(criterion.stall_aware_test(s.step, s.reached),
                    c.u,
                    c.residual(1e4 * s.noise.floor.force)),
              (std::vector<bool>{false, false, false}));
    EXPECT_FALSE(s.step.measured_again);
  }

  TEST(RoundingFloor, LoadBelowTheFloorIsSaidToBeUnresolved)
  {
    // A cantilever with every stiffness 1e9 under a tip force of 1e-5 N,
    // far below its force floor (~5e-3 N from EA eps |x| / l): the start's
    // residual, the load itself, is within the floor and the step is
    // accepted at iteration 0 with no deflection. That is the answer to
    // the rounding of the positions (P L^3 / (3 EI) = 3.3e-15 m, 15 ulps of
    // 1; a forced Newton step stalls on noise 1e3 times the load), but the
    // run must say that the loads are not resolved: once it said nothing.
    constexpr double P = 1e-5, stiffness = 1e9;
    auto             model = rodnet::testing::elastic_model(
      rodnet::testing::straight_network(40),
      RodStiffness{stiffness, stiffness, stiffness, stiffness});
    model->clamp_end("start", 0, true);
    model->add_point_force(40, Vector3(0, 0, -P));
    model->finalize();
    VectorType               u = model->create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = 1;
    std::ostringstream log;
    unsigned int       iterations = 0;
    StaticSolver(*model, parameters, &log)
      .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
        iterations += info.iterations;
      });
    EXPECT_LE(iterations, 1u);
    const double deflection = model->configuration().position(u, 40)[2];
    EXPECT_NEAR(deflection, -P / (3 * stiffness), 1e-14);
    EXPECT_NE(log.str().find("which this model's rounding does not resolve"),
              std::string::npos)
      << log.str();
  }

  TEST(RoundingFloor, P1WithAThousandSegmentsInOneLoadStep)
  {
    // Before the floor was measured again, this step stalled on noise 2-5
    // times the start's floor, was cut four times and took 25 iterations.
    // The tip is ~3.4e-5 from the inextensible elastica's (EA = 7854 N,
    // bench/p1_problem.h): within 1e-4.
    auto                     model = bench::p1::rod_model(1001);
    VectorType               u     = model->create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = 1;
    unsigned int steps = 0, iterations = 0;
    StaticSolver(*model, parameters)
      .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
        ++steps;
        iterations += info.iterations;
      });
    EXPECT_EQ(steps, 1u);
    EXPECT_LE(iterations, 12u);
    const Vector3 tip =
      model->configuration().position(u, bench::p1::tip(*model));
    EXPECT_NEAR(tip[0], bench::p1::x_exact, 1e-4);
    EXPECT_NEAR(tip[2], bench::p1::z_exact, 1e-4);
  }
} // namespace
