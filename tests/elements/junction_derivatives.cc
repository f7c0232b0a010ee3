// Gradient and Hessians of the junction kernel (both measures, both ghost
// spin options) and of the moment functions against central finite
// differences, on random junctions with rotations up to 120 degrees,
// physical segments bent up to 120 degrees from the ghost tangent, twist
// increments up to 2 and unnormalized quaternions.
//
// Error norm: max_ij |analytic_ij - fd_ij| / max(1, max_ij |analytic_ij|),
// per strain component, maximized over all configurations. The gradient is
// differenced from strains() with h = 1e-6, the Hessian from the kernel's
// gradient with h = 1e-6: truncation O(h^2) and round-off O(eps / h) are
// both far below the 1e-6 tolerance at this step. evaluate_weighted() and
// weighted_gradient() must give the weighted sums of the differenced
// Hessians and gradients to the same tolerance. The simple measure with the
// exact spin is the closed form of elements/simple_junction.h, the others
// are automatic derivatives in the central charts.

#include <elements/junction_kernel.h>
#include <elements/junction_moment.h>

#include "common/relative_error.h"
#include "common/weighted_sums.h"
#include "junction_configurations.h"
#include <algorithm>
#include <gtest/gtest.h>
#include <iostream>
#include <tuple>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double       junction_step               = 1e-6;
  constexpr double       junction_tolerance          = 1e-6;
  constexpr double       junction_symmetry_tolerance = 1e-10;
  constexpr unsigned int n_junctions                 = 120;

  /**
   * Random junctions admissible for central differences: away from the
   * jumps of the measures, i.e. the hemisphere boundary of the simple
   * measure (a 180 degree rotation between the two frames), |holonomy| = pi
   * for the classic one, and |w~| = pi for the exact ghost spin. Every
   * fourth junction rotates about its reference ghost tangent (L&K
   * appendix B, special case); the first one has the identity rotation.
   */
  JunctionCase
  admissible_junction(std::mt19937         &rng,
                      const JunctionKernel &kernel,
                      const GhostSpin       spin,
                      const unsigned int    n)
  {
    while (true)
      {
        JunctionCase c = random_junction(rng,
                                         n % 2 == 0,
                                         2 * pi / 3,
                                         2 * pi / 3,
                                         80 * pi / 180,
                                         2,
                                         n % 4 == 0);
        if (n == 0)
          c.dofs.segment<4>(junction_dofs::rotation) << -0.7, 0, 0, 0;

        const Vector3 ghost_tangent =
          c.reference.ghost_frame * Vector3::UnitZ();
        const double w = ghost_spin(c.q(), ghost_tangent, spin);
        if (spin == GhostSpin::exact && std::abs(w) > 3.0)
          continue;
        const Quaternion ghost =
          ghost_frame(c.q(), c.reference.ghost_frame, spin);
        const Quaternion segment  = c.segment_frame();
        const Quaternion relative = c.reference.ghost_first ?
                                      ghost.conjugate() * segment :
                                      segment.conjugate() * ghost;
        if (kernel.name() == "simple" && std::abs(relative.w()) < 0.05)
          continue;
        const double twist_increments = c.reference.ghost_first ?
                                          c.dofs[junction_dofs::twist] - w :
                                          w - c.dofs[junction_dofs::twist];
        const double holonomy         = kernel.strains(c.dofs, c.reference)[2] -
                                c.reference.twist - twist_increments;
        if (kernel.name() == "classic" && std::abs(holonomy) > 3.0)
          continue;
        return c;
      }
  }

  std::string
  spin_name(const GhostSpin spin)
  {
    return spin == GhostSpin::exact ? "exact" : "small_rotation";
  }

  class JunctionDerivatives
      : public ::testing::TestWithParam<std::tuple<std::string, GhostSpin>>
  {
  };

  TEST_P(JunctionDerivatives, FiniteDifferences)
  {
    const std::string    measure = std::get<0>(GetParam());
    const GhostSpin      spin    = std::get<1>(GetParam());
    const JunctionKernel kernel(measure, spin);
    std::mt19937         rng(11);
    double max_gradient = 0, max_hessian = 0, max_symmetry = 0, max_value = 0;
    double max_kappa = 0, max_weighted = 0;

    for (unsigned int n = 0; n < n_junctions; ++n)
      {
        const JunctionCase c = admissible_junction(rng, kernel, spin, n);
        JunctionStrains    s;
        kernel.evaluate(c.dofs, c.reference, s, true);

        Eigen::Matrix<double, 3, n_junction_dofs> fd_gradient;
        std::array<HingeMatrix, 3>                fd_hessian;
        for (unsigned int j = 0; j < n_junction_dofs; ++j)
          {
            JunctionVector plus = c.dofs, minus = c.dofs;
            plus[j] += junction_step;
            minus[j] -= junction_step;
            fd_gradient.col(j) = (kernel.strains(plus, c.reference) -
                                  kernel.strains(minus, c.reference)) /
                                 (2 * junction_step);
            JunctionStrains s_plus, s_minus;
            kernel.evaluate(plus, c.reference, s_plus, false);
            kernel.evaluate(minus, c.reference, s_minus, false);
            for (unsigned int k = 0; k < 3; ++k)
              fd_hessian[k].col(j) =
                (s_plus.gradient.row(k) - s_minus.gradient.row(k)).transpose() /
                (2 * junction_step);
          }

        // evaluate_weighted() and weighted_gradient(): the weighted sums
        // of the strains' Hessians and gradients.
        max_weighted = std::max(max_weighted,
                                weighted_sums_error(kernel,
                                                    c.dofs,
                                                    c.reference,
                                                    s,
                                                    fd_gradient,
                                                    fd_hessian));

        max_value = std::max(max_value,
                             (s.kappa - kernel.strains(c.dofs, c.reference))
                               .cwiseAbs()
                               .maxCoeff());
        max_kappa = std::max(max_kappa, s.kappa.cwiseAbs().maxCoeff());
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Eigen::Matrix<double, 1, n_junction_dofs> g =
              s.gradient.row(k);
            const Eigen::Matrix<double, 1, n_junction_dofs> fd =
              fd_gradient.row(k);
            max_gradient = std::max(max_gradient, relative_error(g, fd));
            max_hessian  = std::max(max_hessian,
                                   relative_error(s.hessian[k], fd_hessian[k]));
            max_symmetry =
              std::max(max_symmetry,
                       relative_error(s.hessian[k],
                                      HingeMatrix(s.hessian[k].transpose())));
          }
      }

    std::cout << measure << " junction, " << spin_name(spin)
              << " ghost spin: max relative FD error gradient " << max_gradient
              << ", Hessian " << max_hessian << "; Hessian asymmetry "
              << max_symmetry << "; weighted sums " << max_weighted
              << "; evaluate() vs strains() " << max_value << "; max |strain| "
              << max_kappa << std::endl;
    EXPECT_LT(max_gradient, junction_tolerance);
    EXPECT_LT(max_hessian, junction_tolerance);
    EXPECT_LT(max_symmetry, junction_symmetry_tolerance);
    EXPECT_LT(max_weighted, junction_tolerance);
    EXPECT_LT(max_value, 1e-13 * std::max(1.0, max_kappa));
  }

  INSTANTIATE_TEST_SUITE_P(
    MeasuresAndSpins,
    JunctionDerivatives,
    ::testing::Combine(::testing::Values("simple", "classic"),
                       ::testing::Values(GhostSpin::exact,
                                         GhostSpin::small_rotation)));

  TEST(RotationAngleDerivatives, FiniteDifferences)
  {
    std::mt19937 rng(12);
    double       max_gradient = 0, max_hessian = 0;
    unsigned int n = 0;
    while (n < n_junctions)
      {
        const Vector3    axis = uniform(rng, 0.5, 2) * random_unit_vector(rng);
        const Quaternion rotation =
          rotation_about(random_unit_vector(rng), uniform(rng, -2, 2));
        const Eigen::Vector4d q =
          raw_quaternion(rotation, uniform(rng, 0.3, 3));

        // Eq. 33 is singular where R v1 is parallel to the axis u. For any
        // unit v1 orthogonal to u, |R v1 . u| <= sqrt(1 - (u . R u)^2), so
        // |u . R u| >= 0.6 keeps |R v1 . u| <= 0.8 whatever v1 the function
        // picks.
        const Vector3 u = axis.normalized();
        if (std::abs((rotation * u).dot(u)) < 0.6)
          continue;
        ++n;

        const RotationAngle a = rotation_angle_about(axis, q);
        Eigen::Vector4d     fd_gradient;
        Eigen::Matrix4d     fd_hessian;
        for (unsigned int j = 0; j < 4; ++j)
          {
            Eigen::Vector4d plus = q, minus = q;
            plus[j] += junction_step;
            minus[j] -= junction_step;
            const RotationAngle a_plus  = rotation_angle_about(axis, plus);
            const RotationAngle a_minus = rotation_angle_about(axis, minus);
            fd_gradient[j] =
              (a_plus.angle - a_minus.angle) / (2 * junction_step);
            fd_hessian.col(j) =
              (a_plus.gradient - a_minus.gradient) / (2 * junction_step);
          }
        max_gradient =
          std::max(max_gradient, relative_error(a.gradient, fd_gradient));
        max_hessian =
          std::max(max_hessian, relative_error(a.hessian, fd_hessian));
        EXPECT_LT(relative_error(a.hessian,
                                 Eigen::Matrix4d(a.hessian.transpose())),
                  junction_symmetry_tolerance);
      }
    std::cout << "rotation_angle_about: max relative FD error gradient "
              << max_gradient << ", Hessian " << max_hessian << std::endl;
    EXPECT_LT(max_gradient, junction_tolerance);
    EXPECT_LT(max_hessian, junction_tolerance);
  }
} // namespace
