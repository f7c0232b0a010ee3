// ArclengthContinuation on a small column, against independent references:
// the bifurcation it locates on the straight branch equals the critical load
// that load stepping's bisection on the tangent's inertia finds (another way
// to the same discrete Euler load); every point it reports is an equilibrium
// (its residual against the load), and it lands on the output load factors
// exactly; after the switch the column is buckled and stable. Too few points
// stop the run with a message naming the entry; a load factor range without
// 0 is refused.
#include <common/held_bar.h>
#include <common/rod_models.h>
#include <materials/standard_linear_solid.h>
#include <solvers/checks/free_motions.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <tuple>
#include <vector>

namespace
{
  using namespace rodnet;

  /// A column of length 1 along x in 20 segments (EI1 = 1, EI2 = 2,
  /// EA = 1e5), clamped at its start, under the end load @p P along -x at
  /// load factor 1.
  std::unique_ptr<RodModel>
  loaded_column(const double P, const double EI2 = 2)
  {
    auto model = rodnet::testing::elastic_model(
      rodnet::testing::straight_network(20,
                                        Vector3(0, 0, 0),
                                        Vector3(1, 0, 0),
                                        true),
      RodStiffness{1e5, 1, EI2, 1});
    model->clamp_end("clamp", 0, true);
    model->add_point_force(model->network().n_vertices() - 1,
                           Vector3(-P, 0, 0));
    model->finalize();
    return model;
  }

  ArclengthContinuation::Parameters
  up_to(const double upper_limit)
  {
    ArclengthContinuation::Parameters p;
    p.upper_limit  = upper_limit;
    p.initial_step = 0.1;
    return p;
  }

  TEST(ArclengthContinuation, BifurcationIsLoadSteppingsCriticalLoad)
  {
    const auto               stepped = loaded_column(3);
    StaticSolver::Parameters s;
    s.n_steps                 = 6;
    s.find_critical_load      = true;
    s.track_lowest_eigenvalue = true;
    s.critical_load_tolerance = 1e-10;
    StaticSolver solver(*stepped, s);
    VectorType   u = stepped->create_vector();
    solver.run(u, [](const StaticSolver::StepInfo &, const VectorType &) {});
    const double critical = 3 * solver.critical_load_factor();
    ASSERT_TRUE(std::isfinite(critical));

    const auto                        followed = loaded_column(1);
    ArclengthContinuation::Parameters p        = up_to(3);
    p.switch_branches                          = false;
    ArclengthContinuation continuation(*followed, p);
    VectorType            v        = followed->create_vector();
    unsigned int          unstable = 0;
    continuation.run(
      v,
      [&](const ArclengthContinuation::StepInfo &info, const VectorType &) {
        unstable += !info.check.stable;
        EXPECT_EQ(info.check.stable, info.load_factor < critical + 1e-6)
          << "load factor " << info.load_factor;
      });
    ASSERT_EQ(continuation.bifurcations().size(), 1u);
    EXPECT_NEAR(continuation.bifurcations()[0], critical, 1e-7 * critical);
    EXPECT_GT(unstable, 0u); // it stayed on the straight branch
    EXPECT_NEAR(critical, M_PI * M_PI / 4, 1e-3 * critical);
  }

  TEST(ArclengthContinuation, PointsAreEquilibriaAndLandOnOutputs)
  {
    const auto                        model = loaded_column(1);
    ArclengthContinuation::Parameters p     = up_to(3);
    p.output_points                         = {2.6, 2.8};
    ArclengthContinuation continuation(*model, p);
    VectorType            u = model->create_vector();
    VectorType            r = model->create_vector();
    std::vector<double>   landed;
    const unsigned int    tip             = model->network().n_vertices() - 1;
    double                last_deflection = 0;
    continuation.run(u,
                     [&](const ArclengthContinuation::StepInfo &info,
                         const VectorType                      &x) {
                       model->assemble(x, info.load_factor, &r, nullptr);
                       // Forces of order the load (1) and moments of order
                       // the load times the length (1).
                       EXPECT_LT(r.l2_norm(), 1e-7)
                         << "load factor " << info.load_factor;
                       if (info.load_factor == 2.6 || info.load_factor == 2.8)
                         landed.push_back(info.load_factor);
                       EXPECT_TRUE(info.check.stable);
                       last_deflection = model->position(x, tip).norm();
                       if (info.branch == 1)
                         {
                           EXPECT_GT(std::hypot(model->position(x, tip)[1],
                                                model->position(x, tip)[2]),
                                     0.01);
                         }
                     });
    EXPECT_EQ(landed, (std::vector<double>{2.6, 2.8}));
    ASSERT_EQ(continuation.bifurcations().size(), 1u);
    EXPECT_LT(last_deflection, 1); // buckled: the tip came closer
  }

