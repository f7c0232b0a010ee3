// The assembled residual is the gradient of the assembled total potential
// energy and the assembled tangent is the gradient of the residual (central
// finite differences), for both kernels, with and without an elastic
// foundation (in every direction, or along one), with and without a moment
// about a fixed axis at a rotation handle on the free end, extensible or
// inextensible (the Lagrangian with its multipliers, at random multiplier
// values), on a rod in a random state whose reference was reset away from
// the undeformed one: this
// checks the DoF maps, the chain rule, the constraint handling and the loop
// over element families together.
#include <common/assembled_derivatives.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <families/elastic_foundation.h>
#include <gtest/gtest.h>
#include <random>

namespace
{
  using namespace rodnet;

  /// No foundation, one in every direction, one along a skew direction.
  enum class Foundation
  {
    none,
    isotropic,
    directional
  };

  std::unique_ptr<RodModel>
  make_model(const std::string &kernel,
             const Foundation   foundation,
             const bool         end_moment,
             const bool         inextensible)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::helix(0.5, 0.1, 0.5, 12),
                     false,
                     Vector3(0.3, 0.2, 1.0),
                     kernel);
    const unsigned int handle =
      end_moment ?
        network->add_rotation_handle("end",
                                     network->rods()[0].vertices.back()) :
        0;
    network->create_triangulation();
    network->set_inextensible(0, inextensible);
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
        std::make_shared<LinearElasticRod>(
          RodStiffness{100, 2, 3, 1.5},
          RodNaturalShape{0.3, -0.2, 0.1, 0.01})});
    model->add_point_force(model->network().rods()[0].vertices.back(),
                           Vector3(0.1, -0.2, 0.3));
    model->add_distributed_force(0, Vector3(0, 0, -0.5));
    if (foundation != Foundation::none)
      {
        ElasticFoundationParameters parameters;
        parameters.stiffness = 40;
        if (foundation == Foundation::directional)
          parameters.direction = Vector3(0.2, 0.3, 1.0);
        model->add_element_family(
          std::make_unique<ElasticFoundation>(model->network(),
                                              model->layout(),
                                              parameters));
      }
    if (end_moment)
      // The potential -M theta_u(q Q) of the junction's whole rotation, Q
      // its rotation at the reference (a reset below moves it).
      model->add_moment(handle, Vector3(0.3, -0.4, 0.8).normalized(), 0.9);
    model->finalize();
    return model;
  }

  class GlobalDerivatives : public ::testing::TestWithParam<
                              std::tuple<std::string, Foundation, bool, bool>>
  {
  };

  TEST_P(GlobalDerivatives, ResidualAndTangentMatchFiniteDifferences)
  {
    const auto [kernel, foundation, end_moment, inextensible] = GetParam();
    const auto model = make_model(kernel, foundation, end_moment, inextensible);
    VectorType u     = model->create_vector();
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> small(-0.05, 0.05);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] = small(random);
    // A reset moves the reference away from the undeformed state, then a
    // further perturbation gives non-zero increments.
    model->reset_reference(u);
    for (unsigned int i = 0; i < u.size(); ++i)
      u[i] += small(random);

    const auto errors =
      rodnet::testing::assembled_derivative_errors(*model, u, 0.7, 1e-6);
    std::cout << kernel << ", foundation " << static_cast<int>(foundation)
              << (end_moment ? ", end moment" : "")
              << (inextensible ? ", inextensible" : "") << ": residual error "
              << errors.residual << ", tangent error " << errors.tangent
              << std::endl;
    EXPECT_LT(errors.residual, 1e-6);
    EXPECT_LT(errors.tangent, 1e-6);
  }

  INSTANTIATE_TEST_SUITE_P(
    HingeKernels,
    GlobalDerivatives,
    ::testing::Combine(::testing::Values("simple", "classic"),
                       ::testing::Values(Foundation::none,
                                         Foundation::isotropic,
                                         Foundation::directional),
                       ::testing::Bool(),
                       ::testing::Bool()));
} // namespace
