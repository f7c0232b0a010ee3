#ifndef RODNET_ELEMENTS_QUATERNION_H
#define RODNET_ELEMENTS_QUATERNION_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace rodnet
{
  /**
   * Unit quaternions represent rotations (Korner et al. 2021, section 2a).
   * We use Eigen's quaternion, whose product is the quaternion product (2.1)
   * and whose action q * v (`q._transformVector(v)`) is the rotation
   * r w r-bar of the paper.
   */
  using Quaternion = Eigen::Quaterniond;
  using Vector3    = Eigen::Vector3d;
  using Matrix3    = Eigen::Matrix3d;

  /// Rotation by @p angle about the unit vector @p axis (Korner eq. 2.2).
  inline Quaternion
  rotation_about(const Vector3 &axis, const double angle)
  {
    const double s = std::sin(0.5 * angle);
    return Quaternion(std::cos(0.5 * angle),
                      s * axis[0],
                      s * axis[1],
                      s * axis[2]);
  }

  /// The matrix of the linear map u -> a x u (Korner eq. 3.3).
  inline Matrix3
  cross_matrix(const Vector3 &a)
  {
    Matrix3 m;
    m << 0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0;
    return m;
  }
} // namespace rodnet

#endif
