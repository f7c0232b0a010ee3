// Reading LinearElasticRod from a scene subsection: resolved stiffnesses for
// both input modes, and errors that name the offending entry.

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <materials/linear_elastic_rod.h>
#include <materials/rod_material.h>

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

using namespace rodnet;

namespace
{
  const double parameters_pi = dealii::numbers::PI;

  /**
   * Creates "linear elastic" through the registry, as a scene does, and
   * reads it from @p entries placed in its subsection.
   */
  LinearElasticRod
  parse_linear_elastic(const std::string &entries)
  {
    const std::unique_ptr<RodMaterial> material =
      MaterialRegistry::instance().create("linear elastic");

    dealii::ParameterHandler prm;
    prm.enter_subsection("linear elastic");
    material->declare_parameters(prm);
    prm.leave_subsection();

    prm.parse_input_from_string("subsection linear elastic\n" + entries +
                                "\nend\n");
    prm.enter_subsection("linear elastic");
    material->parse_parameters(prm);
    prm.leave_subsection();

    const auto *rod = dynamic_cast<const LinearElasticRod *>(material.get());
    EXPECT_NE(rod, nullptr);
    return *rod;
  }

  /// Message of the exception @p entries cause, or "" if none.
  std::string
  linear_elastic_error(const std::string &entries)
  {
    try
      {
        parse_linear_elastic(entries);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

TEST(MaterialParameters, SectionCircleFromPoissonsRatio)
{
  const double E = 1e8, nu = 0.5, r = 5e-3;
  const auto   rod = parse_linear_elastic("set Young's modulus = 1e8\n"
                                          "set Poisson's ratio = 0.5\n"
                                          "set Cross section = circle\n"
                                          "set Radius = 5e-3");
  const auto  &k   = rod.stiffness();
  EXPECT_NEAR(k.EI1, 0.0490874, 1e-6 * 0.0490874);
  EXPECT_NEAR(k.EI2, 0.0490874, 1e-6 * 0.0490874);
  EXPECT_DOUBLE_EQ(k.EA, E * parameters_pi * r * r);
  EXPECT_DOUBLE_EQ(k.GJ,
                   E / (2. * (1. + nu)) * parameters_pi * std::pow(r, 4) / 2.);
}

TEST(MaterialParameters, SectionRectangleWithShearModulusAndNaturalShape)
{
  const double E = 2e9, G = 5e8, w = 0.02, h = 0.005;
  const auto   rod = parse_linear_elastic("set Young's modulus = 2e9\n"
                                          "set Shear modulus = 5e8\n"
                                          "set Poisson's ratio = -0.5\n"
                                          "set Cross section = rectangle\n"
                                          "set Width = 0.02\n"
                                          "set Height = 0.005\n"
                                          "set Natural curvature 1 = 1.5\n"
                                          "set Natural curvature 2 = -2\n"
                                          "set Natural twist = 0.25\n"
                                          "set Axial eigenstrain = -0.03");
  const auto  &k   = rod.stiffness();
  // Width along d1, height along d2; the given G overrides nu.
  EXPECT_DOUBLE_EQ(k.EA, E * w * h);
  EXPECT_DOUBLE_EQ(k.EI1, E * w * h * h * h / 12.);
  EXPECT_DOUBLE_EQ(k.EI2, E * h * w * w * w / 12.);
  // Tabulated Saint-Venant coefficient for a/b = 4.
  EXPECT_NEAR(k.GJ / (G * w * h * h * h), 0.281, 1e-3);

  const auto &shape = rod.natural_shape();
  EXPECT_EQ(shape.curvature1, 1.5);
  EXPECT_EQ(shape.curvature2, -2.);
  EXPECT_EQ(shape.twist, 0.25);
  EXPECT_EQ(shape.axial_eigenstrain, -0.03);
}

TEST(MaterialParameters, SectionExplicit)
{
  const auto rod =
    parse_linear_elastic("set Young's modulus = 10\n"
                         "set Shear modulus = 4\n"
                         "set Cross section = explicit\n"
                         "set Area = 2\nset I1 = 3\nset I2 = 5\nset J = 7");
  EXPECT_EQ(rod.stiffness().EA, 20.);
  EXPECT_EQ(rod.stiffness().EI1, 30.);
  EXPECT_EQ(rod.stiffness().EI2, 50.);
  EXPECT_EQ(rod.stiffness().GJ, 28.);
}

TEST(MaterialParameters, Direct)
{
  const auto rod =
    parse_linear_elastic("set Stiffness input = direct\n"
                         "set EA = 1e4\nset EI1 = 0.25\nset EI2 = 0.5\n"
                         "set GJ = 0.125");
  EXPECT_EQ(rod.stiffness().EA, 1e4);
  EXPECT_EQ(rod.stiffness().EI1, 0.25);
  EXPECT_EQ(rod.stiffness().EI2, 0.5);
  EXPECT_EQ(rod.stiffness().GJ, 0.125);
  EXPECT_EQ(rod.natural_shape().curvature1, 0.);
}

TEST(MaterialParameters, ErrorsNameTheEntry)
{
  const std::string direct = "set Stiffness input = direct\n"
                             "set EI1 = 1\nset EI2 = 1\nset GJ = 1\n";
  const std::string circle = "set Young's modulus = 1e8\nset Radius = 1e-3\n";

  const std::string negative_ea = linear_elastic_error(direct + "set EA = -1");
  EXPECT_NE(negative_ea.find("EA"), std::string::npos) << negative_ea;
  EXPECT_NE(negative_ea.find("-1"), std::string::npos) << negative_ea;

  const std::string unset_ea = linear_elastic_error(direct);
  EXPECT_NE(unset_ea.find("\"EA\""), std::string::npos) << unset_ea;

  const std::string zero_radius =
    linear_elastic_error("set Young's modulus = 1e8\nset Radius = 0");
  EXPECT_NE(zero_radius.find("\"Radius\""), std::string::npos) << zero_radius;

  const std::string zero_modulus =
    linear_elastic_error("set Young's modulus = 0\nset Radius = 1e-3");
  EXPECT_NE(zero_modulus.find("\"Young's modulus\""), std::string::npos)
    << zero_modulus;

  const std::string large_nu =
    linear_elastic_error(circle + "set Poisson's ratio = 0.7");
  EXPECT_NE(large_nu.find("Poisson's ratio"), std::string::npos) << large_nu;

  const std::string nu_minus_one =
    linear_elastic_error(circle + "set Poisson's ratio = -1");
  EXPECT_NE(nu_minus_one.find("\"Poisson's ratio\""), std::string::npos)
    << nu_minus_one;

  const std::string unknown_section =
    linear_elastic_error(circle + "set Cross section = hexagon");
  EXPECT_NE(unknown_section.find("Cross section"), std::string::npos)
    << unknown_section;
  EXPECT_NE(unknown_section.find("hexagon"), std::string::npos)
    << unknown_section;
}

TEST(MaterialParameters, RegistryListsKnownMaterials)
{
  const auto &registry = MaterialRegistry::instance();
  EXPECT_FALSE(registry.description("linear elastic").empty());

  try
    {
      registry.create("steel");
      FAIL() << "create(\"steel\") did not throw";
    }
  catch (const std::invalid_argument &e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find("unknown material \"steel\"; known materials: "),
                std::string::npos)
        << message;
      EXPECT_NE(message.find("linear elastic"), std::string::npos) << message;
    }
}

// The section a material was read with is what time stepping takes the
// inertia from: A = pi r^2 of a circle, and EA = E A; none for "direct".
TEST(MaterialParameters, CrossSectionOfTheStiffnessInput)
{
  const LinearElasticRod rod =
    parse_linear_elastic("set Young's modulus = 2e11\n"
                         "set Cross section = circle\n"
                         "set Radius = 0.01");
  ASSERT_TRUE(rod.cross_section().has_value());
  EXPECT_NEAR(rod.cross_section()->area,
              parameters_pi * 1e-4,
              1e-15 * parameters_pi * 1e-4);
  ASSERT_TRUE(rod.straight_linear_elastic_stiffness().has_value());
  EXPECT_NEAR(rod.straight_linear_elastic_stiffness()->EA,
              2e11 * parameters_pi * 1e-4,
              1e-15 * 2e11 * parameters_pi * 1e-4);

  const LinearElasticRod direct =
    parse_linear_elastic("set Stiffness input = direct\n"
                         "set EA = 1\nset EI1 = 2\n"
                         "set EI2 = 3\nset GJ = 4");
  EXPECT_FALSE(direct.cross_section().has_value());
}

// Dynamic relaxation's element has no natural shape: a twisted rod has no
// straight linear elastic stiffness.
TEST(MaterialParameters, NaturalShapeHasNoStraightStiffness)
{
  const LinearElasticRod rod =
    parse_linear_elastic("set Stiffness input = direct\n"
                         "set EA = 1\nset EI1 = 2\n"
                         "set EI2 = 3\nset GJ = 4\n"
                         "set Natural twist = 0.5");
  EXPECT_FALSE(rod.straight_linear_elastic_stiffness().has_value());
}
