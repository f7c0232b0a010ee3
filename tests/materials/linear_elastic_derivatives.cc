// Energy, stress and tangent of LinearElasticRod: the derivatives against
// central differences of the energy, the energy against hand evaluations.

#include <deal.II/base/numbers.h>

#include <materials/cross_section.h>
#include <materials/linear_elastic_rod.h>

#include <gtest/gtest.h>
#include <random>

using namespace rodnet;

namespace
{
  // Stiffnesses and natural shape of different magnitudes, so that a swapped
  // index or a missing natural term shows.
  const RodStiffness    stiffness{2.3e3, 0.7, 1.9, 0.45};
  const RodNaturalShape shape{3.1, -1.7, 0.8, 0.012};

  constexpr double tolerance = 1e-7;
} // namespace

TEST(LinearElasticDerivatives, HingeStressAndTangentMatchCentralDifferences)
{
  const LinearElasticRod material(stiffness, shape);

  std::mt19937                           generator(20240611);
  std::uniform_real_distribution<double> strain(-0.3, 0.3);
  std::uniform_real_distribution<double> length(0.01, 0.2);

  for (unsigned int sample = 0; sample < 50; ++sample)
    {
      const double              l = length(generator);
      const Eigen::Vector3d     kappa(strain(generator),
                                  strain(generator),
                                  strain(generator));
      const MaterialResponse<3> response = material.hinge_energy(kappa, l);

      // The energy is quadratic, so central differences have no truncation
      // error and h only has to keep round-off (~1e-16 W / h) small.
      const double    h = 1e-4;
      Eigen::Vector3d fd_stress;
      Eigen::Matrix3d fd_tangent;
      for (unsigned int i = 0; i < 3; ++i)
        {
          const Eigen::Vector3d step  = h * Eigen::Vector3d::Unit(i);
          const auto            plus  = material.hinge_energy(kappa + step, l);
          const auto            minus = material.hinge_energy(kappa - step, l);
          fd_stress(i)                = (plus.energy - minus.energy) / (2. * h);
          fd_tangent.col(i)           = (plus.stress - minus.stress) / (2. * h);
        }

      EXPECT_LE((fd_stress - response.stress).norm(),
                tolerance * response.stress.norm())
        << "sample " << sample << ": analytic " << response.stress.transpose()
        << ", central differences " << fd_stress.transpose();
      EXPECT_LE((fd_tangent - response.tangent).norm(),
                tolerance * response.tangent.norm())
        << "sample " << sample << ":\nanalytic\n"
        << response.tangent << "\ncentral differences\n"
        << fd_tangent;
    }
}

TEST(LinearElasticDerivatives, SegmentStressAndTangentMatchCentralDifferences)
{
  const LinearElasticRod material(stiffness, shape);

  std::mt19937                           generator(7);
  std::uniform_real_distribution<double> strain(-0.1, 0.1);
  std::uniform_real_distribution<double> length(0.01, 0.2);

  for (unsigned int sample = 0; sample < 50; ++sample)
    {
      const double l        = length(generator);
      const double eps      = strain(generator);
      const auto   response = material.segment_energy(eps, l);

      const double h          = 1e-6;
      const auto   plus       = material.segment_energy(eps + h, l);
      const auto   minus      = material.segment_energy(eps - h, l);
      const double fd_stress  = (plus.energy - minus.energy) / (2. * h);
      const double fd_tangent = (plus.stress(0) - minus.stress(0)) / (2. * h);

      EXPECT_LE(std::abs(fd_stress - response.stress(0)),
                tolerance * std::abs(response.stress(0)))
        << "sample " << sample;
      EXPECT_LE(std::abs(fd_tangent - response.tangent(0)),
                tolerance * std::abs(response.tangent(0)))
        << "sample " << sample;
    }
}

TEST(LinearElasticDerivatives, PureBendingOfCircularRodByHand)
{
  // Steel-like rod bent about d1 only: W = l/2 E (pi r^4 / 4) (kappa_1/l)^2.
  const double E = 2.1e11, nu = 0.3, r = 2e-3, l = 0.05, kappa1 = 0.02;
  const double pi = dealii::numbers::PI;
  const LinearElasticRod material(
    stiffness_from_section(E, E / (2. * (1. + nu)), circle_section(r)));

  const auto   response = material.hinge_energy({kappa1, 0., 0.}, l);
  const double by_hand =
    l / 2. * E * pi * std::pow(r, 4) / 4. * std::pow(kappa1 / l, 2);
  EXPECT_NEAR(response.energy, by_hand, 1e-12 * by_hand);
  // Bending moment M = E I kappa_1 / l.
  EXPECT_NEAR(response.stress(0),
              E * pi * std::pow(r, 4) / 4. * kappa1 / l,
              1e-12 * by_hand / kappa1);
  EXPECT_EQ(response.stress(1), 0.);
  EXPECT_EQ(response.stress(2), 0.);
}

TEST(LinearElasticDerivatives, PureTwistAndStretchByHand)
{
  const double           l = 0.04, l0 = 0.03, tau = 0.01, eps = 2e-3;
  const LinearElasticRod material(stiffness);

  // W = l/2 GJ (tau/l)^2 and W = l0/2 EA eps^2.
  EXPECT_DOUBLE_EQ(material.hinge_energy({0., 0., tau}, l).energy,
                   l / 2. * 0.45 * (tau / l) * (tau / l));
  EXPECT_DOUBLE_EQ(material.segment_energy(eps, l0).energy,
                   l0 / 2. * 2.3e3 * eps * eps);
}

TEST(LinearElasticDerivatives, NaturalShapeIsStressFree)
{
  const LinearElasticRod material(stiffness, shape);
  const double           l = 0.07;

  // The integrated strain of the natural shape is l times its density.
  const auto hinge = material.hinge_energy({l * shape.curvature1,
                                            l * shape.curvature2,
                                            l * shape.twist},
                                           l);
  EXPECT_NEAR(hinge.energy, 0., 1e-15);
  EXPECT_NEAR(hinge.stress.norm(), 0., 1e-13);

  const auto segment = material.segment_energy(shape.axial_eigenstrain, l);
  EXPECT_NEAR(segment.energy, 0., 1e-15);
  EXPECT_NEAR(segment.stress(0), 0., 1e-13);

  // Away from it, the natural curvature shifts the energy as in
  // Lestringant & Kochmann eq. 16.
  const auto bent = material.hinge_energy({0., 0., 0.}, l);
  EXPECT_NEAR(bent.energy,
              l / 2. * (0.7 * 3.1 * 3.1 + 1.9 * 1.7 * 1.7 + 0.45 * 0.8 * 0.8),
              1e-14);
}

TEST(LinearElasticDerivatives, RejectsNonPositiveStiffness)
{
  EXPECT_THROW(LinearElasticRod({1., 1., 0., 1.}), std::exception);
  EXPECT_THROW(LinearElasticRod({1., 1., 1., -1.}), std::exception);
  EXPECT_THROW(LinearElasticRod({1., 1., 1., 1.}, {0., 0., 0., -1.}),
               std::exception);
}
