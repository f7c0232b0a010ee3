#ifndef RODNET_CORE_RIGID_BODY_MASS_H
#define RODNET_CORE_RIGID_BODY_MASS_H

#include <core/mass_matrix.h>
#include <core/solvable_model.h>

namespace rodnet
{
  /**
   * Adds the inertia of the rigid bodies of @p model
   * (SolvableModel::rigid_bodies()) to its mass matrix @p mass through
   * @p constraints (as assemble_mass_matrix() distributes the segments'):
   * constant blocks, exact at the start of every step (RigidBody;
   * doc/theory.md, "Rigid bodies"). At a vertex: m I_3 on its position and
   * 4 j I_3 on the vector part of its junction's quaternion increment (for
   * an inertia tensor, j = trace(J_0) / 3: RigidBody::isotropic_inertia()). At
   * a free rod end, with a = 1 + c/l and b = c/l: m [[a^2, -ab], [-ab,
   * b^2]] + J_p / l^2 [[1, -1], [-1, 1]] on the positions of the end
   * vertex and the one before it (per component), and J_t on the end
   * segment's twist.
   */
  void
  add_rigid_body_mass(const SolvableModel                     &model,
                      const dealii::AffineConstraints<double> &constraints,
                      MatrixType                              &mass);
} // namespace rodnet

#endif
