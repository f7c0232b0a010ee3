#ifndef RODNET_SOLVERS_CONTINUATION_LIMIT_POINT_ESTIMATE_H
#define RODNET_SOLVERS_CONTINUATION_LIMIT_POINT_ESTIMATE_H

#include <array>
#include <utility>

namespace rodnet
{
  /**
   * The load factor at the turn of the parabola lambda(s) through the three
   * points (s, lambda) around a limit point (the middle one's if they are
   * collinear): the continuation's estimate of a limit point it passed.
   */
  double
  parabola_extremum(const std::array<std::pair<double, double>, 3> &points);

  /**
   * The load factor where dlambda/ds, taken linear in s from @p p_slope at
   * (@p p_s, @p p_lambda) to @p q_slope (of the other sign) at @p q_s,
   * vanishes: the estimate when the fold comes in the path's first step,
   * before there are three points for parabola_extremum(). Exact for a
   * parabola lambda(s).
   */
  double
  slope_extremum(double p_s,
                 double p_lambda,
                 double p_slope,
                 double q_s,
                 double q_slope);
} // namespace rodnet

#endif
