// The registry of integration schemes: the names a scene can select, the
// message for an unknown one (listing the known ones), and that every
// integrator has its scheme with the coefficients of its equations
// (TimeIntegrator's documentation): the mass coefficient c of
// c M (u - u_n - h v_n) and the time at which the loads act.
#include <common/held_bar.h>
#include <core/mass_matrix.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/time/integration_scheme_registry.h>
#include <solvers/time/time_integrator.h>

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  struct Expected
  {
    std::string integrator;
    bool        dynamic;
    /// c h^2 of the mass coefficient c.
    double mass_coefficient_h2;
    /// Where in the step (0 start, 1 end) the loads act.
    double load_fraction;
    /// The damping velocity a (u - u_n) - b v_n: a h and b.
    double damping_ah, damping_b;
  };

  class IntegrationSchemes : public ::testing::Test
  {
  protected:
    std::unique_ptr<RodModel> model =
      rodnet::testing::held_bar(std::make_shared<LinearElasticRod>(
                                  RodStiffness{1, 1, 1, 1}),
                                2,
                                Vector3::Zero());
    MatrixType mass, constrained_mass, damping, constrained_damping;
    std::vector<rodnet::global_dof_index> massless_rows;
    StepSystem                            system{*model,
                      mass,
                      constrained_mass,
                      massless_rows,
                      damping,
                      constrained_damping};

    /// The potential of scheme @p name at @p y has the residual as its
    /// gradient (central differences along @p direction).
    void
    check_potential(const std::string &name,
                    const StepStart   &step,
                    const VectorType  &v,
                    const VectorType  &y,
                    const VectorType  &direction)
    {
      const auto scheme = integration_scheme_registry().create(name, system);
      ASSERT_TRUE(scheme->has_incremental_potential()) << name;
      scheme->start(step.u, v, 1.0);
      NewtonSolver::Problem problem;
      scheme->set_up(step, problem);
      ASSERT_TRUE(problem.energy) << name;
      VectorType r = model->create_vector();
      problem.residual(y, r);
      VectorType r_with_energy = model->create_vector();
      problem.energy(y, &r_with_energy);
      r_with_energy -= r;
      EXPECT_EQ(r_with_energy.linfty_norm(), 0.0) << name;

      const double eps     = 1e-6;
      VectorType   shifted = y;
      shifted.add(eps, direction);
      const double plus = problem.energy(shifted, nullptr);
      shifted.add(-2 * eps, direction);
      const double minus      = problem.energy(shifted, nullptr);
      const double difference = (plus - minus) / (2 * eps);
      const double slope      = r * direction;
      EXPECT_NEAR(difference, slope, 1e-7 * std::abs(slope)) << name;
    }
  };

  TEST_F(IntegrationSchemes, UnknownNameListsTheKnownOnes)
  {
    const std::vector<std::string> names =
      integration_scheme_registry().names();
    EXPECT_EQ(names,
              (std::vector<std::string>{"quasi-static",
                                        "backward euler",
                                        "newmark",
                                        "midpoint",
                                        "generalized alpha"}));
    try
      {
        integration_scheme_registry().create("leapfrog", system);
        ADD_FAILURE() << "an unknown scheme was created";
      }
    catch (const std::invalid_argument &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("unknown time integrator \"leapfrog\""),
                  std::string::npos)
          << message;
        for (const std::string &name : names)
          EXPECT_NE(message.find(name), std::string::npos) << message;
      }
  }

  // Generalized alpha at rho_inf = 0.8 (Chung & Hulbert 1993): alpha_m =
  // 1/3, alpha_f = 4/9, gamma = 11/18, beta = 25/81, so c h^2 = (1 -
  // alpha_m) / ((1 - alpha_f) beta) = 1458/375 and the damping velocity
  // gamma/(beta h) (u - u_n) + (1 - gamma/beta) v_n, gamma/beta = 1.98.
  TEST_F(IntegrationSchemes, EveryIntegratorHasItsScheme)
  {
    const double h = 0.125, start = 1.5;
    system.spectral_radius_at_infinity = 0.8;
    for (const Expected &e :
         {Expected{"quasi-static", false, 0, 1, 1, 0},
          Expected{"backward euler", true, 1, 1, 1, 0},
          Expected{"newmark", true, 4, 1, 2, 1},
          Expected{"midpoint", true, 2, 0.5, 1, 0},
          Expected{"generalized alpha", true, 1458.0 / 375, 1, 1.98, 0.98}})
      {
        const std::string &name = e.integrator;
        const auto scheme = integration_scheme_registry().create(name, system);
        EXPECT_EQ(scheme->name(), name);
        EXPECT_EQ(scheme->dynamic(), e.dynamic) << name;
        EXPECT_NEAR(scheme->mass_coefficient(h) * h * h,
                    e.mass_coefficient_h2,
                    1e-15)
          << name;
        EXPECT_NEAR(scheme->load_time(start, start + h),
                    start + e.load_fraction * h,
                    1e-15)
          << name;
        EXPECT_EQ(scheme->needs_stored_energy(), e.integrator == "midpoint")
          << name;
        EXPECT_NEAR(scheme->damping_velocity(h).a * h, e.damping_ah, 1e-15)
          << name;
        EXPECT_NEAR(scheme->damping_velocity(h).b, e.damping_b, 1e-15) << name;
      }
  }

  // The incremental potential each scheme gives the energy line search
  // (Problem::energy) has the step's residual as its gradient: central
  // differences along a direction of the free DoFs, at a bent state of a
  // bar with mass, against residual . direction, without damping and with
  // C = 0.7 M (the dissipation potential a/2 |u - u_n|_C^2 - b u.C v_n).
  // The midpoint rule has none (its Jacobian is not symmetric) and says so.
  TEST_F(IntegrationSchemes, IncrementalPotentialHasTheResidualAsGradient)
  {
    const std::vector<RodInertia> inertia{{2.0, 1e-3}};
    assemble_mass_matrix(*model, inertia, MassKind::consistent, mass, false);
    assemble_mass_matrix(*model,
                         inertia,
                         MassKind::consistent,
                         constrained_mass,
                         true);
    VectorType u = model->create_vector(), base = model->create_vector(),
               y = model->create_vector(), direction = model->create_vector();
    for (unsigned int i = 0; i < u.size(); ++i)
      {
        u[i]         = 0.01 * std::sin(1.0 + i);
        base[i]      = u[i] + 0.02 * std::cos(2.0 * i);
        y[i]         = u[i] + 0.03 * std::sin(3.0 * i + 0.5);
        direction[i] = std::cos(0.7 * i + 0.2);
      }
    for (VectorType *v : {&u, &base, &y, &direction})
      v->compress(dealii::VectorOperation::insert);
    model->apply_boundary_values(u, 1.0);
    model->apply_boundary_values(y, 1.0);
    model->constraints().set_zero(direction);
    const StepStart step{u, base, 0.05, 1.0};
    VectorType      v = base;
    v -= u;
    v /= step.h;

    // Generalized alpha with dissipation: its start solves M a_0 = p_0 (a
    // state out of balance), whose damping force h (1 - gamma/(2 beta))
    // C a_0 enters e_n.
    system.spectral_radius_at_infinity = 0.8;
    for (const bool damped : {false, true})
      for (const std::string name :
           {"quasi-static", "backward euler", "newmark", "generalized alpha"})
        {
          if (damped)
            for (MatrixType *c : {&damping, &constrained_damping})
              {
                model->initialize_matrix(*c);
                c->add(0.7, c == &damping ? mass : constrained_mass);
              }
          check_potential(name, step, v, y, direction);
        }
    const auto midpoint =
      integration_scheme_registry().create("midpoint", system);
    EXPECT_FALSE(midpoint->has_incremental_potential());
  }

  TEST_F(IntegrationSchemes, SpectralRadiusOutsideTheUnitIntervalIsRefused)
  {
    for (const double rho : {-0.1, 1.5, std::nan("")})
      {
        system.spectral_radius_at_infinity = rho;
        try
          {
            integration_scheme_registry().create("generalized alpha", system);
            ADD_FAILURE() << "took a spectral radius of " << rho;
          }
        catch (const std::invalid_argument &e)
          {
            EXPECT_NE(std::string(e.what()).find(
                        "spectral radius at infinity must lie in [0, 1]"),
                      std::string::npos)
              << e.what();
          }
      }
  }

  TEST_F(IntegrationSchemes, EnergyLineSearchRefusesTheMidpointRule)
  {
    TimeIntegrator::Parameters p;
    p.integrator         = "midpoint";
    p.time_step          = 0.1;
    p.end_time           = 1;
    p.newton.line_search = "energy";
    try
      {
        TimeIntegrator(*model, {{1, 1e-3}}, p);
        ADD_FAILURE() << "the midpoint rule took the energy line search";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("not the minimum of a potential"),
                  std::string::npos)
          << e.what();
      }
  }
} // namespace
