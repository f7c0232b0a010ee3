// The bonding constraint family, a family with a DoF block of its own:
// its residual and tangent against central differences at a random state
// (bonds to a point and between vertices, one at a junction's second rod
// end, whose DoFs are the junction vertex's), its energy k mu . g written
// out by hand, the block numbered after all other DoFs with the roles,
// names and output the family declared, and the scene entry's errors.
#include <deal.II/base/parameter_handler.h>

#include <common/assembled_derivatives.h>
#include <common/welded_knee.h>
#include <core/rod_model.h>
#include <families/bonding_constraint.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/checks/dof_roles.h>

#include <algorithm>
#include <gtest/gtest.h>
#include <iostream>
#include <random>

namespace
{
  using namespace rodnet;

  /// The family of @p text's bonds ("a = b; c = x, y, z") on @p model.
  std::unique_ptr<ElementFamily>
  bonds_from_scene(const RodModel &model, const std::string &text)
  {
    dealii::ParameterHandler prm;
    BondingConstraintRequest request;
    request.declare_parameters(prm);
    prm.set("Bonds", text);
    request.parse_parameters(prm);
    EXPECT_TRUE(request.requested());
    return request.create(model);
  }

  /// Random displacements, twists and multipliers of size @p scale.
  VectorType
  random_bonded_state(const RodModel &model, const double scale)
  {
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> uniform(-scale, scale);
    VectorType                             u = model.create_vector();
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = uniform(random);
    model.layout().junction_constraints().distribute(u);
    return u;
  }

  TEST(BondingConstraint, DerivativesMatchFiniteDifferences)
  {
    auto model = rodnet::testing::welded_knee_model();
    model->add_element_family(
      bonds_from_scene(*model, "2:end = 0.5, 1.5, 0.2; 1:start = 2:start"));
    model->clamp_end("clamp", 0, true);
    model->finalize();
    const VectorType u = random_bonded_state(*model, 0.05);
    const rodnet::testing::DerivativeErrors errors =
      rodnet::testing::assembled_derivative_errors(*model, u, 0.6, 1e-6);
    std::cout << "residual error " << errors.residual << ", tangent error "
              << errors.tangent << std::endl;
    EXPECT_LT(errors.residual, 1e-6);
    EXPECT_LT(errors.tangent, 1e-6);
  }

  // k mu . g with g = u_a - u_b - lambda (X_b - X_a) or u_a - lambda
  // (p - X_a), k = EI / l^3 of the stiffest segment at the bonded vertices
  // (max(2, 3) / 1^3 at rod 2's start, 3 / 0.5^3 at rod 1's end).
  TEST(BondingConstraint, EnergyIsTheMultipliersTimesTheScaledGaps)
  {
    auto bare   = rodnet::testing::welded_knee_model(),
         bonded = rodnet::testing::welded_knee_model();
    bonded->add_element_family(
      bonds_from_scene(*bonded, "2:start = 0:end; 1:end = 3, 2.5, 1"));
    bare->finalize();
    bonded->finalize();
    ASSERT_EQ(bonded->layout().n_dofs(), bare->layout().n_dofs() + 6);
    const VectorType u      = random_bonded_state(*bonded, 0.1);
    VectorType       u_bare = bare->create_vector();
    for (unsigned int i = 0; i < u_bare.size(); ++i)
      u_bare[i] = u[i];
    const double lambda = 0.3;
    const auto   dof    = [&](const unsigned int v, const unsigned int c) {
      return u[bonded->layout().vertex_dof(v, c)];
    };
    const auto   &rods  = bonded->network().rods();
    const auto    first = bare->layout().n_dofs();
    const Vector3 gap_0 = Vector3(3, 0, 0) - Vector3(0, 5, 0);
    const Vector3 gap_1(0, 0, 1);
    double        expected = 0;
    for (unsigned int c = 0; c < 3; ++c)
      {
        expected += 3.0 * u[first + c] *
                    (dof(rods[2].vertices[0], c) - dof(rods[0].vertices[2], c) -
                     lambda * gap_0[c]);
        expected += 3 / 0.125 * u[first + 3 + c] *
                    (dof(rods[1].vertices[2], c) - lambda * gap_1[c]);
      }
    const double energy =
      bonded->assemble(u, lambda, nullptr, nullptr, false) -
      bare->assemble(u_bare, lambda, nullptr, nullptr, false);
    EXPECT_NEAR(energy, expected, 1e-12 * std::abs(expected));
  }

