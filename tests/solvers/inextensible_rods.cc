// Inextensible rods (Rod::inextensible, families/inextensibility_family.h):
// the segments keep their lengths to rounding, the multipliers are the axial
// forces that statics gives, the stability count and the lowest eigenvalue
// are those on the constraint manifold (against a nearly inextensible rod),
// and the solvers that need a potential or a mass refuse the model.
#include <common/rod_models.h>
#include <common/solve_model.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/statics/static_solver.h>
#include <solvers/time/time_integrator.h>

#include <cmath>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr RodStiffness unit_bending{1e8,
                                      1,
                                      1,
                                      1}; // EA unused when inextensible

  /// A cantilever of length 1 along x in @p n segments, clamped at its
  /// start, inextensible unless @p extensible_EA is given, with the tip
  /// force @p tip_force.
  std::unique_ptr<RodModel>
  cantilever(const unsigned int n,
             const Vector3     &tip_force,
             const double       extensible_EA = 0)
  {
    auto network = straight_network(n);
    network->create_triangulation();
    network->set_inextensible(0, extensible_EA == 0);
    RodStiffness stiffness = unit_bending;
    if (extensible_EA > 0)
      stiffness.EA = extensible_EA;
    auto model = elastic_model(std::move(network), stiffness);
    model->clamp_end("clamp", 0, true);
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           tip_force);
    return model;
  }

  TEST(InextensibleRods, SegmentsKeepTheirLengthsAndCarryTheStaticAxialForce)
  {
    // A bent cantilever: the hinges' forces are normal to the segments
    // (the strains depend on the tangents only), so each segment's axial
    // force is the tip force along its tangent, N_j = F . t_j.
    const Vector3        force(-2.0, 1.5, 0.4);
    const auto           model         = cantilever(30, force);
    const VectorType     u             = solve(*model, 10);
    const Configuration &configuration = model->configuration();
    const auto          &rod           = model->network().rods()[0];
    double               length_error = 0, force_error = 0;
    unsigned int         checked = 0;
    for (unsigned int j = 0; j < rod.segments.size(); ++j)
      {
        const unsigned int cell = rod.segments[j];
        const double       l0   = configuration.rest_length(cell);
        length_error =
          std::max(length_error,
                   std::abs(configuration.segment_length(u, cell) - l0) / l0);
        if (j == 0) // held by the clamp: no multiplier
          {
            EXPECT_EQ(model->axial_force(cell, u), 0.0);
            continue;
          }
        const Vector3 t = (configuration.position(u, rod.vertices[j + 1]) -
                           configuration.position(u, rod.vertices[j]))
                            .normalized();
        force_error =
          std::max(force_error,
                   std::abs(model->axial_force(cell, u) - force.dot(t)));
        ++checked;
      }
    std::cout << "length error " << length_error << ", axial force error "
              << force_error << " N over " << checked << " segments"
              << std::endl;
    EXPECT_EQ(checked, 29u);
    EXPECT_LT(length_error, 1e-12);
    EXPECT_LT(force_error, 1e-8 * force.norm());
    // The tip moved far: a real bent state, not the straight rod.
    EXPECT_GT(configuration.position(u, rod.vertices.back())[1], 0.3);
  }

  /// At the straight equilibrium of a column under its load (one Newton
  /// step, no branch switching: the axial force is the multipliers' or the
  /// stretch's): the lowest eigenvalue by the dense solver and by the
  /// sparse one, and the negative count.
  struct LowestEigenvalue
  {
    double       dense;
    double       sparse;
    unsigned int negative;
  };

  LowestEigenvalue
  lowest_at_straight_state(RodModel &model)
  {
    model.finalize();
    VectorType               u = model.create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps                 = 1;
    parameters.branch_switch_amplitude = 0;
    StaticSolver(model, parameters).run(u, [](const auto &, const auto &) {});
    MatrixType tangent;
    model.initialize_matrix(tangent);
    LowestEigenvalue result;
    result.negative = negative_eigenvalues(model, u, 1.0, tangent);
    model.assemble(u, 1.0, nullptr, &tangent);
    const auto &multipliers = model.multiplier_dofs();
    result.dense =
      dense_eigenpairs(tangent, model.constraints(), 1, multipliers).values[0];
    result.sparse =
      lowest_eigenpairs(tangent, model.constraints(), 1, multipliers).values[0];
    return result;
  }

  class ManifoldEigenvalues : public ::testing::TestWithParam<unsigned int>
  {
  };

  TEST_P(ManifoldEigenvalues, MatchANearlyInextensibleRodAndCountOnTheManifold)
  {
    // The straight column under a compressive tip load P. Its lowest
    // eigenvalue on the constraint manifold by the null-space basis (dense)
    // and by the regularized KKT factorization (sparse Lanczos, beyond 300
    // DoFs) agree, and equal that of the same rod with EA = 1e9 EI / L^2
    // (to 1e-5: the Lanczos tolerance and the rounding of the stiff
    // extensible tangent, ~1e-6 measured). The count is 0 below the critical
    // load pi^2/4 and 2 above (EI1 = EI2: both lateral planes), not one more
    // per constraint.
    const unsigned int n = GetParam();
    for (const double P : {0.9 * M_PI * M_PI / 4, 1.1 * M_PI * M_PI / 4})
      {
        auto inextensible = cantilever(n, Vector3(-P, 0, 0));
        auto extensible   = cantilever(n, Vector3(-P, 0, 0), 1e9);
        const LowestEigenvalue constrained =
          lowest_at_straight_state(*inextensible);
        const LowestEigenvalue free = lowest_at_straight_state(*extensible);
        std::cout << "N = " << n << ", P = " << P << ": lowest "
                  << constrained.dense << " (dense), " << constrained.sparse
                  << " (sparse), nearly inextensible " << free.dense
                  << "; negative " << constrained.negative << std::endl;
        const double scale = std::abs(free.dense);
        EXPECT_NEAR(constrained.sparse, constrained.dense, 1e-5 * scale);
        EXPECT_NEAR(constrained.dense, free.dense, 1e-5 * scale);
        EXPECT_EQ(constrained.negative, P < M_PI * M_PI / 4 ? 0u : 2u);
        EXPECT_EQ(constrained.negative, free.negative);
      }
  }

  INSTANTIATE_TEST_SUITE_P(DenseAndSparse,
                           ManifoldEigenvalues,
                           ::testing::Values(40u, 200u));

  TEST(InextensibleRods, SolversThatNeedAPotentialOrAMassRefuse)
  {
    auto model = cantilever(10, Vector3(-1, 0.1, 0));
    model->finalize();
    StaticSolver::Parameters energy;
    energy.newton.line_search = "energy";
    try
      {
        StaticSolver solver(*model, energy);
        ADD_FAILURE() << "the energy line search was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("Lagrangian"), std::string::npos)
          << e.what();
      }
    TimeIntegrator::Parameters stepping;
    stepping.integrator = "quasi-static";
    stepping.time_step  = 0.1;
    stepping.end_time   = 1;
    try
      {
        TimeIntegrator integrator(*model, {}, stepping);
        ADD_FAILURE() << "time stepping was accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("inextensible"), std::string::npos)
          << e.what();
      }
  }
} // namespace

