#ifndef RODNET_CORE_TENSOR_BODY_SPIN_H
#define RODNET_CORE_TENSOR_BODY_SPIN_H

#include <core/solvable_model.h>

#include <array>
#include <vector>

namespace rodnet
{
  /**
   * A rigid body at a junction whose kinetic energy depends on the
   * junction's rotation R (RigidBody::turns_with_junction()): a general
   * inertia tensor, or a centre off the vertex, x_c = x_j + R r_0. Of its
   * kinetic energy 1/2 m |xdot_j + omega x R r_0|^2 + 1/2 omega . R J_c
   * R^T omega the constant mass matrix carries 1/2 m |xdot_j|^2 +
   * 1/2 j |omega|^2, j = RigidBody::isotropic_inertia(); the rest is
   * counted from here (doc/dynamics.md, "Rigid bodies").
   */
  struct TensorBody
  {
    /// Its index in SolvableModel::rigid_bodies().
    unsigned int index;
    /// The junction whose rotation the body turns with, and its vertex.
    unsigned int junction, vertex;
    /// The vector part a of its quaternion increment q = (1, a).
    std::array<global_dof_index, 3> dofs;
    /// The position x_j of the vertex.
    std::array<global_dof_index, 3> position;
    /// J_c, about the centre, in global axes at the undeformed
    /// configuration.
    Matrix3 inertia;
    /// J_c + m (|r_0|^2 I - r_0 r_0^T), about the vertex.
    Matrix3 vertex_inertia;
    /// m and r_0 (zero for a centre at the vertex).
    double  mass;
    Vector3 offset;
    /// j, the isotropic part in the mass matrix.
    double isotropic;
  };

  /// The bodies of @p model (finalized) that turn with their junction.
  std::vector<TensorBody>
  tensor_bodies(const SolvableModel &model);

  /// R J_c R^T at @p u, R the junction's rotation from the undeformed
  /// configuration.
  Matrix3
  spatial_inertia(const SolvableModel &model,
                  const TensorBody    &body,
                  const VectorType    &u);

  /// R r_0 at @p u, the centre's offset from the vertex.
  Vector3
  centre_arm(const SolvableModel &model,
             const TensorBody    &body,
             const VectorType    &u);

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

  /// The kinetic energy and momenta of the bodies that turn with their
  /// junctions less what the mass matrix counts (1/2 m |xdot_j|^2 +
  /// 1/2 j |omega|^2, m xdot_j, x_j x m xdot_j + j omega).
  struct BodySpin
  {
    double  kinetic_energy   = 0;
    Vector3 linear_momentum  = Vector3::Zero();
    Vector3 angular_momentum = Vector3::Zero();
  };

  /// The BodySpin of the tensor bodies of @p model at (@p u, @p v), summed:
  /// what a probe adds to 1/2 v.Mv and to the momenta of M v. The centre
  /// moves at xdot_c = xdot_j + omega x R r_0; its momentum is m xdot_c,
  /// the angular momentum about the origin x_c x m xdot_c + R J_c R^T
  /// omega. Collective on several processes where there are such bodies:
  /// every process reads replicas and gets the whole sum.
  BodySpin
  tensor_body_spin(const SolvableModel &model,
                   const VectorType    &u,
                   const VectorType    &v);
} // namespace rodnet

#endif
