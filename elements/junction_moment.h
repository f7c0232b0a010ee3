#ifndef RODNET_ELEMENTS_JUNCTION_MOMENT_H
#define RODNET_ELEMENTS_JUNCTION_MOMENT_H

#include <elements/quaternion.h>

namespace rodnet
{
  /// The angle theta_u(q) of L&K eq. 33 with its derivatives with respect
  /// to the raw quaternion components (w, x, y, z).
  struct RotationAngle
  {
    double          angle;
    Eigen::Vector4d gradient;
    Eigen::Matrix4d hessian;
  };

  /**
   * Angle by which the rotation R of the (raw, nonzero) quaternion @p q =
   * (w, x, y, z) turns the plane orthogonal to @p axis, L&K appendix C,
   * eq. 33: cos theta = R v1 . v1, sin theta = R v1 . v2, with (u, v1, v2)
   * a right-handed orthonormal basis completing the unit axis u. It lies in
   * (-pi, pi] and equals the rotation angle for rotations about u. For
   * other rotations it depends on the choice of v1, the unit vector
   * orthogonal to u in the plane of u and the Cartesian axis least aligned
   * with it; it is undefined where R v1 is parallel to u.
   *
   * An applied moment M about the fixed axis u has the load potential
   * -M theta_u(q); its generalized forces are M times the gradient (eq. 32).
   */
  RotationAngle
  rotation_angle_about(const Vector3 &axis, const Eigen::Vector4d &q);

  /**
   * The spatial moment of a function E(q / |q|) of a rotation, given its
   * gradient @p gradient = dE/dq with respect to the raw quaternion @p q =
   * (w, x, y, z): the vector M such that dE = M . omega for every spatial
   * angular variation omega, where omega = 2 Im(dq-bar conj(q-bar)) for the
   * unit quaternion q-bar = q / |q|.
   *
   * Derivation: a spatial variation is dq-bar = (0, omega) q-bar / 2, and
   * dq = |q| dq-bar realizes it (dq-bar is orthogonal to q-bar). With
   * q-bar = (w, a) and g = (g_w, g_a),
   * dE = g . dq = (|q| / 2) g . (-omega . a, w omega + omega x a)
   *    = (|q| / 2) omega . (w g_a - g_w a + a x g_a).
   * Used to report the reaction moment of a clamped junction, or to check
   * an applied one.
   */
  Vector3
  spatial_moment(const Eigen::Vector4d &q, const Eigen::Vector4d &gradient);
} // namespace rodnet

#endif
