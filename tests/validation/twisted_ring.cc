// A closed rod whose material frame makes k half turns around it
// (Rod::frame_half_turns; odd k: a Moebius band). An isotropic, naturally
// straight rod closed into a circle of radius R with a uniform twist: the
// circle is an equilibrium of energy pi EI / R + GJ (k pi)^2 / (2 L),
// L = 2 pi R, and it is stable while the twist rate tau = k pi / L keeps
// GJ tau R below sqrt(3) EI (Michell 1889-90; for GJ = EI: k <= 3 stable,
// k = 4 not).
#include <core/rod_generators.h>
#include <core/rod_model.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/equilibrium_check.h>

#include <cmath>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;

  /// A circle of radius 1 in the xy-plane in @p n segments (d1 = e_z),
  /// naturally straight, EI = GJ = 1, with @p half_turns of its frame, its
  /// six rigid motions held by six position components: vertex 0 (at
  /// (1, 0, 0)) in x, y, z, vertex n/2 in y and z, vertex n/4 in z.
  std::unique_ptr<RodModel>
  twisted_ring(const unsigned int n, const unsigned int half_turns)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::ring(Vector3::Zero(),
                                      1.0,
                                      Vector3::UnitX(),
                                      Vector3::UnitY(),
                                      n),
                     true,
                     Vector3::UnitZ(),
                     "simple",
                     NaturalShape::straight);
    network->create_triangulation();
    network->set_frame_half_turns(0, half_turns);
    auto model = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
        std::make_shared<LinearElasticRod>(RodStiffness{1e4, 1, 1, 1})});
    const auto &v = model->network().rods()[0].vertices;
    model->fix_components("origin", v[0], {{true, true, true}});
    model->fix_components("opposite", v[n / 2], {{false, true, true}});
    model->fix_components("quarter", v[n / 4], {{false, false, true}});
    model->finalize();
    return model;
  }

  /// The energy of the undeformed twisted ring of @p n segments, and the
  /// norm of its residual into @p residual.
  double
  ring_energy(const unsigned int n, const unsigned int k, double &residual)
  {
    const auto       model  = twisted_ring(n, k);
    const VectorType u      = model->create_vector();
    VectorType       r      = model->create_vector();
    const double     energy = model->assemble(u, 1.0, &r, nullptr, true);
    residual                = r.l2_norm();
    return energy;
  }

  TEST(TwistedRing, CircleIsAnEquilibriumOfTheTwistEnergy)
  {
    // For k = 0 ... 3 the residual of the circle is at rounding and its
    // energy converges to the continuum's at second order (relative errors
    // 1.6e-4, 3.1e-4, 6.6e-4, 1.1e-3 at N = 100: the strains 2 sin of half
    // the hinge's angle); the closing hinge of an odd k (a Moebius band)
    // sees the same twist as the others, or the energy would be off by
    // order one.
    for (unsigned int k = 0; k <= 3; ++k)
      {
        const double exact = M_PI + k * k * M_PI / 4;
        double       residual_coarse, residual_fine;
        const double coarse = ring_energy(100, k, residual_coarse) - exact;
        const double fine   = ring_energy(200, k, residual_fine) - exact;
        const double order  = std::log2(coarse / fine);
        std::cout << "k = " << k << ": relative errors " << coarse / exact
                  << ", " << fine / exact << ", order " << order
                  << ", residuals " << residual_coarse << ", " << residual_fine
                  << std::endl;
        EXPECT_LT(std::abs(coarse), 2e-3 * exact) << "k = " << k;
        EXPECT_NEAR(order, 2.0, 0.05) << "k = " << k;
        EXPECT_LT(residual_coarse, 1e-9) << "k = " << k;
        EXPECT_LT(residual_fine, 1e-9) << "k = " << k;
      }
  }

  TEST(TwistedRing, MichellsStabilityLimit)
  {
    // GJ tau R < sqrt(3) EI: stable for k = 3 (tau R = 1.5), unstable for
    // k = 4 (tau R = 2), with the frames' common turn (a symmetry of the
    // isotropic rod) left out of the count.
    for (const unsigned int k : {1u, 3u, 4u})
      {
        const auto       model = twisted_ring(100, k);
        const VectorType u     = model->create_vector();
        MatrixType       tangent;
        model->initialize_matrix(tangent);
        const unsigned int negative =
          negative_eigenvalues(*model, u, 1.0, tangent);
        std::cout << "k = " << k << ": " << negative
                  << " negative eigenvalue(s)" << std::endl;
        EXPECT_EQ(negative == 0, k < 2 * std::sqrt(3.0)) << "k = " << k;
      }
  }
} // namespace
