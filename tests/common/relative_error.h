#ifndef RODNET_TESTS_COMMON_RELATIVE_ERROR_H
#define RODNET_TESTS_COMMON_RELATIVE_ERROR_H

#include <algorithm>

namespace rodnet::testing
{
  /**
   * The largest entry of |analytic - reference|, divided by the largest
   * entry of |analytic| where that exceeds 1: the error measure with which
   * the kernel tests compare a derivative with its finite difference, or a
   * quantity with its rotated or reset counterpart (an absolute error for
   * small quantities, a relative one for large).
   */
  template <typename Matrix>
  double
  relative_error(const Matrix &analytic, const Matrix &reference)
  {
    return (analytic - reference).cwiseAbs().maxCoeff() /
           std::max(1.0, analytic.cwiseAbs().maxCoeff());
  }
} // namespace rodnet::testing

#endif
