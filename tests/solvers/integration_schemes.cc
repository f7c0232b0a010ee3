// The registry of integration schemes: the names a scene can select, the
// message for an unknown one (listing the known ones), and that every
// integrator has its scheme with the coefficients of its equations
// (TimeIntegrator's documentation): the mass coefficient c of
// c M (u - u_n - h v_n) and the time at which the loads act.
#include <materials/linear_elastic_rod.h>

#include <common/held_bar.h>
#include <solvers/integration_scheme_registry.h>
#include <solvers/time_integrator.h>

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
  };

  class IntegrationSchemes : public ::testing::Test
  {
  protected:
    std::unique_ptr<RodModel> model = rodnet::testing::held_bar(
      std::make_shared<LinearElasticRod>(RodStiffness{1, 1, 1, 1}),
      2,
      Vector3::Zero());
    MatrixType        mass, constrained_mass;
    std::vector<bool> has_mass;
    StepSystem        system{*model, mass, constrained_mass, has_mass};
  };

  TEST_F(IntegrationSchemes, UnknownNameListsTheKnownOnes)
  {
    const std::vector<std::string> names =
      integration_scheme_registry().names();
    EXPECT_EQ(names,
              (std::vector<std::string>{
                "quasi-static", "backward euler", "newmark", "midpoint"}));
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

  TEST_F(IntegrationSchemes, EveryIntegratorHasItsScheme)
  {
    const double h = 0.125, start = 1.5;
    for (const Expected &e : {Expected{"quasi-static", false, 0, 1},
                              Expected{"backward euler", true, 1, 1},
                              Expected{"newmark", true, 4, 1},
                              Expected{"midpoint", true, 2, 0.5}})
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
      }
  }
} // namespace
