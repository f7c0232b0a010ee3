#ifndef RODNET_CORE_TENSOR_BODY_SPIN_H
#define RODNET_CORE_TENSOR_BODY_SPIN_H

#include <core/rod_model.h>

#include <array>
#include <vector>

namespace rodnet
{
  /**
   * The rotation of a rigid body with a general inertia tensor at a
   * junction (RigidBody::inertia_tensor): of its kinetic energy
   * 1/2 omega . R J_0 R^T omega the constant mass matrix carries the
   * isotropic part 1/2 j |omega|^2, j = trace(J_0) / 3
   * (RigidBody::isotropic_inertia()); the rest, which depends on the
   * orientation R, is counted from here (doc/dynamics.md, "Rigid bodies").
   */
  struct TensorBody
  {
    /// The junction whose rotation the body turns with.
    unsigned int junction;
    /// The vector part a of its quaternion increment q = (1, a).
    std::array<global_dof_index, 3> dofs;
    /// J_0 in global axes at the undeformed configuration.
    Matrix3 inertia;
    /// j, the isotropic part in the mass matrix.
    double isotropic;
  };

  /// The bodies of @p model (finalized) with a general inertia tensor.
  std::vector<TensorBody>
  tensor_bodies(const RodModel &model);

  /// R J_0 R^T at @p u, R the junction's rotation from the undeformed
  /// configuration.
  Matrix3
  spatial_inertia(const RodModel   &model,
                  const TensorBody &body,
                  const VectorType &u);

  /**
   * The spatial angular velocity of the junction of @p body at the
   * increment a of @p u and its rate adot of @p v: q = (1, a) turns by
   * omega = 2 (adot + a x adot) / (1 + |a|^2), 2 adot at a = 0, where the
   * time integrators leave it after every step (doc/junctions.md).
   */
  Vector3
  angular_velocity(const TensorBody &body,
                   const VectorType &u,
                   const VectorType &v);

  /// The rotational kinetic energy and the spatial angular momentum
  /// R J_0 R^T omega of bodies with inertia tensors less what the mass
  /// matrix counts, 1/2 j |omega|^2 and j omega.
  struct BodySpin
  {
    double  kinetic_energy   = 0;
    Vector3 angular_momentum = Vector3::Zero();
  };

  /// The BodySpin of the tensor bodies of @p model at (@p u, @p v), summed:
  /// what a probe adds to 1/2 v.Mv and to the junctions' spin of M v.
  BodySpin
  tensor_body_spin(const RodModel   &model,
                   const VectorType &u,
                   const VectorType &v);
} // namespace rodnet

#endif
