// The checks of every converged state against independent references: the
// inertia of the tangent of a straight column counts its Euler modes below
// the load (stable below the first, 14 negative eigenvalues at 200 times
// it); the axial strain of a bar is F / EA; the bending strain of a rod
// bent by an end moment is M r / EI; strains past the rod model's range are
// named in a warning.
#include <common/rod_models.h>
#include <common/scene_text.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/stability/stability.h>
#include <solvers/statics/static_solver.h>
#include <solvers/time/time_integrator.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <vector>

namespace
{
  using namespace rodnet;

  constexpr double EA = 1e4, EI = 1;

  /// A rod of length 1 along x in @p n segments, clamped at its start by
  /// its first two vertices and twist; with a welded junction "tip" at its
  /// end if @p handle.
  std::unique_ptr<RodModel>
  cantilever(const unsigned int n, const bool handle = false)
  {
    auto network = rodnet::testing::straight_network(n,
                                                     Vector3(0, 0, 0),
                                                     Vector3(1, 0, 0),
                                                     true);
    if (handle)
      network->add_junction("tip", JunctionKind::welded, {{0, false}});
    auto model = rodnet::testing::elastic_model(std::move(network),
                                                RodStiffness{EA, EI, EI, EI});
    model->clamp_end("clamp", 0, true);
    return model;
  }

