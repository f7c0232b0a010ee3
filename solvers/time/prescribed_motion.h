#ifndef RODNET_SOLVERS_TIME_PRESCRIBED_MOTION_H
#define RODNET_SOLVERS_TIME_PRESCRIBED_MOTION_H

#include <core/solvable_model.h>

#include <functional>

namespace rodnet
{
  /**
   * Puts the velocity of the prescribed motion at @p time into the
   * constrained rows of @p v: d/dt of the values that
   * SolvableModel::apply_boundary_values(u, load_factor(t), t) gives the fixed
   * DoFs of @p u (supports moving with the load factor or by functions of
   * time, clamps turning), by the one-sided second-order difference
   * (-3 u(t) + 4 u(t + e) - u(t + 2e)) / (2e), e = 1e-4 @p time_scale,
   * forward, so that a load factor with a jump just before @p time (a
   * release at the start) does not enter. The rows of the junction copies
   * get the velocity of their junction if it is held, zero otherwise.
   *
   * A dynamic run needs it at its start (doc/dynamics.md, "Moving
   * supports"): the trapezoidal velocity update of a held DoF, v_{n+1} =
   * 2 (u_{n+1} - u_n)/h - v_n, started from zero under a support that
   * moves would alternate by twice the support's velocity from step to
   * step, and the consistent mass would hand that to the free DoFs next
   * to it as an inertial force of order 1/h.
   */
  void
  set_prescribed_velocity(const SolvableModel                 &model,
                          const std::function<double(double)> &load_factor,
                          double                               time,
                          double                               time_scale,
                          const VectorType                    &u,
                          VectorType                          &v);
} // namespace rodnet

#endif
