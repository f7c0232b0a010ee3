// The clamped-free Euler-Bernoulli modes (analytic), for the references of
// tests/validation/moving_supports.cc and bench/spin_up.cc.
#ifndef RODNET_TESTS_COMMON_CANTILEVER_MODES_H
#define RODNET_TESTS_COMMON_CANTILEVER_MODES_H

#include <cmath>
#include <vector>

namespace rodnet
{
  namespace testing
  {
    /// A clamped-free mode on [0, L], phi = cosh(beta x) - cos(beta x) -
    /// sigma (sinh(beta x) - sin(beta x)), and its first two derivatives.
    struct CantileverMode
    {
      double beta, sigma;

      double
      value(const double x) const
      {
        const double b = beta * x;
        return std::cosh(b) - std::cos(b) -
               sigma * (std::sinh(b) - std::sin(b));
      }

      double
      slope(const double x) const
      {
        const double b = beta * x;
        return beta * (std::sinh(b) + std::sin(b) -
                       sigma * (std::cosh(b) - std::cos(b)));
      }

      double
      curvature(const double x) const
      {
        const double b = beta * x;
        return beta * beta *
               (std::cosh(b) + std::cos(b) -
                sigma * (std::sinh(b) + std::sin(b)));
      }
    };

    /// The first @p n (at most 5) modes of a cantilever of length
    /// @p length: beta L the roots of cos(beta L) cosh(beta L) = -1.
    inline std::vector<CantileverMode>
    cantilever_modes(const unsigned int n, const double length)
    {
      const double                roots[] = {1.8751040687119611,
                                             4.6940911329741745,
                                             7.8547574382376126,
                                             10.995540734875467,
                                             14.137168391046471};
      std::vector<CantileverMode> modes;
      for (unsigned int k = 0; k < n && k < 5; ++k)
        {
          const double b = roots[k];
          modes.push_back(
            {b / length,
             (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b))});
        }
      return modes;
    }
  } // namespace testing
} // namespace rodnet

#endif
