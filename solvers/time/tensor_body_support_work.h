#ifndef RODNET_SOLVERS_TIME_TENSOR_BODY_SUPPORT_WORK_H
#define RODNET_SOLVERS_TIME_TENSOR_BODY_SUPPORT_WORK_H

#include <core/tensor_body_spin.h>

#include <vector>

namespace rodnet
{
  /**
   * What the inertial force of the bodies with an inertia tensor at
   * junctions whose rotation is held (a clamp or a prescribed rotation)
   * adds to the reaction there, beyond the mass matrix's M (v_{n+1} - v_n)
   * / h: the midpoint rule's force on the rows of v (BodyRotationInertia,
   * f = (2 / h) (I - [v / 2]_x) (pi_{n+1} - pi_n)) less the block of M on
   * them times the turned velocities' change. The supports' work of a step
   * (EnergyBalance) takes the reaction with it; without it a body turned
   * by a prescribed rotation about an axis that is not principal did work
   * the balance did not count.
   *
   * @p u0, @p u1 and @p v0 are the step's ends and start velocity in its
   * chart (the increment of @p u0 zero), @p mass_change M (v_{n+1} - v_n)
   * on every row, @p h the step's length; @p fixed marks the fixed DoFs.
   * Returns the extra force on each body row that is fixed, as (dof,
   * force) pairs.
   */
  std::vector<std::pair<global_dof_index, double>>
  tensor_body_reaction(const SolvableModel           &model,
                       const std::vector<TensorBody> &bodies,
                       const std::vector<bool>       &fixed,
                       const VectorType              &u0,
                       const VectorType              &u1,
                       const VectorType              &v0,
                       const VectorType              &mass_change,
                       double                         h);
} // namespace rodnet

#endif
