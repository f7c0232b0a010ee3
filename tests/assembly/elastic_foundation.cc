// The elastic foundation family: its energy is the sum of the Winkler
// springs sum_v k l_v / 2 |P u_v|^2 written out here by hand (Voronoi
// lengths of a polyline with unequal segments, a junction vertex shared by
// two rods, a rod left off the foundation), it is added only before
// finalize(), and bad constants and unknown family names are refused with
// a message naming them. Derivatives: tests/assembly/global_derivatives.
#include <common/welded_knee.h>
#include <core/family_request.h>
#include <core/rod_model.h>
#include <materials/linear_elastic_rod.h>

#include <families/elastic_foundation.h>
#include <gtest/gtest.h>
#include <random>

namespace
{
  using namespace rodnet;

  TEST(ElasticFoundation, EnergyIsTheSumOfTheSprings)
  {
    const double  k    = 7;
    const Vector3 n    = Vector3(1, 2, 2) / 3;
    auto          bare = rodnet::testing::welded_knee_model(),
         founded       = rodnet::testing::welded_knee_model();
    ElasticFoundationParameters parameters;
    parameters.stiffness = k;
    parameters.direction = Vector3(1, 2, 2);
    parameters.rods      = {0, 1};
    founded->add_element_family(
      std::make_unique<ElasticFoundation>(founded->network(),
                                          founded->layout(),
                                          parameters));
    bare->finalize();
    founded->finalize();

    VectorType                             u = founded->create_vector();
    std::mt19937                           random(3);
    std::uniform_real_distribution<double> small(-0.1, 0.1);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = small(random);
    // Vertices of rods 0 and 1 along them, with their Voronoi lengths:
    // halves of the adjacent segments; the knee gets 1 (rod 0) + 1 (rod 1).
    const RodNetwork                                  &net = founded->network();
    const std::vector<std::pair<unsigned int, double>> springs = {
      {net.rods()[0].vertices[0], 0.5},
      {net.rods()[0].vertices[1], 1.5},
      {net.rods()[0].vertices[2], 2.0},
      {net.rods()[1].vertices[1], 1.25},
      {net.rods()[1].vertices[2], 0.25}};
    double expected = 0;
    for (const auto &[v, length] : springs)
      {
        Vector3 displacement;
        for (unsigned int c = 0; c < 3; ++c)
          displacement[c] = u[founded->layout().vertex_dof(v, c)];
        expected += 0.5 * k * length * std::pow(n.dot(displacement), 2);
      }
    const double energy =
      founded->elastic_energy(u, 0.0) - bare->elastic_energy(u, 0.0);
    EXPECT_NEAR(energy, expected, 1e-12 * expected);
    EXPECT_GT(expected, 0);
  }

  TEST(ElasticFoundation, IsAddedBeforeFinalizeOnly)
  {
    auto model = rodnet::testing::welded_knee_model();
    model->finalize();
    ElasticFoundationParameters parameters;
    parameters.stiffness = 1;
    EXPECT_THROW(model->add_element_family(
                   std::make_unique<ElasticFoundation>(model->network(),
                                                       model->layout(),
                                                       parameters)),
                 std::logic_error);
  }

  /// The message of the std::invalid_argument that @p build throws.
  template <class Build>
  std::string
  refusal(const Build &build)
  {
    try
      {
        build();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "(no exception)";
  }

  TEST(ElasticFoundation, RefusesBadConstants)
  {
    const auto                  model = rodnet::testing::welded_knee_model();
    const auto                 &net   = model->network();
    const auto                 &dofs  = model->layout();
    ElasticFoundationParameters parameters;
    parameters.stiffness = -1;
    EXPECT_NE(refusal([&] {
                ElasticFoundation(net, dofs, parameters);
              }).find("modulus k must be finite and not negative"),
              std::string::npos);
    parameters.stiffness = 1;
    parameters.rods      = {3};
    EXPECT_NE(refusal([&] {
                ElasticFoundation(net, dofs, parameters);
              }).find("rod 3 does not exist; the network has 3 rods"),
              std::string::npos);
    parameters.rods      = {};
    parameters.direction = Vector3::Zero();
    EXPECT_NE(refusal([&] {
                ElasticFoundation(net, dofs, parameters);
              }).find("direction of the springs must be a nonzero vector"),
              std::string::npos);
  }

  TEST(ElementFamilyRegistry, KnowsTheFoundationAndListsItForUnknownNames)
  {
    EXPECT_TRUE(element_family_registry().contains("Elastic foundation"));
    const std::string message =
      refusal([] { element_family_registry().create("Pasternak"); });
    EXPECT_NE(message.find("unknown element family \"Pasternak\"; known "
                           "element families: \"Bonding constraints\", "
                           "\"Elastic foundation\""),
              std::string::npos)
      << message;
  }
} // namespace
