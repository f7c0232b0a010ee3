#ifndef RODNET_TESTS_COMMON_WEIGHTED_SUMS_H
#define RODNET_TESTS_COMMON_WEIGHTED_SUMS_H

#include <elements/hinge_kernel.h>

#include "relative_error.h"
#include <algorithm>
#include <array>

namespace rodnet::testing
{
  /// Fixed strain weights, and the strains they were asked at: the stress
  /// that the kernel tests hand to evaluate_weighted() and
  /// weighted_gradient().
  struct RecordingWeights : StrainWeights
  {
    Vector3
    at(const Vector3 &kappa) const override
    {
      asked_at = kappa;
      return weights;
    }
    Vector3 weights{0.3, -1.2, 0.7};
    // Far from any strain: an error if at() was never asked.
    mutable Vector3 asked_at = Vector3::Constant(1e30);
  };

  /**
   * The largest relative error of a kernel's evaluate_weighted() and
   * weighted_gradient() (hinge or junction, 11 DoFs) at @p dofs against the
   * weighted sums of the finite-difference Hessians @p fd_hessian and
   * gradient @p fd_gradient, of the strain gradient against evaluate()'s
   * @p strains, and of the strains the weights were asked at.
   */
  template <class Kernel, class Reference>
  double
  weighted_sums_error(const Kernel                                 &kernel,
                      const HingeVector                            &dofs,
                      const Reference                              &reference,
                      const HingeStrains                           &strains,
                      const Eigen::Matrix<double, 3, n_hinge_dofs> &fd_gradient,
                      const std::array<HingeMatrix, 3>             &fd_hessian)
  {
    const RecordingWeights weights;
    HingeStrains           s_weighted;
    HingeMatrix            weighted;
    kernel.evaluate_weighted(dofs, reference, weights, s_weighted, weighted);
    HingeMatrix fd_weighted = HingeMatrix::Zero();
    for (unsigned int k = 0; k < 3; ++k)
      fd_weighted += weights.weights[k] * fd_hessian[k];

    const RecordingWeights gradient_weights;
    HingeVector            weighted_gradient;
    const Vector3          kappa = kernel.weighted_gradient(dofs,
                                                   reference,
                                                   gradient_weights,
                                                   weighted_gradient);
    return std::max({relative_error(weighted, fd_weighted),
                     relative_error(s_weighted.gradient, strains.gradient),
                     relative_error(weights.asked_at, strains.kappa),
                     relative_error(weighted_gradient,
                                    HingeVector(fd_gradient.transpose() *
                                                gradient_weights.weights)),
                     relative_error(kappa, strains.kappa),
                     relative_error(gradient_weights.asked_at, strains.kappa)});
  }
} // namespace rodnet::testing

#endif
