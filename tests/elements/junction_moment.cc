// Moments at a junction (Lestringant & Kochmann 2020, appendix C): the angle
// theta_u(q) of eq. 33 with its derivatives, and the spatial moment of a
// function of the junction rotation.
//
// Finite differences: central, h = 1e-6 on the raw quaternion components
// and on the angle of the superposed spatial rotation.

#include <elements/junction_moment.h>

#include "junction_configurations.h"
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double       moment_step        = 1e-6;
  constexpr unsigned int n_moment_junctions = 200;

  TEST(RotationAngle, EqualsAngleOfRotationsAboutAxis)
  {
    std::mt19937 rng(31);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_moment_junctions; ++n)
      {
        const Vector3 u     = random_unit_vector(rng);
        const double  angle = uniform(rng, -3.1, 3.1);
        const double  scale = uniform(rng, 0.3, 3) * (n % 2 == 0 ? -1 : 1);
        max_difference =
          std::max(max_difference,
                   std::abs(rotation_angle_about(
                              uniform(rng, 0.5, 2) * u,
                              raw_quaternion(rotation_about(u, angle), scale))
                              .angle -
                            angle));
      }
    std::cout << "theta_u for rotations about u: max difference "
              << max_difference << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }

  // E = k theta_u^2 / 2 at a rotation by theta about u has the moment
  // k theta u.
  TEST(SpatialMoment, OfQuadraticAngleEnergy)
  {
    std::mt19937 rng(32);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_moment_junctions; ++n)
      {
        const Vector3         u     = random_unit_vector(rng);
        const double          theta = uniform(rng, -3, 3);
        const double          k     = uniform(rng, 0.1, 10);
        const Eigen::Vector4d q =
          raw_quaternion(rotation_about(u, theta), uniform(rng, 0.3, 3));
        const RotationAngle a = rotation_angle_about(u, q);
        max_difference =
          std::max(max_difference,
                   (spatial_moment(q, k * a.angle * a.gradient) - k * theta * u)
                     .cwiseAbs()
                     .maxCoeff());
      }
    std::cout << "moment of k theta^2 / 2: max difference to k theta u "
              << max_difference << std::endl;
    EXPECT_LT(max_difference, 1e-10);
  }

  // E(q) = A : R(q / |q|) for a random matrix A: the moment predicts the
  // derivative of E along q(eps) = exp(omega eps) q.
  TEST(SpatialMoment, PredictsDirectionalDerivative)
  {
    std::mt19937 rng(33);
    double       max_error = 0;
    for (unsigned int n = 0; n < n_moment_junctions; ++n)
      {
        Matrix3 A;
        for (unsigned int i = 0; i < 9; ++i)
          A(i) = uniform(rng, -1, 1);
        const auto energy = [&A](const Eigen::Vector4d &q) {
          return (A.cwiseProduct(unit_quaternion(q).toRotationMatrix())).sum();
        };
        const Eigen::Vector4d q =
          raw_quaternion(rotation_about(random_unit_vector(rng),
                                        uniform(rng, -3, 3)),
                         uniform(rng, 0.3, 3) * (n % 2 == 0 ? -1 : 1));

        Eigen::Vector4d gradient;
        for (unsigned int j = 0; j < 4; ++j)
          {
            Eigen::Vector4d plus = q, minus = q;
            plus[j] += moment_step;
            minus[j] -= moment_step;
            gradient[j] = (energy(plus) - energy(minus)) / (2 * moment_step);
          }

        const Vector3 omega = uniform(rng, 0.1, 2) * random_unit_vector(rng);
        const auto    superposed = [&](const double eps) {
          const Quaternion r =
            rotation_about(omega.normalized(), omega.norm() * eps) *
            Quaternion(q[0], q[1], q[2], q[3]);
          return Eigen::Vector4d(r.w(), r.x(), r.y(), r.z());
        };
        const double derivative =
          (energy(superposed(moment_step)) - energy(superposed(-moment_step))) /
          (2 * moment_step);
        max_error = std::max(max_error,
                             std::abs(spatial_moment(q, gradient).dot(omega) -
                                      derivative) /
                               std::max(1.0, std::abs(derivative)));
      }
    std::cout << "M . omega vs directional derivative: max relative error "
              << max_error << std::endl;
    EXPECT_LT(max_error, 1e-7);
  }

  TEST(RotationAngle, RefusesZeroInput)
  {
    EXPECT_THROW(rotation_angle_about(Vector3(0, 0, 1),
                                      Eigen::Vector4d::Zero()),
                 std::invalid_argument);
    EXPECT_THROW(rotation_angle_about(Vector3::Zero(),
                                      Eigen::Vector4d(1, 0, 0, 0)),
                 std::invalid_argument);
    EXPECT_THROW(spatial_moment(Eigen::Vector4d::Zero(),
                                Eigen::Vector4d(1, 0, 0, 0)),
                 std::invalid_argument);
  }
} // namespace