namespace
{
  TEST(InextensibleRods, AnExtensibleSegmentCarriesTheLoadUnderAnEigenstrain)
  {
    // An extensible cantilever with a uniform axial eigenstrain of 1 % and
    // a tip force F along its axis: statics gives N = F in every segment,
    // whatever the eigenstrain (which only lengthens the rod, by 1 %).
    const double F     = 2.0;
    auto         model = cantilever(10, Vector3(F, 0, 0), 1e3);
    model->add_activation(0,
                          [](const double t0, const double t1) {
                            return Eigen::Vector4d(0, 0, 0, 0.01 * (t1 - t0));
                          },
                          {ActivationDrive::Kind::fixed, nullptr});
    const VectorType u   = solve(*model, 1);
    const auto      &rod = model->network().rods()[0];
    // The clamp holds both ends of the first segment: its eigenstrain is
    // blocked, N = -EA eps (the support takes it).
    EXPECT_NEAR(model->axial_force(rod.segments[0], u), -1e3 * 0.01, 1e-9);
    for (unsigned int j = 1; j < rod.segments.size(); ++j)
      EXPECT_NEAR(model->axial_force(rod.segments[j], u), F, 1e-9 * F)
        << "segment " << j;
    // The eigenstrain acted: the rod grew by more than its elastic 0.2 %.
    EXPECT_GT(model->position(u, rod.vertices.back())[0], 1.009);
  }
} // namespace
