// Gradient and Hessians of the hinge kernels and of the stretch kernel
// against central finite differences, on random configurations with large
// bends, twists and reference-to-current rotations.
//
// Error norm: max_ij |analytic_ij - fd_ij| / max(1, max_ij |analytic_ij|),
// per strain component, maximized over all configurations. The gradient is
// differenced from strains() with h = 1e-6, the Hessian from the analytic
// gradient with h = 1e-6: truncation O(h^2) and round-off O(eps / h) are
// both far below the 1e-6 tolerance at this step.
//
// evaluate_weighted() and weighted_gradient() (the Hessians and the
// gradients summed with weights that depend on the strains, as the assembly
// asks for them) are checked against the same finite differences, summed
// with the weights.
//
// The simple kernel is also compared with Sacado's forward-over-forward AD
// of an independent, quaternion-by-quaternion transcription of Korner et
// al. eqs. 2.3, 2.8, 2.11 and 2.13; the classic kernel's closed forms with
// the same AD of frame_algebra.h's templated eqs. 11-12 of Lestringant &
// Kochmann (which the junction kernels differentiate that way).

#include <elements/frame_algebra.h>
#include <elements/hinge_kernel.h>
#include <elements/stretch_kernel.h>

#include "common/relative_error.h"
#include "common/weighted_sums.h"
#include "hinge_configurations.h"
#include <Sacado.hpp>
#include <algorithm>
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double       hinge_step               = 1e-6;
  constexpr double       hinge_tolerance          = 1e-6;
  constexpr double       hinge_symmetry_tolerance = 1e-10;
  constexpr unsigned int n_hinges                 = 120;

  struct ErrorSummary
  {
    double gradient  = 0;
    double hessian   = 0;
    double symmetry  = 0;
    double weighted  = 0;
    double value     = 0;
    double max_kappa = 0;

    void
    print(const std::string &name) const
    {
      std::cout << name << ": max relative FD error gradient " << gradient
                << ", Hessian " << hessian << ", weighted Hessian " << weighted
                << "; Hessian asymmetry " << symmetry
                << "; evaluate() vs strains() " << value << "; max |strain| "
                << max_kappa << std::endl;
    }
  };

  /**
   * Random hinges that are admissible for central differences: the simple
   * kernel picks the hemisphere of q (Re q >= 0), whose boundary Re q = 0
   * (a 180 degree rotation between adjacent frames) is a jump of kappa; the
   * classic holonomy jumps at |gamma| = pi. Configurations within a margin
   * of these are redrawn.
   */
  HingeCase
  admissible_hinge(std::mt19937 &rng, const HingeKernel &kernel)
  {
    while (true)
      {
        const HingeCase c = random_hinge(rng, 150 * pi / 180, 80 * pi / 180, 2);
        if (kernel.name() == "simple" &&
            std::abs((c.frame_prev().conjugate() * c.frame_next()).w()) < 0.05)
          continue;
        const double holonomy = kernel.strains(c.dofs, c.reference)[2] -
                                c.reference.twist - c.dofs[7] + c.dofs[3];
        if (kernel.name() == "classic" && std::abs(holonomy) > 3.0)
          continue;
        return c;
      }
  }

  void
  check_hinge_kernel(const std::string &name)
  {
    const auto   kernel = create_hinge_kernel(name);
    std::mt19937 rng(42);
    ErrorSummary errors;

    for (unsigned int n = 0; n < n_hinges; ++n)
      {
        const HingeCase c = admissible_hinge(rng, *kernel);
        HingeStrains    s;
        kernel->evaluate(c.dofs, c.reference, s, true);

        Eigen::Matrix<double, 3, n_hinge_dofs> fd_gradient;
        std::array<HingeMatrix, 3>             fd_hessian;
        for (unsigned int j = 0; j < n_hinge_dofs; ++j)
          {
            HingeVector plus = c.dofs, minus = c.dofs;
            plus[j] += hinge_step;
            minus[j] -= hinge_step;
            fd_gradient.col(j) = (kernel->strains(plus, c.reference) -
                                  kernel->strains(minus, c.reference)) /
                                 (2 * hinge_step);
            HingeStrains s_plus, s_minus;
            kernel->evaluate(plus, c.reference, s_plus, false);
            kernel->evaluate(minus, c.reference, s_minus, false);
            for (unsigned int k = 0; k < 3; ++k)
              fd_hessian[k].col(j) =
                (s_plus.gradient.row(k) - s_minus.gradient.row(k)).transpose() /
                (2 * hinge_step);
          }

        errors.weighted = std::max(errors.weighted,
                                   weighted_sums_error(*kernel,
                                                       c.dofs,
                                                       c.reference,
                                                       s,
                                                       fd_gradient,
                                                       fd_hessian));

        errors.value = std::max(errors.value,
                                (s.kappa - kernel->strains(c.dofs, c.reference))
                                  .cwiseAbs()
                                  .maxCoeff());
        errors.max_kappa =
          std::max(errors.max_kappa, s.kappa.cwiseAbs().maxCoeff());
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Eigen::Matrix<double, 1, n_hinge_dofs> g = s.gradient.row(k);
            const Eigen::Matrix<double, 1, n_hinge_dofs> fd =
              fd_gradient.row(k);
            errors.gradient = std::max(errors.gradient, relative_error(g, fd));
            errors.hessian =
              std::max(errors.hessian,
                       relative_error(s.hessian[k], fd_hessian[k]));
            errors.symmetry =
              std::max(errors.symmetry,
                       relative_error(s.hessian[k],
                                      HingeMatrix(s.hessian[k].transpose())));
          }
      }

    errors.print(name);
    EXPECT_LT(errors.gradient, hinge_tolerance);
    EXPECT_LT(errors.hessian, hinge_tolerance);
    EXPECT_LT(errors.weighted, hinge_tolerance);
    EXPECT_LT(errors.symmetry, hinge_symmetry_tolerance);
    EXPECT_LT(errors.value, 1e-13 * std::max(1.0, errors.max_kappa));
  }

  TEST(HingeDerivatives, Simple)
  {
    check_hinge_kernel("simple");
  }

  TEST(HingeDerivatives, Classic)
  {
    check_hinge_kernel("classic");
  }

  // Quaternions over any scalar type, for the AD reference of the simple
  // kernel.
  template <typename Number>
  struct ScalarQuaternion
  {
    Number                w;
    std::array<Number, 3> v;
  };

  template <typename Number>
  ScalarQuaternion<Number>
  operator*(const ScalarQuaternion<Number> &a,
            const ScalarQuaternion<Number> &b)
  {
    // Eq. 2.1.
    return {a.w * b.w - a.v[0] * b.v[0] - a.v[1] * b.v[1] - a.v[2] * b.v[2],
            {{a.w * b.v[0] + b.w * a.v[0] + a.v[1] * b.v[2] - a.v[2] * b.v[1],
              a.w * b.v[1] + b.w * a.v[1] + a.v[2] * b.v[0] - a.v[0] * b.v[2],
              a.w * b.v[2] + b.w * a.v[2] + a.v[0] * b.v[1] -
                a.v[1] * b.v[0]}}};
  }

  template <typename Number>
  ScalarQuaternion<Number>
  segment_frame(const std::array<Number, n_hinge_dofs> &u,
                const int                               first_vertex,
                const int                               twist,
                const Quaternion                       &reference_frame)
  {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const Vector3         T = reference_frame * Vector3::UnitZ();
    std::array<Number, 3> t;
    for (unsigned int d = 0; d < 3; ++d)
      t[d] = u[first_vertex + 4 + d] - u[first_vertex + d];
    const Number length = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (Number &component : t)
      component /= length;

    // Eq. 2.3.
    const Number c =
      sqrt(0.5 * (1.0 + T[0] * t[0] + T[1] * t[1] + T[2] * t[2]));
    const ScalarQuaternion<Number> p = {c,
                                        {{0.5 * (T[1] * t[2] - T[2] * t[1]) / c,
                                          0.5 * (T[2] * t[0] - T[0] * t[2]) / c,
                                          0.5 * (T[0] * t[1] - T[1] * t[0]) /
                                            c}}};
    const Number                   s = sin(0.5 * u[twist]);
    const ScalarQuaternion<Number> r = {cos(0.5 * u[twist]),
                                        {{s * T[0], s * T[1], s * T[2]}}};
    const ScalarQuaternion<Number> D = {
      reference_frame.w(),
      {{reference_frame.x(), reference_frame.y(), reference_frame.z()}}};
    // Eq. 2.8.
    return p * r * D;
  }

  TEST(HingeDerivatives, SimpleAgainstAutomaticDifferentiation)
  {
    using Inner         = Sacado::Fad::SFad<double, n_hinge_dofs>;
    using Number        = Sacado::Fad::SFad<Inner, n_hinge_dofs>;
    const auto   kernel = create_hinge_kernel("simple");
    std::mt19937 rng(43);
    double       max_gradient_error = 0, max_hessian_error = 0;
    for (unsigned int n = 0; n < n_hinges; ++n)
      {
        const HingeCase c = admissible_hinge(rng, *kernel);
        HingeStrains    s;
        kernel->evaluate(c.dofs, c.reference, s, true);

        std::array<Number, n_hinge_dofs> u;
        for (unsigned int i = 0; i < n_hinge_dofs; ++i)
          u[i] = Number(n_hinge_dofs, i, Inner(n_hinge_dofs, i, c.dofs[i]));
        ScalarQuaternion<Number> q =
          segment_frame(u, 0, 3, c.reference.frame_prev);
        for (Number &component : q.v)
          component = -component;
        q = q * segment_frame(u, 4, 7, c.reference.frame_next);
        // Eq. 2.13 in the hemisphere Re(q) >= 0.
        const double sign = q.w.val().val() < 0 ? -2.0 : 2.0;

        for (unsigned int k = 0; k < 3; ++k)
          {
            Eigen::Matrix<double, 1, n_hinge_dofs> gradient;
            HingeMatrix                            hessian;
            for (unsigned int i = 0; i < n_hinge_dofs; ++i)
              {
                gradient[i] = sign * q.v[k].dx(i).val();
                for (unsigned int j = 0; j < n_hinge_dofs; ++j)
                  hessian(i, j) = sign * q.v[k].dx(i).dx(j);
              }
            EXPECT_NEAR(s.kappa[k], sign * q.v[k].val().val(), 1e-14);
            const Eigen::Matrix<double, 1, n_hinge_dofs> g = s.gradient.row(k);
            max_gradient_error =
              std::max(max_gradient_error, relative_error(g, gradient));
            max_hessian_error = std::max(max_hessian_error,
                                         relative_error(s.hessian[k], hessian));
          }
      }
    std::cout << "simple vs AD: max relative error gradient "
              << max_gradient_error << ", Hessian " << max_hessian_error
              << std::endl;
    EXPECT_LT(max_gradient_error, 1e-12);
    EXPECT_LT(max_hessian_error, 1e-12);
  }

  TEST(HingeDerivatives, ClassicAgainstAutomaticDifferentiation)
  {
    using namespace frame_algebra;
    const auto   kernel = create_hinge_kernel("classic");
    std::mt19937 rng(44);
    double max_value_error = 0, max_gradient_error = 0, max_hessian_error = 0;
    for (unsigned int n = 0; n < n_hinges; ++n)
      {
        const HingeCase c = admissible_hinge(rng, *kernel);
        HingeStrains    s;
        kernel->evaluate(c.dofs, c.reference, s, true);

        const SegmentReference prev(c.reference.frame_prev),
          next(c.reference.frame_next);
        const auto strains = [&](const auto &u) {
          using Number        = std::decay_t<decltype(u[0])>;
          const auto position = [&u](const int offset) {
            return Vec<Number>{{u[offset], u[offset + 1], u[offset + 2]}};
          };
          return classic_strains(
            prev,
            segment_directors(prev, unit_edge(position(0), position(4)), u[3]),
            next,
            segment_directors(next, unit_edge(position(4), position(8)), u[7]),
            c.reference.twist);
        };
        HingeStrains ad;
        differentiate<3, n_hinge_dofs>(c.dofs,
                                       strains,
                                       ad.kappa,
                                       ad.gradient,
                                       &ad.hessian);

        max_value_error =
          std::max(max_value_error, (s.kappa - ad.kappa).cwiseAbs().maxCoeff());
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Eigen::Matrix<double, 1, n_hinge_dofs> g = s.gradient.row(k),
                                                         g_ad =
                                                           ad.gradient.row(k);
            max_gradient_error =
              std::max(max_gradient_error, relative_error(g, g_ad));
            max_hessian_error =
              std::max(max_hessian_error,
                       relative_error(s.hessian[k], ad.hessian[k]));
          }
      }
    std::cout << "classic vs AD: max error strains " << max_value_error
              << ", max relative error gradient " << max_gradient_error
              << ", Hessian " << max_hessian_error << std::endl;
    EXPECT_LT(max_value_error, 1e-13);
    EXPECT_LT(max_gradient_error, 1e-12);
    EXPECT_LT(max_hessian_error, 1e-12);
  }

  TEST(StretchDerivatives, FiniteDifferences)
  {
    std::mt19937 rng(7);
    ErrorSummary errors;
    for (unsigned int n = 0; n < n_hinges; ++n)
      {
        SegmentVector dofs;
        for (unsigned int j = 0; j < n_segment_dofs; ++j)
          dofs[j] = uniform(rng, -1, 1);
        const double  rest_length = uniform(rng, 0.2, 2);
        StretchStrain s;
        evaluate_stretch(dofs, rest_length, s, true);

        Eigen::Matrix<double, 1, n_segment_dofs> fd_gradient;
        SegmentMatrix                            fd_hessian;
        for (unsigned int j = 0; j < n_segment_dofs; ++j)
          {
            SegmentVector plus = dofs, minus = dofs;
            plus[j] += hinge_step;
            minus[j] -= hinge_step;
            StretchStrain s_plus, s_minus;
            evaluate_stretch(plus, rest_length, s_plus, false);
            evaluate_stretch(minus, rest_length, s_minus, false);
            fd_gradient[j] =
              (s_plus.strain - s_minus.strain) / (2 * hinge_step);
            fd_hessian.col(j) =
              (s_plus.gradient - s_minus.gradient) / (2 * hinge_step);
          }

        // evaluate() against the definition.
        const double length = (dofs.tail<3>() - dofs.head<3>()).norm();
        errors.value =
          std::max(errors.value,
                   std::abs(s.strain - (length / rest_length - 1)));
        errors.max_kappa = std::max(errors.max_kappa, std::abs(s.strain));
        errors.gradient =
          std::max(errors.gradient,
                   relative_error(Eigen::Matrix<double, 1, n_segment_dofs>(
                                    s.gradient.transpose()),
                                  fd_gradient));
        errors.hessian =
          std::max(errors.hessian, relative_error(s.hessian, fd_hessian));
        errors.symmetry =
          std::max(errors.symmetry,
                   relative_error(s.hessian,
                                  SegmentMatrix(s.hessian.transpose())));
      }
    errors.print("stretch");
    EXPECT_LT(errors.gradient, hinge_tolerance);
    EXPECT_LT(errors.hessian, hinge_tolerance);
    EXPECT_LT(errors.symmetry, hinge_symmetry_tolerance);
    EXPECT_LT(errors.value, 1e-14);
  }
} // namespace
