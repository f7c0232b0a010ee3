// Invariances of the hinge strains, which are functions of the current
// director frames only:
// - a rigid motion applied to the whole description (current positions,
//   and reference frames, which are tied to the reference configuration);
// - a reference reset (new reference frames = current frames, new reference
//   twist = current classic twist, zero twist increments).
// Also: the classic twist (L&K eq. 12) equals the spatial-transport twist
// of the current frames, and both kernels agree to leading order for small
// bends and twists.

#include <elements/hinge_kernel.h>

#include "common/relative_error.h"
#include "hinge_configurations.h"
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr unsigned int n_rotated_hinges = 200;

  class HingeInvariance : public ::testing::TestWithParam<std::string>
  {
  };

  TEST_P(HingeInvariance, RigidMotion)
  {
    const auto   kernel = create_hinge_kernel(GetParam());
    std::mt19937 rng(3);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_hinges; ++n)
      {
        const HingeCase c = random_hinge(rng, 150 * pi / 180, 80 * pi / 180, 2);
        const Quaternion rotation =
          rotation_about(random_unit_vector(rng), uniform(rng, -pi, pi));
        const Vector3 translation = 10 * random_unit_vector(rng);

        HingeCase moved = c;
        for (const int offset : {0, 4, 8})
          moved.dofs.segment<3>(offset) =
            rotation * c.dofs.segment<3>(offset) + translation;
        moved.reference.frame_prev = rotation * c.reference.frame_prev;
        moved.reference.frame_next = rotation * c.reference.frame_next;

        max_difference =
          std::max(max_difference,
                   relative_error(kernel->strains(c.dofs, c.reference),
                                  kernel->strains(moved.dofs,
                                                  moved.reference)));
      }
    std::cout << GetParam() << ": rigid motion changes the strains by "
              << max_difference << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }

  TEST_P(HingeInvariance, ReferenceReset)
  {
    const auto   kernel  = create_hinge_kernel(GetParam());
    const auto   classic = create_hinge_kernel("classic");
    std::mt19937 rng(4);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_hinges; ++n)
      {
        const HingeCase c = random_hinge(rng, 150 * pi / 180, 80 * pi / 180, 2);

        HingeCase reset            = c;
        reset.reference.frame_prev = c.frame_prev();
        reset.reference.frame_next = c.frame_next();
        reset.reference.twist      = classic->strains(c.dofs, c.reference)[2];
        reset.dofs[3]              = 0;
        reset.dofs[7]              = 0;

        max_difference =
          std::max(max_difference,
                   relative_error(kernel->strains(c.dofs, c.reference),
                                  kernel->strains(reset.dofs,
                                                  reset.reference)));
      }
    std::cout << GetParam() << ": reference reset changes the strains by "
              << max_difference << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }

  INSTANTIATE_TEST_SUITE_P(Kernels,
                           HingeInvariance,
                           ::testing::Values("simple", "classic"));


  // With the reference twist of L&K eq. 12 set to the classic twist of the
  // reference frames, tau is the classic twist of the current frames, built
  // here from the quaternion transports of Korner et al. eqs. 2.3 and 2.8.
  TEST(ClassicTwist, EqualsSpatialTransportTwist)
  {
    const auto   kernel = create_hinge_kernel("classic");
    std::mt19937 rng(5);
    double       max_difference = 0;
    for (unsigned int n = 0; n < n_rotated_hinges; ++n)
      {
        HingeCase c = random_hinge(rng, 150 * pi / 180, 80 * pi / 180, 2);
        c.reference.twist =
          classic_twist(c.reference.frame_prev, c.reference.frame_next);
        const double tau      = kernel->strains(c.dofs, c.reference)[2];
        const double expected = classic_twist(c.frame_prev(), c.frame_next());
        // Equal modulo 2 pi: the reference twist is unwrapped by increments.
        max_difference =
          std::max(max_difference,
                   std::abs(std::remainder(tau - expected, 2 * pi)));
      }
    std::cout << "classic twist vs spatial transport twist: " << max_difference
              << std::endl;
    EXPECT_LT(max_difference, 1e-12);
  }


  // A hinge whose current frames differ by a small rotation (bend and twist
  // of order `size`; straight reference, current tangents up to 60 degrees
  // away from it): both kernels measure its rotation vector in the director
  // frame, with the same signs, and differ at higher order (third order is
  // observed; second order is asserted).
  TEST(HingeKernels, AgreeForSmallBends)
  {
    const auto   simple  = create_hinge_kernel("simple");
    const auto   classic = create_hinge_kernel("classic");
    std::mt19937 rng(6);
    for (const double size : {1e-2, 1e-3})
      {
        double max_ratio = 0;
        for (unsigned int n = 0; n < n_rotated_hinges; ++n)
          {
            HingeCase c            = random_hinge(rng, size, 60 * pi / 180, 2);
            c.dofs[7]              = c.dofs[3] + uniform(rng, -size, size);
            c.reference.frame_next = c.reference.frame_prev;
            c.reference.twist      = 0;

            const Vector3 kappa_simple  = simple->strains(c.dofs, c.reference);
            const Vector3 kappa_classic = classic->strains(c.dofs, c.reference);
            EXPECT_LT((kappa_simple - kappa_classic).norm(), size * size);
            max_ratio =
              std::max(max_ratio,
                       (kappa_simple - kappa_classic).norm() / (size * size));
          }
        std::cout << "small bends of size " << size
                  << ": max |kappa_simple - kappa_classic| / size^2 = "
                  << max_ratio << std::endl;
      }
  }
} // namespace
