// The dynamic-relaxation beam (DrModel, DynamicRelaxation) against beam
// theory: a cantilever under a small tip load in and out of the plane of
// its normals against P L^3 / (3 EI), the post-buckled elastica against
// the exact elliptic-integral solution, and a time step far above the
// stability limit, which must be cut rather than produce NaN.
#include <common/bent_dr_network.h>
#include <common/elastica_exact.h>
#include <core/dr_model.h>
#include <geometry/rod_generators.h>
#include <solvers/relaxation/dynamic_relaxation.h>

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <map>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// Adds a straight rod from @p a to @p b of @p n elements to @p network.
  void
  add_straight_rod(RodNetwork        &network,
                   const Vector3     &a,
                   const Vector3     &b,
                   const unsigned int n,
                   const Vector3     &director_hint = Vector3::UnitZ())
  {
    network.add_rod(generators::straight(a, b, n),
                    false,
                    director_hint,
                    "simple");
  }

  /// A rod from the origin to (1, 0, 0) in @p n elements with normals e_z.
  std::unique_ptr<RodNetwork>
  straight_rod(const unsigned int n)
  {
    auto network = std::make_unique<RodNetwork>();
    add_straight_rod(*network, Vector3(0, 0, 0), Vector3(1, 0, 0), n);
    return network;
  }

  double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }

  // Tip load P = 1e-4 along e_y bends about the normals (EI1, the turn
  // strains) and along e_z towards them (EI2, the tilts); EI1 = 1 and
  // EI2 = 2 so that a swapped rigidity shows. Clamped by one node.
  TEST(DrCantilever, SmallDeflectionMatchesBeamTheory)
  {
    const unsigned int n = 20;
    const double       P = 1e-4, EI1 = 1, EI2 = 2;
    for (const unsigned int direction : {1u, 2u})
      {
        DrModel model(straight_rod(n), {RodStiffness{1e4, EI1, EI2, 1}});
        model.clamp_end("clamp", 0, true);
        const unsigned int tip = model.network().rods()[0].vertices.back();
        model.add_point_force(tip, P * Vector3::Unit(direction));
        model.finalize();

        DrVector                      u = model.create_vector();
        DynamicRelaxation::Parameters parameters;
        const auto                    start = std::chrono::steady_clock::now();
        const auto result = DynamicRelaxation(model, parameters)
                              .run(u, [](const auto &, const auto &) {});
        const double  time       = seconds_since(start);
        const double  EI         = direction == 1 ? EI1 : EI2;
        const double  exact      = P / (3 * EI);
        const double  deflection = model.position(u, tip)[direction];
        const Vector3 reaction = model.reaction(model.support("clamp"), u, 1.0);
        std::cout << "tip load along e_" << direction << ", N = " << n
                  << ": deflection " << deflection << ", P L^3/(3 EI) " << exact
                  << ", relative error " << (deflection - exact) / exact << "; "
                  << result.total_iterations << " iterations, " << time
                  << " s; clamp reaction " << reaction.transpose() << std::endl;
        EXPECT_NEAR(deflection, exact, 0.01 * exact);
        EXPECT_NEAR(reaction[direction], -P, 1e-3 * P);
        EXPECT_EQ(result.time_step_cuts, 0u);
      }
  }

  // Clamped-free elastica, B = L = 1, dead compressive end load ramped to
  // P = 5 in five steps, with a transverse imperfection force 1e-4 P
  // (EA = 1e4: axial strain 5e-4 at P = 5); the tips at P = 3 and P = 5
  // within 0.01 L of the exact solution, closer at N = 40 than at N = 20.
  TEST(DrCantilever, PostBuckledElasticaMatchesExact)
  {
    const double P_max             = 5;
    double       previous_error[2] = {INFINITY, INFINITY};
    for (const unsigned int n : {20u, 40u})
      {
        DrModel model(straight_rod(n), {RodStiffness{1e4, 1, 1, 1}});
        model.clamp_end("clamp", 0, true);
        const unsigned int tip = model.network().rods()[0].vertices.back();
        model.add_point_force(tip, Vector3(-P_max, 1e-4 * P_max, 0));
        model.finalize();

        DrVector                      u = model.create_vector();
        DynamicRelaxation::Parameters parameters;
        parameters.n_steps = 5;
        std::map<int, ElasticaTip> computed;
        const auto                 start = std::chrono::steady_clock::now();
        const auto                 result =
          DynamicRelaxation(model, parameters)
            .run(u, [&](const auto &info, const DrVector &x) {
              const Vector3 p = model.position(x, tip);
              computed[std::lround(info.load_factor * P_max)] =
                {p[0], std::hypot(p[1], p[2])};
              std::cout << "N = " << n << ", P = " << info.load_factor * P_max
                        << ": " << info.iterations << " iterations, "
                        << info.peaks << " peaks, " << info.wall_time << " s"
                        << std::endl;
            });
        std::cout << "N = " << n << ": " << result.total_iterations
                  << " iterations in " << seconds_since(start) << " s"
                  << std::endl;
        EXPECT_EQ(result.time_step_cuts, 0u);
        for (const int i : {0, 1})
          {
            const int         P     = i == 0 ? 3 : 5;
            const ElasticaTip exact = elastica_tip(P);
            const double      error =
              std::max(std::abs(computed[P].x - exact.x),
                       std::abs(computed[P].delta - exact.delta));
            std::cout << "N = " << n << ", P = " << P << ": tip ("
                      << computed[P].x << ", " << computed[P].delta
                      << "), exact (" << exact.x << ", " << exact.delta
                      << "), error " << error << std::endl;
            EXPECT_LT(error, 0.01) << "P = " << P;
            EXPECT_LT(error, previous_error[i]) << "P = " << P;
            previous_error[i] = error;
          }
      }
  }

  // Time step 10 where the masses allow sqrt(2): the step must be cut and
  // then converge to the answer; with cuts forbidden, a SolverFailure that
  // names the time step, and the last converged (finite) state.
  TEST(DrCantilever, TimeStepAboveStabilityLimitIsCut)
  {
    const unsigned int n = 20;
    const double       P = 1e-4;
    DrModel            model(straight_rod(n), {RodStiffness{1e4, 1, 1, 1}});
    model.clamp_end("clamp", 0, true);
    const unsigned int tip = model.network().rods()[0].vertices.back();
    model.add_point_force(tip, Vector3(0, P, 0));
    model.finalize();

    DynamicRelaxation::Parameters parameters;
    parameters.time_step = 10;
    DrVector   u         = model.create_vector();
    const auto result    = DynamicRelaxation(model, parameters, &std::cout)
                          .run(u, [](const auto &, const auto &) {});
    const double deflection = model.position(u, tip)[1];
    std::cout << result.time_step_cuts << " cuts to time step "
              << result.time_step << ", deflection " << deflection << std::endl;
    EXPECT_GT(result.time_step_cuts, 0u);
    EXPECT_LE(result.time_step, std::sqrt(2.0));
    EXPECT_NEAR(deflection, P / 3, 0.01 * P / 3);

    parameters.min_time_step_fraction = 0.5;
    u                                 = 0;
    try
      {
        DynamicRelaxation(model, parameters)
          .run(u, [](const auto &, const auto &) {});
        ADD_FAILURE() << "no SolverFailure";
      }
    catch (const SolverFailure &e)
      {
        std::cout << "expected failure: " << e.what() << std::endl;
        EXPECT_NE(std::string(e.what()).find("time step"), std::string::npos);
      }
    EXPECT_TRUE(std::isfinite(u.l2_norm()));
    EXPECT_EQ(u.l2_norm(), 0.0);
  }
  // A tip displacement prescribed along e_y, ramped in two steps: the
  // support force is 3 EI delta / L^3 and the clamp balances it.
  TEST(DrCantilever, PrescribedTipDisplacementReaction)
  {
    const double delta = 1e-3;
    DrModel      model(straight_rod(20), {RodStiffness{1e4, 1, 2, 1}});
    model.clamp_end("clamp", 0, true);
    const unsigned int tip = model.network().rods()[0].vertices.back();
    model.fix_components("tip",
                         tip,
                         {{false, true, false}},
                         delta * Vector3::UnitY());
    model.finalize();

    DrVector                      u = model.create_vector();
    DynamicRelaxation::Parameters parameters;
    parameters.n_steps = 2;
    DynamicRelaxation(model, parameters).run(u, [](const auto &, const auto &) {
    });
    const double force = model.reaction(model.support("tip"), u, 1.0)[1];
    const double clamp = model.reaction(model.support("clamp"), u, 1.0)[1];
    std::cout << "tip force " << force << ", 3 EI delta / L^3 " << 3 * delta
              << ", relative error " << (force - 3 * delta) / (3 * delta)
              << "; clamp " << clamp << std::endl;
    EXPECT_NEAR(model.position(u, tip)[1], delta, 1e-15);
    EXPECT_NEAR(force, 3 * delta, 0.01 * 3 * delta);
    EXPECT_NEAR(clamp, -force, 1e-4 * force);
  }

  // A uniform load q along e_z (a weight, mass per length times g) lumped to
  // the nodes: tip deflection q L^4 / (8 EI2); the lumping misses the end
  // moment q h^2 / 12 of the consistent load, a relative error h^2 / 3.
  TEST(DrCantilever, UniformLoadMatchesBeamTheory)
  {
    const double q = 1e-4, EI2 = 2;
    DrModel      model(straight_rod(20), {RodStiffness{1e4, 1, EI2, 1}});
    model.clamp_end("clamp", 0, true);
    model.add_distributed_force(0, 1e-5 * Vector3(0, 0, q / 1e-5));
    model.finalize();

    DrVector u = model.create_vector();
    DynamicRelaxation(model, {}).run(u, [](const auto &, const auto &) {});
    const unsigned int tip   = model.network().rods()[0].vertices.back();
    const double       exact = q / (8 * EI2);
    const double       w     = model.position(u, tip)[2];
    std::cout << "tip deflection " << w << ", q L^4/(8 EI) " << exact
              << ", relative error " << (w - exact) / exact << std::endl;
    EXPECT_NEAR(w, exact, 0.01 * exact);
    EXPECT_NEAR(model.reaction(model.support("clamp"), u, 1.0)[2],
                -q,
                1e-3 * q);
  }

  /// A beam from (0, 0, 0) to (1, 0, 0) of two rods of @p n elements,
  /// clamped at both ends, joined at the middle by a junction of kind
  /// @p kind; returns the deflection of the middle under a small force
  /// P along e_@p direction there.
  double
  clamped_beam_deflection(const JunctionKind kind,
                          const unsigned int direction,
                          const unsigned int n,
                          const double       P)
  {
    auto        owned   = std::make_unique<RodNetwork>();
    RodNetwork &network = *owned; // owned by the model from its construction
    add_straight_rod(network, Vector3(0, 0, 0), Vector3(0.5, 0, 0), n);
    add_straight_rod(network, Vector3(0.5, 0, 0), Vector3(1, 0, 0), n);
    network.add_junction("middle", kind, {{0, false}, {1, true}});
    const RodStiffness k{1e4, 1, 2, 1};
    DrModel            model(std::move(owned), {k, k});
    model.clamp_end("left", 0, true);
    model.clamp_end("right", 1, false);
    const unsigned int middle = network.named_vertex("middle");
    model.add_point_force(middle, P * Vector3::Unit(direction));
    model.finalize();
    DrVector u = model.create_vector();
    DynamicRelaxation(model, {}).run(u, [](const auto &, const auto &) {});
    return model.position(u, middle)[direction];
  }

  // A welded middle junction carries the moment: the clamped-clamped beam,
  // P L^3 / (192 EI). A pinned one does not: two cantilevers of length L/2
  // with tip loads P/2, P L^3 / (48 EI). In and out of the normals' plane.
  TEST(DrCantilever, WeldedAndPinnedJunctions)
  {
    const double P = 1e-4;
    for (const unsigned int direction : {1u, 2u})
      {
        const double EI = direction == 1 ? 1 : 2;
        const double welded =
          clamped_beam_deflection(JunctionKind::welded, direction, 10, P);
        const double pinned =
          clamped_beam_deflection(JunctionKind::pinned, direction, 10, P);
        const double exact_w = P / (192 * EI), exact_p = P / (48 * EI);
        std::cout << "e_" << direction << ": welded " << welded << " (exact "
                  << exact_w << "), pinned " << pinned << " (exact " << exact_p
                  << ")" << std::endl;
        EXPECT_NEAR(welded, exact_w, 0.01 * exact_w);
        EXPECT_NEAR(pinned, exact_p, 0.01 * exact_p);
      }
  }

  // The residual is the gradient of the energy, anchors, welded and pinned
  // junctions, far nodes and loads included: central differences on a
  // bent network of four rods at a random state.
  TEST(DrModelDerivatives, ResidualIsEnergyGradient)
  {
    const std::unique_ptr<DrModel> owned = bent_dr_network();
    const DrModel                 &model = *owned;

    DrVector u = model.create_vector();
    std::srand(7);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = 0.05 * (2.0 * std::rand() / RAND_MAX - 1);
    const double load_factor = 0.7;
    DrVector     r;
    model.residual(u, load_factor, r);
    double error = 0;
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        const double h       = 1e-6;
        DrVector     shifted = u;
        shifted[i] += h;
        const double plus = model.energy(shifted, load_factor);
        shifted[i] -= 2 * h;
        const double minus = model.energy(shifted, load_factor);
        error = std::max(error, std::abs(r[i] - (plus - minus) / (2 * h)));
      }
    std::cout << model.n_dofs() << " DoFs, max |r - dE/du| " << error
              << ", max |r| " << r.linfty_norm() << std::endl;
    EXPECT_LT(error, 1e-6 * std::max(1.0, r.linfty_norm()));
  }
  // Inputs the model cannot represent are refused with the place named: a
  // normal in the xy plane (the element's n_z = sqrt(1 - n_x^2 - n_y^2) is
  // singular there) and a stiffness count that does not match the rods.
  TEST(DrModelInput, RefusesWhatItCannotRepresent)
  {
    const auto in_plane_rod = [] {
      auto network = std::make_unique<RodNetwork>();
      add_straight_rod(*network,
                       Vector3(0, 0, 0),
                       Vector3(1, 0, 0),
                       4,
                       Vector3::UnitY());
      return network;
    };
    const RodStiffness k{1, 1, 1, 1};
    try
      {
        DrModel model(in_plane_rod(), {k});
        ADD_FAILURE() << "a normal in the xy plane was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        std::cout << e.what() << std::endl;
        EXPECT_NE(std::string(e.what()).find("rod 0, vertex 0"),
                  std::string::npos);
      }
    EXPECT_THROW(DrModel(in_plane_rod(), {k, k}), std::invalid_argument);
  }
} // namespace
