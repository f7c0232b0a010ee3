#ifndef RODNET_TESTS_ELASTICA_EXACT_H
#define RODNET_TESTS_ELASTICA_EXACT_H

#include <cmath>

namespace rodnet::testing
{
  /// Tip of the clamped-free inextensible elastica under a dead
  /// compressive end load (Timoshenko & Gere; VALIDATION.md).
  struct ElasticaTip
  {
    double x;     ///< axial tip position / L, from the clamp
    double delta; ///< lateral tip deflection / L
  };

  /**
   * Exact post-buckled tip for load P (units B/L^2) above pi^2/4: with
   * k = sin(alpha/2), sqrt(P) = K(k), x/L = 2E(k)/K(k) - 1,
   * delta/L = 2k/K(k). k is found by bisection on K(k) = sqrt(P).
   */
  inline ElasticaTip
  elastica_tip(const double P)
  {
    double lo = 0, hi = 1 - 1e-15;
    for (int i = 0; i < 200; ++i)
      {
        const double mid                                   = 0.5 * (lo + hi);
        (std::comp_ellint_1(mid) < std::sqrt(P) ? lo : hi) = mid;
      }
    const double k  = 0.5 * (lo + hi);
    const double Kk = std::comp_ellint_1(k);
    return {2 * std::comp_ellint_2(k) / Kk - 1, 2 * k / Kk};
  }
} // namespace rodnet::testing

#endif