  /// The last converged step of a one-step solve of @p model, with the
  /// solver's log in @p log.
  StaticSolver::StepInfo
  solve(RodModel                       &model,
        std::ostringstream             &log,
        const StaticSolver::Parameters &parameters = {})
  {
    model.finalize();
    VectorType             u = model.create_vector();
    StaticSolver::StepInfo last;
    StaticSolver(model, parameters, &log)
      .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
        last = info;
      });
    return last;
  }

  unsigned int
  tip_of(const RodModel &model)
  {
    return model.network().rods()[0].vertices.back();
  }

  TEST(Stability, EulerColumnCountsItsModesBelowTheLoad)
  {
    // Clamped-free column: P_k = (2k - 1)^2 pi^2 EI / (4 L^2), in both
    // bending planes (EI1 = EI2). On the straight branch (no imperfection)
    // the tangent has 2 #{k : P_k < P} negative eigenvalues: none at
    // P = P_1 / 2, two at 2 P_1, and 2 x 7 at 200 P_1 (13^2 < 200 < 15^2).
    const double critical = M_PI * M_PI * EI / 4;
    for (const auto &[ratio, expected] :
         std::vector<std::pair<double, unsigned int>>{{0.5, 0},
                                                      {2, 2},
                                                      {200, 14}})
      {
        auto model = cantilever(50);
        model->add_point_force(tip_of(*model),
                               Vector3(-ratio * critical, 0, 0));
        StaticSolver::Parameters parameters;
        parameters.n_steps = 1;
        std::ostringstream           log;
        const StaticSolver::StepInfo info = solve(*model, log, parameters);
        std::cout << "P / P_cr = " << ratio << ": "
                  << info.check.negative_eigenvalues
                  << " negative eigenvalues, Euler's count " << expected
                  << std::endl;
        EXPECT_EQ(info.check.negative_eigenvalues, expected);
        EXPECT_EQ(info.check.stable, expected == 0);
        EXPECT_EQ(log.str().find("is unstable") != std::string::npos,
                  expected > 0)
          << log.str();
      }
  }

  TEST(Stability, InertiaMatchesTheDenseEigenvalues)
  {
    // The LDL^T inertia of a stiff, indefinite tangent (the column at 200
    // P_cr, compressed on its straight branch) against the signs of the
    // dense symmetric eigenvalues.
    auto model = cantilever(40);
    model->add_point_force(tip_of(*model),
                           Vector3(-200 * M_PI * M_PI / 4, 0, 0));
    const VectorType u = rodnet::testing::solve_in_one_step(*model);
    MatrixType       tangent;
    model->initialize_matrix(tangent);
    model->assemble(u, 1.0, nullptr, &tangent);
    const std::vector<double> values =
      lowest_eigenpairs(tangent, model->constraints(), 40).values;
    const unsigned int negative =
      std::count_if(values.begin(), values.end(), [](const double v) {
        return v < 0;
      });
    EXPECT_EQ(tangent_inertia(tangent, model->constraints()).negative,
              negative);
    EXPECT_EQ(negative, 14u);
  }

  TEST(StrainRange, BarStrainIsForceOverAxialStiffness)
  {
    // A clamped bar pulled along its axis: every free segment has the
    // strain F / EA, exactly in the discrete model.
    const double F     = 1e-3 * EA;
    auto         model = cantilever(10);
    model->add_point_force(tip_of(*model), Vector3(F, 0, 0));
    std::ostringstream           log;
    const StaticSolver::StepInfo info = solve(*model, log);
    std::cout << "axial strain " << info.strain.axial << ", F / EA " << F / EA
              << std::endl;
    EXPECT_NEAR(info.strain.axial, F / EA, 1e-9 * F / EA);
    EXPECT_TRUE(info.strain.in_range);
    EXPECT_EQ(log.str().find("warning"), std::string::npos) << log.str();
  }

  TEST(StrainRange, HugeLoadIsNamedInAWarning)
  {
    // The 1e12 N on a bar of EA = 1e4: a strain of 1e8.
    auto model = cantilever(10);
    model->add_point_force(tip_of(*model), Vector3(1e12, 0, 0));
    std::ostringstream           log;
    const StaticSolver::StepInfo info = solve(*model, log);
    EXPECT_NEAR(info.strain.axial, 1e8, 1e-6 * 1e8);
    EXPECT_FALSE(info.strain.in_range);
    EXPECT_EQ(info.strain.axial_rod, 0u);
    EXPECT_NE(log.str().find("warning: strain past the range of the rod "
                             "model: axial strain 1e+08 at rod 0 segment"),
              std::string::npos)
      << log.str();
  }

  TEST(StrainRange, HugePrescribedDisplacementIsNamed)
  {
    // A tip moved by 1e12 m: strains of order 1e11 in the segments that
    // carry it.
    auto model = cantilever(10);
    model->fix_components("far",
                          tip_of(*model),
                          {{true, false, false}},
                          Vector3(1e12, 0, 0));
    std::ostringstream           log;
    const StaticSolver::StepInfo info = solve(*model, log);
    EXPECT_GT(info.strain.axial, 1e10);
    EXPECT_FALSE(info.strain.in_range);
    EXPECT_NE(log.str().find("axial strain"), std::string::npos) << log.str();
  }

  TEST(StrainRange, BendingStrainOfAnEndMoment)
  {
    // An end moment M bends the rod into a circle of curvature M / EI: the
    // fiber at r from the centerline is strained by M r / EI. M = 0.5 EI / L
    // gives a small deflection; r = 0.1 puts the strain 0.05 in range, and
    // r = 0.4 (0.2) past the limit 0.1.
    const double M = 0.5 * EI;
    for (const double r : {0.1, 0.4})
      {
        auto model = cantilever(50, true);
        model->add_moment(model->network().junction_index("tip"),
                          Vector3::UnitZ(),
                          M);
        StaticSolver::Parameters parameters;
        parameters.strain_limits.fiber_distance = {{r, r}};
        std::ostringstream           log;
        const StaticSolver::StepInfo info = solve(*model, log, parameters);
        std::cout << "r = " << r << ": bending strain " << info.strain.bending
                  << ", M r / EI " << M * r / EI << std::endl;
        EXPECT_NEAR(info.strain.bending, M * r / EI, 1e-4 * M * r / EI);
        EXPECT_EQ(info.strain.in_range, M * r / EI <= 0.1);
        EXPECT_EQ(log.str().find("bending strain") != std::string::npos,
                  M * r / EI > 0.1)
          << log.str();
      }
  }

  TEST(Stability, SceneRecordsTheStableColumn)
  {
    // A clamped column (P_cr = pi^2 / 4, no imperfection) loaded to 3 P_cr
    // in 4 steps stays on the straight branch: probes.csv says stable 1 at
    // 0.75 P_cr, 0 at 1.5, 2.25 and 3 P_cr (no step near P_cr, which the
    // discrete column puts within 1e-3 of Euler's).
    const RunSummary summary = rodnet::testing::run_scene_text(
      "subsection Geometry\n"
      "  set Segments = 50\n"
      "  set Director d1 = 0, 0, 1\n"
      "  set Clamp at first segment midpoint = true\n"
      "end\n" +
        rodnet::testing::direct_material("1e7") +
        "subsection Supports\n  set Clamped ends = start\nend\n"
        "subsection Loads\n"
        "  set Steps = 4\n"
        "  set Point forces = end: -7.4022033008170185, 0, 0\n"
        "end\n"
        "subsection Output\n"
        "  set Write VTU = false\n"
        "  set Plot = false\n"
        "end\n",
      "straight_column");
    ASSERT_TRUE(summary.failure.empty()) << summary.failure;
    EXPECT_EQ(summary.unstable_steps, 3u);
    std::ifstream csv("straight_column/probes.csv");
    std::string   header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "step,load_factor,stable,in_range");
    const std::vector<std::string> expected = {
      "0,0,nan,nan", // step 0 is not checked
      "1,0.25,1,1",
      "2,0.5,0,1",
      "3,0.75,0,1",
      "4,1,0,1"};
    for (const std::string &row : expected)
      {
        ASSERT_TRUE(std::getline(csv, line));
        EXPECT_EQ(line, row);
      }
  }

  TEST(StrainRange, QuasiStaticTimeSteppingRefusesAFreeRod)
  {
    // Without inertia nothing holds a free rod either.
    auto model =
      rodnet::testing::elastic_model(rodnet::testing::straight_network(10),
                                     RodStiffness{EA, EI, EI, EI});
    model->add_point_force(10, Vector3(0, 0, 1e-3));
    model->finalize();
    TimeIntegrator::Parameters parameters;
    parameters.integrator = "quasi-static";
    parameters.time_step  = 0.1;
    parameters.end_time   = 1;
    TimeIntegrator integrator(*model, {}, parameters);
    VectorType     u = model->create_vector(), v = model->create_vector();
    EXPECT_THROW(integrator.run(u, v, {}), std::invalid_argument);
  }
} // namespace