  TEST(ArclengthContinuation, IsotropicColumnBucklesStably)
  {
    // EI1 = EI2: the buckled column's plane may turn about the load axis
    // (one symmetry mode, whose eigenvalue is rounding of either sign). The
    // path switches at the bifurcation (two modes cross there), counts
    // every buckled point stable, and keeps its plane: the mode is left out
    // of the steps.
    const auto            model = loaded_column(1, 1);
    ArclengthContinuation continuation(*model, up_to(3));
    VectorType            u   = model->create_vector();
    const unsigned int    tip = model->network().n_vertices() - 1;
    std::vector<double>   planes;
    continuation.run(u,
                     [&](const ArclengthContinuation::StepInfo &info,
                         const VectorType                      &x) {
                       EXPECT_TRUE(info.check.stable)
                         << "load factor " << info.load_factor;
                       const Vector3 p = model->position(x, tip);
                       if (info.branch == 1)
                         planes.push_back(std::atan2(p[2], p[1]));
                     });
    ASSERT_EQ(continuation.bifurcations().size(), 1u);
    ASSERT_GT(planes.size(), 3u);
    for (const double plane : planes)
      EXPECT_NEAR(plane, planes.front(), 1e-6);
    // At the last point (load factor 3): one symmetry mode, none with
    // EI2 = 2 at the same load.
    EXPECT_EQ(symmetry_modes(*model, u, 3).size(), 1u);
    const auto            anisotropic = loaded_column(1, 2);
    ArclengthContinuation other(*anisotropic, up_to(3));
    VectorType            v = anisotropic->create_vector();
    other.run(v,
              [](const ArclengthContinuation::StepInfo &, const VectorType &) {
              });
    EXPECT_EQ(symmetry_modes(*anisotropic, v, 3).size(), 0u);
  }

  TEST(ArclengthContinuation, StraightIsotropicColumnStaysUnstable)
  {
    // Without the switch, the straight column past P_cr = pi^2/4 has two
    // buckling modes (either plane) below zero; the check for symmetry
    // modes must not hide them (a straight rod turned about its line moves
    // no DoF: no mode there).
    const auto                        model = loaded_column(1, 1);
    ArclengthContinuation::Parameters p     = up_to(3);
    p.switch_branches                       = false;
    ArclengthContinuation continuation(*model, p);
    VectorType            u    = model->create_vector();
    unsigned int          past = 0;
    continuation.run(u,
                     [&](const ArclengthContinuation::StepInfo &info,
                         const VectorType &) {
                       if (info.load_factor > 2.5)
                         {
                           EXPECT_EQ(info.check.negative_eigenvalues, 2u);
                           ++past;
                         }
                     });
    EXPECT_GT(past, 0u);
    EXPECT_TRUE(symmetry_modes(*model, u, 3).empty());
  }

  TEST(ArclengthContinuation, TooFewPointsStopWithTheirEntry)
  {
    const auto                        model = loaded_column(1);
    ArclengthContinuation::Parameters p     = up_to(3);
    p.max_steps                             = 3;
    ArclengthContinuation continuation(*model, p);
    VectorType            u = model->create_vector();
    try
      {
        continuation.run(u,
                         [](const ArclengthContinuation::StepInfo &,
                            const VectorType &) {});
        FAIL() << "no SolverFailure";
      }
    catch (const SolverFailure &e)
      {
        EXPECT_NE(std::string(e.what()).find("Max points"), std::string::npos)
          << e.what();
      }
  }

  TEST(ArclengthContinuation, ViscoelasticMaterialIsRefused)
  {
    // A path of equilibria has no time for a rate-dependent material.
    auto model = rodnet::testing::held_bar(
      std::make_shared<StandardLinearSolid>(RodStiffness{1, 1, 1, 1}, 0.3, 1),
      10,
      Vector3(0, 0.1, 0));
    try
      {
        ArclengthContinuation continuation(*model, up_to(1));
        FAIL() << "accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("internal variables"),
                  std::string::npos)
          << e.what();
      }
  }

  TEST(ArclengthContinuation, RangeWithoutZeroOrOutputsOutsideIsRefused)
  {
    // A range that does not hold the start, and an output point the path
    // cannot reach (it would silently never be written).
    for (const auto &[range, outputs, entry] :
         {std::tuple{"0.5, 1", "", "Load factor range"},
          std::tuple{"-1, 1", "0.5, 1.5", "Output load factors"}})
      {
        dealii::ParameterHandler prm;
        ArclengthContinuation::Parameters::declare_parameters(prm);
        prm.set("Load factor range", range);
        prm.set("Output load factors", outputs);
        ArclengthContinuation::Parameters p;
        try
          {
            p.parse_parameters(prm);
            ADD_FAILURE() << "accepted " << range << " / " << outputs;
          }
        catch (const std::invalid_argument &e)
          {
            EXPECT_NE(std::string(e.what()).find(entry), std::string::npos)
              << e.what();
          }
      }
  }
} // namespace