  // The block comes after every other DoF; DofRoles calls its DoFs
  // multipliers, at the bonded vertex, named as the family labels them;
  // the output writes -k mu as the "bond_force" at that vertex.
  TEST(BondingConstraint, DeclaredBlockIsNumberedNamedAndWritten)
  {
    auto model = rodnet::testing::welded_knee_model();
    model->add_element_family(bonds_from_scene(*model, "1:end = 3, 3, 0.5"));
    model->clamp_end("clamp", 0, true);
    model->finalize();
    // The knee's quaternion, then the bonds.
    const auto &blocks = model->layout().declared_blocks();
    ASSERT_EQ(blocks.size(), 2u);
    EXPECT_EQ(blocks[0].owner, "junction elements");
    const DofBlock &bonds = blocks[1];
    EXPECT_EQ(bonds.owner, "bonding constraints");
    EXPECT_EQ(bonds.first + 3, model->layout().n_dofs());
    EXPECT_EQ(model->multiplier_dofs().size(), 3u);
    EXPECT_EQ(model->multiplier_dofs().back(), bonds.first + 2);
    const DofRoles     roles(*model);
    const unsigned int end = model->network().rods()[1].vertices[2];
    EXPECT_EQ(roles.kind(bonds.first + 1), DofRoles::Kind::multiplier);
    EXPECT_EQ(roles.owner(bonds.first + 1), end);
    EXPECT_EQ(roles.describe(bonds.first + 1),
              "bond 0 (1:end = 3, 3, 0.5), its y component");

    VectorType u           = model->create_vector();
    u[bonds.first + 2]     = 0.25;
    const OutputFields out = model->output_fields(u);
    const auto         field =
      std::find_if(out.vertex_fields.begin(),
                   out.vertex_fields.end(),
                   [](const auto &f) { return f.name == "bond_force"; });
    ASSERT_NE(field, out.vertex_fields.end());
    EXPECT_EQ(field->components, 3u);
    EXPECT_DOUBLE_EQ(field->values[3 * end + 2], -0.25 * 3 / 0.125);
    EXPECT_EQ(field->values[3 * end + 1], 0.0);
  }

  /// The message of the std::invalid_argument that @p f throws.
  template <class F>
  std::string
  bond_refusal(const F &f)
  {
    try
      {
        f();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "(nothing thrown)";
  }

  TEST(BondingConstraint, BadBondsAreRefusedByName)
  {
    auto model = rodnet::testing::welded_knee_model();
    EXPECT_EQ(bond_refusal(
                [&] { bonds_from_scene(*model, "0:end = 1:start"); }),
              "entry \"Bonding constraints/Bonds\": bond \"0:end = "
              "1:start\" ties a vertex to itself");
    EXPECT_NE(bond_refusal([&] {
                bonds_from_scene(*model, "0:end");
              }).find("is not \"a = b\""),
              std::string::npos);
    EXPECT_NE(bond_refusal([&] {
                bonds_from_scene(*model, "0:end = 7:start");
              }).find("Bonding constraints/Bonds"),
              std::string::npos);

    EXPECT_EQ(bond_refusal([&] {
                bonds_from_scene(*model, "0:start = 1:end; 1:end = 0:start");
              }),
              "entry \"Bonding constraints/Bonds\": bond \"1:end = "
              "0:start\" ties what bond \"0:start = 1:end\" ties already "
              "(its constraints would be redundant)");
    EXPECT_NE(bond_refusal([&] {
                bonds_from_scene(*model,
                                 "0:start = 1, 0, 0; 0:start = 2, 0, 0");
              }).find("ties what bond \"0:start = 1, 0, 0\" ties already"),
              std::string::npos);
    EXPECT_EQ(
      bond_refusal([&] { bonds_from_scene(*model, "0:start = nan, 0, 0"); }),
      "entry \"Bonding constraints/Bonds\": bond \"0:start = nan, 0, 0\": "
      "the point is not finite");

    // A bond at a clamped vertex would leave its multipliers' rows empty.
    model->add_element_family(bonds_from_scene(*model, "0:start = 0, 0, 1"));
    model->clamp_end("clamp", 0, true);
    EXPECT_EQ(bond_refusal([&] { model->finalize(); }),
              "bonding constraints: bond 0 (0:start = 0, 0, 1), its x "
              "component constrains DoFs that the supports hold already; "
              "remove the constraint or the support");
  }
} // namespace
