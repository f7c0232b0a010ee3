// TimeIntegrator and NewtonSolver's rank-one Jacobian on small problems:
// stress relaxation of a standard-linear-solid bar held at a prescribed
// elongation against E(t) = E1 + E2 exp(-t / t_r) (within the first-order
// error of the backward-Euler update), Newton with a dense rank-one
// Jacobian part (with modified Newton too), modified Newton (one tangent
// per solve), the model assemblies of a dynamic step,
// the parameter checks, and a failed run that reports its last state
// instead of NaN.
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <common/cantilever_swing.h>
#include <common/held_bar.h>
#include <core/mass_matrix.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <materials/standard_linear_solid.h>
#include <solvers/time/time_integrator.h>

#include <atomic>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace
{
  using namespace rodnet;

  using rodnet::testing::held_bar;

  // A bar pulled by eps = 1e-4 at t = 0 and held: the force relaxes from
  // (1 + r) EA eps towards EA eps as E(t) / E1 = 1 + r exp(-t / t_r).
  // Backward Euler's w^k = (t_r / (t_r + dt))^k replaces exp(-k dt / t_r),
  // an error below r t / (2 t_r) dt / t_r exp(-t/t_r) relative; with
  // dt = t_r / 200 that is < 2.5e-3 r.
  TEST(TimeIntegrator, StressRelaxationOfHeldBar)
  {
    const double EA = 1e4, r = 0.3, t_r = 0.5, eps = 1e-4;
    auto         model = held_bar(
      std::make_shared<StandardLinearSolid>(RodStiffness{EA, 1, 1, 1}, r, t_r),
      4,
      Vector3(eps, 0, 0));
    TimeIntegrator::Parameters p;
    p.integrator = "quasi-static";
    p.time_step  = t_r / 200;
    p.end_time   = 3 * t_r;
    TimeIntegrator integrator(*model, {}, p);
    VectorType     u = model->create_vector(), v = model->create_vector();
    double         worst = 0;
    unsigned int   n     = 0;
    integrator.run(u,
                   v,
                   [&](const TimeIntegrator::StepInfo &info,
                       const VectorType               &x,
                       const VectorType &) {
                     const double force =
                       model->reaction(model->support("right"), x, 1.0)[0];
                     // The clamp holds the first of the 4 segments:
                     // the other 3 take the elongation.
                     const double expected =
                       EA * eps * 4 / 3 * (1 + r * std::exp(-info.time / t_r));
                     worst = std::max(worst, std::abs(force / expected - 1));
                     ++n;
                   });
    EXPECT_EQ(n, 600u);
    EXPECT_LT(worst, 2.5e-3 * r);
    std::cout << "relaxation: max relative force error " << worst << std::endl;
  }

  // f(x) = D x + a (b.x) - c is linear with Jacobian D + a b^T: Newton
  // with the rank-one term converges in one iteration; without, in many.
  TEST(NewtonSolver, RankOneJacobianTerm)
  {
    const unsigned int             n   = 6;
    const dealii::IndexSet         all = dealii::complete_index_set(n);
    VectorType                     a(all, MPI_COMM_WORLD), b = a, c = a, x = a;
    dealii::DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      pattern.add(i, i);
    MatrixType tangent;
    tangent.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      {
        a[i] = 1.0 + i;
        b[i] = 0.5 - 0.1 * i;
        c[i] = std::sin(1.0 + i);
      }
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &y, VectorType &r) {
      const double by = b * y;
      for (unsigned int i = 0; i < n; ++i)
        r[i] = (2.0 + i) * y[i] + a[i] * by - c[i];
      r.compress(dealii::VectorOperation::insert);
    };
    problem.tangent = [&](const VectorType &, MatrixType &k) {
      for (unsigned int i = 0; i < n; ++i)
        k.set(i, i, 2.0 + i);
      k.compress(dealii::VectorOperation::insert);
    };
    problem.rank_one = [&](const VectorType &, VectorType &p, VectorType &q) {
      p = a;
      q = b;
    };
    NewtonSolver::Parameters parameters;
    parameters.tolerance = 1e-12;
    const auto exact     = NewtonSolver(parameters).solve(problem, x, tangent);
    EXPECT_TRUE(exact.converged);
    EXPECT_EQ(exact.iterations, 1u);

    problem.rank_one   = nullptr;
    x                  = 0;
    const auto inexact = NewtonSolver(parameters).solve(problem, x, tangent);
    EXPECT_GT(inexact.iterations, 1u);
  }

  // f(y)_i = (2 + i) y_i + y_i^3 / 20 + a_i (b.y) - c_i, Jacobian
  // diag(2 + i + 3 y_i^2 / 20) + a b^T: Newton with the rank-one part by
  // Sherman-Morrison takes the iterates of Newton on the dense Jacobian,
  // in full Newton (K^-1 a solved anew at every iterate) as in modified
  // Newton (K^-1 a of the first iterate, solved once, for all).
  TEST(NewtonSolver, RankOneSolveFollowsTheTangent)
  {
    const unsigned int             n   = 6;
    const dealii::IndexSet         all = dealii::complete_index_set(n);
    VectorType                     a(all, MPI_COMM_WORLD), b = a, c = a;
    dealii::DynamicSparsityPattern diagonal(n, n), dense(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        a[i] = 1.0 + i;
        b[i] = 0.5 - 0.1 * i;
        c[i] = 3 * std::sin(1.0 + i);
        diagonal.add(i, i);
        for (unsigned int j = 0; j < n; ++j)
          dense.add(i, j);
      }
    MatrixType sparse_tangent, dense_tangent;
    sparse_tangent.reinit(diagonal);
    dense_tangent.reinit(dense);
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &y, VectorType &r) {
      const double by = b * y;
      for (unsigned int i = 0; i < n; ++i)
        r[i] = (2.0 + i) * y[i] + std::pow(y[i], 3) / 20 + a[i] * by - c[i];
      r.compress(dealii::VectorOperation::insert);
    };
    // The diagonal of the Jacobian without the rank-one part.
    const auto diagonal_entry = [](const VectorType &y, const unsigned int i) {
      return 2.0 + i + 3 * y[i] * y[i] / 20;
    };
    NewtonSolver::Parameters parameters;
    parameters.tolerance = 1e-13;
    for (const bool modified : {false, true})
      {
        problem.reuse_first_jacobian = modified;
        problem.tangent              = [&](const VectorType &y, MatrixType &k) {
          for (unsigned int i = 0; i < n; ++i)
            k.set(i, i, diagonal_entry(y, i));
          k.compress(dealii::VectorOperation::insert);
        };
        problem.rank_one =
          [&](const VectorType &, VectorType &p, VectorType &q) {
            p = a;
            q = b;
          };
        VectorType x = c;
        const auto low_rank =
          NewtonSolver(parameters).solve(problem, x, sparse_tangent);

        problem.rank_one = nullptr;
        problem.tangent  = [&](const VectorType &y, MatrixType &k) {
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              k.set(i, j, a[i] * b[j] + (i == j ? diagonal_entry(y, i) : 0.0));
          k.compress(dealii::VectorOperation::insert);
        };
        VectorType reference = c;
        const auto full =
          NewtonSolver(parameters).solve(problem, reference, dense_tangent);
        ASSERT_TRUE(low_rank.converged) << modified;
        ASSERT_TRUE(full.converged) << modified;
        EXPECT_EQ(low_rank.iterations, full.iterations) << modified;
        x -= reference;
        EXPECT_LT(x.linfty_norm(), 1e-12) << modified;
      }
  }

  // f(y)_i = (2 + i) y_i + y_i^3 / 20 - c_i, Jacobian diag(2 + i +
  // 3 y_i^2 / 20): modified Newton assembles the tangent once, at the first
  // iterate, converges linearly (more iterations than Newton) to the same
  // root; full Newton assembles it at every iterate.
  TEST(NewtonSolver, ModifiedNewtonAssemblesTheTangentOnce)
  {
    const unsigned int             n   = 5;
    const dealii::IndexSet         all = dealii::complete_index_set(n);
    VectorType                     x(all, MPI_COMM_WORLD), newton = x;
    dealii::DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      pattern.add(i, i);
    MatrixType tangent;
    tangent.reinit(pattern);
    unsigned int          tangents = 0;
    NewtonSolver::Problem problem;
    problem.residual = [&](const VectorType &y, VectorType &r) {
      for (unsigned int i = 0; i < n; ++i)
        r[i] = (2.0 + i) * y[i] + std::pow(y[i], 3) / 20 - std::sin(1.0 + i);
      r.compress(dealii::VectorOperation::insert);
    };
    problem.tangent = [&](const VectorType &y, MatrixType &k) {
      ++tangents;
      for (unsigned int i = 0; i < n; ++i)
        k.set(i, i, 2.0 + i + 3 * y[i] * y[i] / 20);
      k.compress(dealii::VectorOperation::insert);
    };
    NewtonSolver::Parameters parameters;
    parameters.tolerance = 1e-13;
    const auto full = NewtonSolver(parameters).solve(problem, newton, tangent);
    ASSERT_TRUE(full.converged);
    EXPECT_EQ(tangents, full.iterations);

    tangents                     = 0;
    problem.reuse_first_jacobian = true;
    const auto chord = NewtonSolver(parameters).solve(problem, x, tangent);
    ASSERT_TRUE(chord.converged);
    EXPECT_EQ(tangents, 1u);
    EXPECT_GT(chord.iterations, full.iterations);
    x -= newton;
    EXPECT_LT(x.linfty_norm(), 1e-12);
  }

  // Modified Newton solves every step to the same tolerance as full
  // Newton: the cantilever of cantilever_swing.h (N = 20) in its first
  // mode, tip at 0.01 L, one period in 40 steps, follows the same path.
  TEST(TimeIntegrator, ModifiedNewtonStepsAsFullNewton)
  {
    const auto elastic =
      std::make_shared<LinearElasticRod>(rodnet::testing::swing_stiffness);
    auto model                = rodnet::testing::cantilever(20, elastic, 0);
    const auto [omega, shape] = rodnet::testing::first_mode(*model);
    const double amplitude    = 0.01 / shape[model->layout().vertex_dof(20, 2)];
    const double period       = 2 * M_PI / omega;
    for (const std::string method : {"newmark", "midpoint", "backward euler"})
      {
        rodnet::testing::SwingHistory runs[2];
        for (const bool modified : {false, true})
          {
            auto rod = rodnet::testing::cantilever(20, elastic, 0);
            runs[modified] =
              rodnet::testing::free_vibration(*rod,
                                              shape,
                                              amplitude,
                                              method,
                                              period / 40,
                                              period,
                                              [&](
                                                TimeIntegrator::Parameters &p) {
                                                p.modified_newton = modified;
                                              });
            ASSERT_TRUE(runs[modified].failure.empty()) << method;
          }
        ASSERT_EQ(runs[0].tip.size(), runs[1].tip.size());
        double difference = 0;
        for (std::size_t k = 0; k < runs[0].tip.size(); ++k)
          difference =
            std::max(difference, std::abs(runs[1].tip[k] - runs[0].tip[k]));
        EXPECT_LT(difference, 1e-9) << method; // of a 0.01 m amplitude
      }
  }

  /// A linear elastic rod that counts the evaluations of its segments:
  /// every assembly of the model (energy, residual or tangent) evaluates
  /// each segment once.
  class CountingRod : public LinearElasticRod
  {
  public:
    CountingRod(const RodStiffness &stiffness, std::atomic<unsigned> &count)
        : LinearElasticRod(stiffness)
        , count(count)
    {
    }

    MaterialResponse<1>
    segment_energy(const double strain, const double rest_length) const override
    {
      ++count;
      return LinearElasticRod::segment_energy(strain, rest_length);
    }

  private:
    std::atomic<unsigned> &count;
  };

  // The assemblies of a dynamic step in free vibration (load factor 0),
  // modified Newton with k iterations, in a step without the round-off
  // measurement: the predictor's residual (for the tolerance, and NOX's
  // first), the reactions of the load scale (the applied loads at load
  // factor 0 are no second assembly), one tangent, the residuals of the k
  // iterates and the energy of the converged state: k + 4 (Newmark,
  // backward Euler). The midpoint rule evaluates its residual as the
  // gradient at the midpoint and the energy at the end, 2 (k + 1), its
  // tangent the gradient at the end and the Hessian at the midpoint
  // (the gradient there is the residual's). The gradient at the end of its
  // tangent at the predictor is the unconstrained residual the load scale
  // needs there: one assembly for both (MidpointScheme::
  // shared_gradient()), which gives the energy at the predictor too; the
  // energy of the converged state is its last residual's
  // (IntegrationScheme::energy_at()) and the energy of the start that of
  // the converged state before (StepStart::start_energy): 2 k + 3 (2 k + 6
  // before, 2 k + 7 without the shared gradient).
  TEST(TimeIntegrator, AssembliesOfAStep)
  {
    std::atomic<unsigned> count{0};
    const auto            rod =
      std::make_shared<CountingRod>(rodnet::testing::swing_stiffness, count);
    const unsigned int n      = 20;
    auto               model  = rodnet::testing::cantilever(n, rod, 0);
    const auto [omega, shape] = rodnet::testing::first_mode(*model);
    const double amplitude    = 0.01 / shape[model->layout().vertex_dof(n, 2)];
    for (const std::string method : {"newmark", "backward euler", "midpoint"})
      {
        TimeIntegrator::Parameters p;
        p.integrator  = method;
        p.time_step   = 2 * M_PI / omega / 40;
        p.end_time    = 10 * p.time_step;
        p.load_factor = [](double) { return 0.0; };
        TimeIntegrator integrator(*model, {rodnet::testing::swing_inertia}, p);
        VectorType     u = shape, v = model->create_vector();
        u *= amplitude;
        // Per step: assemblies (segment evaluations / segments) beyond
        // what its iterations need; the least over the steps is a step
        // without the round-off measurement (every 20 steps).
        unsigned int fewest = std::numeric_limits<unsigned int>::max();
        unsigned int before = 0;
        integrator.run(u,
                       v,
                       [&](const TimeIntegrator::StepInfo &info,
                           const VectorType &,
                           const VectorType &) {
                         const unsigned int step = count - before;
                         EXPECT_EQ(step % n, 0u) << method;
                         const unsigned int per_iteration =
                           method == "midpoint" ? 2 : 1;
                         fewest =
                           std::min(fewest,
                                    step / n - per_iteration * info.iterations);
                         before = count;
                       });
        EXPECT_EQ(fewest, method == "midpoint" ? 3u : 4u) << method;
      }
  }

  // A load factor that moves in time while nothing in the model follows it
  // (the cantilever's tip force is 0, no field, no moving support): the
  // energy watch and the load scale cost no assembly, and the steps cost
  // what they cost under a constant load factor
  // (TimeIntegrator.AssembliesOfAStep: Newmark k + 4, midpoint 2 k + 3:
  // the midpoint rule's start and end energies are reused as under a
  // constant load factor, TimeIntegrator::same_potential_load()).
  // Before the model was asked (RodModel::potential_follows_load_factor())
  // both took k + 9 and 2 k + 9: the watch balanced the loads' work at each
  // force point (4 and 2 assemblies) and the load scale assembled the
  // applied loads at load factor 0.
  TEST(TimeIntegrator, AssembliesOfAStepUnderALoadFactorNothingFollows)
  {
    std::atomic<unsigned> count{0};
    const auto            rod =
      std::make_shared<CountingRod>(rodnet::testing::swing_stiffness, count);
    const unsigned int n      = 20;
    auto               model  = rodnet::testing::cantilever(n, rod, 0);
    const auto [omega, shape] = rodnet::testing::first_mode(*model);
    ASSERT_FALSE(model->potential_follows_load_factor());
    ASSERT_FALSE(model->potential_follows_time());
    for (const std::string method : {"newmark", "midpoint"})
      {
        TimeIntegrator::Parameters p;
        p.integrator  = method;
        p.time_step   = 2 * M_PI / omega / 40;
        p.end_time    = 10 * p.time_step;
        p.load_factor = [](const double t) { return t; };
        TimeIntegrator integrator(*model, {rodnet::testing::swing_inertia}, p);
        VectorType     u = shape, v = model->create_vector();
        u *= 0.01 / shape[model->layout().vertex_dof(n, 2)];
        unsigned int fewest = std::numeric_limits<unsigned int>::max();
        unsigned int before = 0;
        integrator.run(u,
                       v,
                       [&](const TimeIntegrator::StepInfo &info,
                           const VectorType &,
                           const VectorType &) {
                         const unsigned int per_iteration =
                           method == "midpoint" ? 2 : 1;
                         fewest = std::min(fewest,
                                           (count - before) / n -
                                             per_iteration * info.iterations);
                         before = count;
                       });
        EXPECT_EQ(fewest, method == "midpoint" ? 3u : 4u) << method;
      }
  }

  TEST(TimeIntegrator, RejectsBadParameters)
  {
    auto model =
      held_bar(std::make_shared<LinearElasticRod>(RodStiffness{1, 1, 1, 1}),
               4,
               Vector3::Zero());
    const std::vector<RodInertia> inertia{{1, 1e-3}};
    TimeIntegrator::Parameters    p;
    p.end_time = 1;
    for (const double bad : {0.0, -1e-3, std::nan("")})
      {
        p.time_step = bad;
        EXPECT_THROW(TimeIntegrator(*model, inertia, p), std::invalid_argument)
          << bad;
      }
    p.time_step = 0.1;
    p.end_time  = -1;
    EXPECT_THROW(TimeIntegrator(*model, inertia, p), std::invalid_argument);
    p.end_time = 1;
    // Dynamics needs the inertia; quasi-static does not.
    EXPECT_THROW(TimeIntegrator(*model, {}, p), std::invalid_argument);
    p.integrator = "quasi-static";
    EXPECT_NO_THROW(TimeIntegrator(*model, {}, p));
    p.integrator = "leapfrog";
    EXPECT_THROW(TimeIntegrator(*model, inertia, p), std::invalid_argument);

    // The midpoint rule needs a stored energy.
    auto viscous = held_bar(
      std::make_shared<StandardLinearSolid>(RodStiffness{1, 1, 1, 1}, 0.3, 1.0),
      4,
      Vector3::Zero());
    p.integrator = "midpoint";
    try
      {
        TimeIntegrator(*viscous, inertia, p);
        ADD_FAILURE() << "midpoint accepted a viscoelastic material";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("midpoint"), std::string::npos);
      }
  }

  // A bar whose end jumps sideways by its length in one step, with two
  // Newton iterations allowed and no room to cut: the run throws
  // SolverFailure naming the time, and the state is the last converged one
  // (finite).
  TEST(TimeIntegrator, FailureKeepsLastConvergedState)
  {
    auto model = held_bar(std::make_shared<LinearElasticRod>(
                            RodStiffness{1e6, 1e-3, 1e-3, 1e-3}),
                          8,
                          Vector3(0, 1, 0));
    TimeIntegrator::Parameters p;
    p.integrator            = "newmark";
    p.time_step             = 1e-3;
    p.end_time              = 2e-3;
    p.load_factor           = [](const double t) { return t > 1.5e-3; };
    p.min_step_fraction     = 1.0;
    p.newton.max_iterations = 2;
    TimeIntegrator integrator(*model, {{1e-6, 1e-9}}, p);
    VectorType     u = model->create_vector(), v = model->create_vector();
    unsigned int   steps = 0;
    try
      {
        integrator.run(u, v, [&](const auto &, const auto &, const auto &) {
          ++steps;
        });
        ADD_FAILURE() << "the run did not fail";
      }
    catch (const SolverFailure &e)
      {
        EXPECT_NE(std::string(e.what()).find("t = 0.001"), std::string::npos)
          << e.what();
      }
    EXPECT_EQ(steps, 1u);
    EXPECT_TRUE(std::isfinite(u.l2_norm()));
    EXPECT_TRUE(std::isfinite(v.l2_norm()));
    EXPECT_EQ(u.l2_norm(), 0.0);
  }
} // namespace
