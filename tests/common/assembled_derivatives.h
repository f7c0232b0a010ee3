// The assembled residual and tangent of a model against central finite
// differences of its assembled energy and residual, for the derivative
// tests of tests/assembly.
#ifndef RODNET_TESTS_COMMON_ASSEMBLED_DERIVATIVES_H
#define RODNET_TESTS_COMMON_ASSEMBLED_DERIVATIVES_H

#include <core/rod_model.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rodnet::testing
{
  /// Largest errors relative to the largest entries.
  struct DerivativeErrors
  {
    double residual = 0;
    double tangent  = 0;
  };

  /// The residual against the central difference of the energy and the
  /// tangent against that of the residual, at @p u and @p load_factor,
  /// step @p h, without constraints; @p tangent_only is added to the
  /// difference's diagonal (a term that only the tangent carries), if not
  /// empty.
  inline DerivativeErrors
  assembled_derivative_errors(const RodModel            &model,
                              const VectorType          &u,
                              const double               load_factor,
                              const double               h,
                              const std::vector<double> &tangent_only = {})
  {
    VectorType r = model.create_vector();
    MatrixType k;
    model.initialize_matrix(k);
    model.assemble(u, load_factor, &r, &k, false);
    double     max_r = 0, max_k = 0, err_r = 0, err_k = 0;
    VectorType r_plus  = model.create_vector();
    VectorType r_minus = model.create_vector();
    for (unsigned int j = 0; j < u.size(); ++j)
      {
        VectorType up = u, um = u;
        up[j] += h;
        um[j] -= h;
        const double fd_r =
          (model.assemble(up, load_factor, &r_plus, nullptr, false) -
           model.assemble(um, load_factor, &r_minus, nullptr, false)) /
          (2 * h);
        max_r = std::max(max_r, std::abs(r[j]));
        err_r = std::max(err_r, std::abs(fd_r - r[j]));
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            const double fd_k =
              (r_plus[i] - r_minus[i]) / (2 * h) +
              (i == j && !tangent_only.empty() ? tangent_only[i] : 0.0);
            max_k = std::max(max_k, std::abs(k.el(i, j)));
            err_k = std::max(err_k, std::abs(fd_k - k.el(i, j)));
          }
      }
    return {err_r / max_r, err_k / max_k};
  }
} // namespace rodnet::testing

#endif
