#include <solvers/continuation/limit_point_estimate.h>

#include <cmath>

namespace rodnet
{
  double
  parabola_extremum(const std::array<std::pair<double, double>, 3> &p)
  {
    const auto [s0, l0] = p[0];
    const auto [s1, l1] = p[1];
    const auto [s2, l2] = p[2];
    // Newton's form: lambda = l0 + d01 (s - s0) + d012 (s - s0)(s - s1).
    const double d01  = (l1 - l0) / (s1 - s0);
    const double d12  = (l2 - l1) / (s2 - s1);
    const double d012 = (d12 - d01) / (s2 - s0);
    if (d012 == 0 || !std::isfinite(d012))
      return l1;
    const double s_turn = 0.5 * (s0 + s1) - d01 / (2 * d012);
    return l0 + d01 * (s_turn - s0) + d012 * (s_turn - s0) * (s_turn - s1);
  }

  double
  slope_extremum(const double p_s,
                 const double p_lambda,
                 const double p_slope,
                 const double q_s,
                 const double q_slope)
  {
    // lambda' = p_slope + (q_slope - p_slope) (s - p_s) / (q_s - p_s)
    // vanishes at s_turn; lambda gains the triangle under lambda' there.
    const double s_turn = (q_s - p_s) * p_slope / (p_slope - q_slope);
    return p_lambda + 0.5 * p_slope * s_turn;
  }
} // namespace rodnet
