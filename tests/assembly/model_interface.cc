// The model interface (core/model.h): one specification of supports and
// loads lowered onto a RodModel and a DrModel, probes evaluated through the
// interface on both, the lumping of distributed loads, and the refusal of
// supports and loads added after finalize(). References: statics (the
// reactions balance the loads), the Voronoi lumping q h / 2 at rod ends and
// q h inside, the bounding-box diagonal.
#include <core/dr_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <io/probes.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/relaxation/dynamic_relaxation.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>

namespace
{
  using namespace rodnet;

  const unsigned int n_interface_segments = 10;
  const RodStiffness interface_stiffness{1e4, 1, 2, 1};

  /// A straight rod from the origin to (1, 0, 0.5) of 10 segments, d1 = e_z.
  std::unique_ptr<RodNetwork>
  straight_rod()
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0.5),
                                          n_interface_segments),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    return network;
  }

  std::unique_ptr<RodModel>
  rod_model()
  {
    return std::make_unique<RodModel>(
      straight_rod(),
      std::vector<std::shared_ptr<const RodMaterial>>{
        std::make_shared<LinearElasticRod>(interface_stiffness)});
  }

  std::unique_ptr<DrModel>
  dr_model()
  {
    return std::make_unique<DrModel>(straight_rod(),
                                     std::vector<RodStiffness>{
                                       interface_stiffness});
  }

  /// A cantilever clamped at its start under a tip force and a weight.
  SupportsAndLoads
  cantilever_supports(const Vector3 &tip_force,
                      const Vector3 &weight_per_length)
  {
    SupportsAndLoads spec;
    spec.clamps.push_back({"clamp", RodEnd{0, true}});
    spec.point_forces.push_back({n_interface_segments, tip_force});
    spec.distributed_forces.push_back({0, weight_per_length});
    return spec;
  }

  /// The reaction of "clamp" and the tip position through the interface.
  template <class State>
  std::vector<double>
  clamp_reaction_and_tip(const Model<State> &model, const State &u)
  {
    // The clamp holds the first vertex.
    const ProbeList probes = parse_probes(
      "R0: reaction start x; R1: reaction start y; R2: reaction start z; "
      "tip: position end z",
      model,
      "test");
    return evaluate_probes(probes, model, u, 1.0);
  }

  // Lumping: a rod of 10 segments of length h under q gets q h / 2 at its
  // ends and q h at every inner vertex, q L in total, with the point force
  // on top at its vertex.
  TEST(DeadLoads, VoronoiLumping)
  {
    const auto    network = straight_rod();
    const Vector3 q(0.5, -2, 3), point(0, 1, 0);
    DeadLoads     loads;
    loads.add_distributed_force(*network, 0, q);
    loads.add_point_force(*network, 4, point);
    const std::vector<Vector3> forces = loads.vertex_forces(*network);
    const double               h      = std::sqrt(1.25) / n_interface_segments;
    ASSERT_EQ(forces.size(), n_interface_segments + 1);
    for (unsigned int v = 0; v <= n_interface_segments; ++v)
      {
        const double  share = (v == 0 || v == n_interface_segments) ? 0.5 : 1.0;
        const Vector3 expected =
          share * h * q + (v == 4 ? point : Vector3(Vector3::Zero()));
        EXPECT_LT((forces[v] - expected).norm(), 1e-14) << "vertex " << v;
      }
  }

  // One specification, both models: at the undeformed state (no internal
  // forces) the clamp's reaction is minus the load it holds, q h / 2 of the
  // DrModel's clamped node, 3 q h / 2 of the RodModel's two clamped
  // vertices; once solved, minus the whole load (statics). The length scale
  // is the diagonal of the bounding box, sqrt(1.25).
  TEST(ModelInterface, SameSpecificationOnBothModels)
  {
    const Vector3 P(0, 1e-4, -2e-4), q(0, 0, -1e-4);
    const double  L = std::sqrt(1.25), h = L / n_interface_segments;
    const Vector3 total = P + L * q;

    auto rods = rod_model();
    rods->apply(cantilever_supports(P, q));
    rods->finalize();
    auto relaxed = dr_model();
    relaxed->apply(cantilever_supports(P, q));
    relaxed->finalize();
    EXPECT_NEAR(rods->length_scale(), L, 1e-15);
    EXPECT_NEAR(relaxed->length_scale(), L, 1e-15);

    VectorType                u        = rods->create_vector();
    DrVector                  ud       = relaxed->create_vector();
    const std::vector<double> rest_rod = clamp_reaction_and_tip(*rods, u);
    const std::vector<double> rest_dr  = clamp_reaction_and_tip(*relaxed, ud);
    for (unsigned int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(rest_rod[c], -1.5 * h * q[c], 1e-11) << c;
        EXPECT_NEAR(rest_dr[c], -0.5 * h * q[c], 1e-11) << c;
      }
    EXPECT_NEAR(rest_rod[3], 0.5, 1e-15);
    EXPECT_NEAR(rest_dr[3], 0.5, 1e-15);

    StaticSolver::Parameters newton;
    StaticSolver(*rods, newton).run(u, [](const auto &, const auto &) {});
    DynamicRelaxation(*relaxed, {}).run(ud, [](const auto &, const auto &) {});
    const std::vector<double> rod = clamp_reaction_and_tip(*rods, u);
    const std::vector<double> dr  = clamp_reaction_and_tip(*relaxed, ud);
    for (unsigned int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(rod[c], -total[c], 1e-8 * total.norm()) << c;
        // Dynamic relaxation stops at a residual of 1e-6 of the load.
        EXPECT_NEAR(dr[c], -total[c], 1e-5 * total.norm()) << c;
      }
  }

  // What the element cannot represent is refused with one message.
  TEST(ModelInterface, DynamicRelaxationRefusesRotationalLoads)
  {
    SupportsAndLoads spec =
      cantilever_supports(Vector3::UnitY(), Vector3::Zero());
    spec.moments.push_back(
      {"tip", n_interface_segments, {}, Vector3::UnitZ(), 1.0});
    try
      {
        dr_model()->apply(spec);
        FAIL() << "a moment was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find(
                    "act on junction quaternions, which the dynamic "
                    "relaxation element does not have"),
                  std::string::npos)
          << e.what();
      }
  }

  /// Expects @p add to throw std::logic_error naming @p what and
  /// finalize().
  template <class Add>
  void
  expect_refused_after_finalize(const Add &add, const std::string &what)
  {
    try
      {
        add();
        ADD_FAILURE() << what << " after finalize() was accepted";
      }
    catch (const std::logic_error &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find(what), std::string::npos) << message;
        EXPECT_NE(message.find("after finalize()"), std::string::npos)
          << message;
      }
  }

  /// Expects the supports and loads of the interface added to the
  /// finalized @p model to be refused.
  template <class State>
  void
  expect_refused_after_finalize(Model<State> &model)
  {
    expect_refused_after_finalize([&] { model.clamp_end("late", 0, true); },
                                  "clamp_end \"late\"");
    expect_refused_after_finalize(
      [&] {
        model.fix_components("pin", 3, {{true, true, true}}, Vector3::Zero());
      },
      "fix_components \"pin\"");
    expect_refused_after_finalize(
      [&] { model.add_point_force(3, Vector3::Zero()); },
      "add_point_force at vertex 3");
    expect_refused_after_finalize(
      [&] { model.add_distributed_force(0, Vector3::Zero()); },
      "add_distributed_force on rod 0");
  }

  // A support or load added after finalize() would never be applied.
  TEST(ModelInterface, RefusesSupportsAndLoadsAfterFinalize)
  {
    auto rods = rod_model();
    rods->finalize();
    expect_refused_after_finalize(*rods);
    expect_refused_after_finalize(
      [&] { rods->rotate_clamp("late", Vector3::UnitZ(), 1); },
      "rotate_clamp");
    expect_refused_after_finalize(
      [&] { rods->add_moment(0, Vector3::UnitZ(), 1); },
      "add_moment");

    auto relaxed = dr_model();
    relaxed->finalize();
    expect_refused_after_finalize(*relaxed);
  }

  // A matrix made before finalize() has no pattern: a tangent assembled
  // into it would lose every entry (an inertia of no negative eigenvalue).
  TEST(ModelInterface, RefusesAMatrixBeforeFinalize)
  {
    auto       rods = rod_model();
    MatrixType matrix;
    try
      {
        rods->initialize_matrix(matrix);
        FAIL() << "a matrix before finalize() was made";
      }
    catch (const std::logic_error &e)
      {
        EXPECT_NE(std::string(e.what()).find(
                    "RodModel::initialize_matrix before finalize()"),
                  std::string::npos)
          << e.what();
      }
    rods->finalize();
    rods->initialize_matrix(matrix);
    EXPECT_EQ(matrix.m(), rods->layout().n_dofs());
  }
} // namespace
