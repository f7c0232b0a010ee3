#include <elements/frame_algebra.h>
#include <elements/junction_moment.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    using namespace frame_algebra;

    /// Eq. 33 for a unit axis with its orthonormal completion (v1, v2).
    template <typename Number>
    std::array<Number, 1>
    angle_in_plane(const std::array<Number, 4> &q,
                   const Vec<double>           &v1,
                   const Vec<double>           &v2)
    {
      using std::atan2;
      const Vec<Number> rotated =
        rotate(unit_quaternion(q[0], q[1], q[2], q[3]), v1);
      return {{atan2(dot<Number>(rotated, v2), dot<Number>(rotated, v1))}};
    }
  } // namespace


  RotationAngle
  rotation_angle_about(const Vector3 &axis, const Eigen::Vector4d &q)
  {
    if (!axis.allFinite() || !(axis.norm() > 0))
      throw std::invalid_argument(
        "rotation_angle_about: the axis must be finite and nonzero");
    if (!q.allFinite() || !(q.norm() > 0))
      throw std::invalid_argument(
        "rotation_angle_about: the quaternion must be finite and nonzero");

    const Vector3 u = axis.normalized();
    Eigen::Index  i;
    u.cwiseAbs().minCoeff(&i);
    const Vector3 v1 = u.cross(Vector3::Unit(i)).cross(u).normalized();
    const Vector3 v2 = u.cross(v1);

    RotationAngle                  result;
    Eigen::Matrix<double, 1, 1>    value;
    Eigen::Matrix<double, 1, 4>    gradient;
    std::array<Eigen::Matrix4d, 1> hessian;
    const Vec<double>              v1_array = to_vec(v1);
    const Vec<double>              v2_array = to_vec(v2);
    differentiate<1, 4>(
      q,
      [&](const auto &x) { return angle_in_plane(x, v1_array, v2_array); },
      value,
      gradient,
      &hessian);
    result.angle    = value[0];
    result.gradient = gradient.transpose();
    result.hessian  = hessian[0];
    return result;
  }


  Vector3
  spatial_moment(const Eigen::Vector4d &q, const Eigen::Vector4d &gradient)
  {
    const double norm = q.norm();
    if (!q.allFinite() || !(norm > 0))
      throw std::invalid_argument(
        "spatial_moment: the quaternion must be finite and nonzero");
    const double  w   = q[0] / norm;
    const Vector3 a   = q.tail<3>() / norm;
    const Vector3 g_a = gradient.tail<3>();
    return 0.5 * norm * (w * g_a - gradient[0] * a + a.cross(g_a));
  }
} // namespace rodnet
