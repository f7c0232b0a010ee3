#include <io/picture_camera.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace rodnet
{
  namespace
  {
    constexpr double radians_per_degree = M_PI / 180;

    /// Points whose spread across a plane is below this fraction of their
    /// largest spread lie in that plane: an out-of-plane motion that small
    /// would not show in any view.
    constexpr double flatness = 1e-3;

    /**
     * The normal of the plane that holds every point of @p sets, if they
     * lie in one: the principal axis of least spread. Points on a line lie
     * in many planes: the one that holds z as well as the line is taken
     * (a straight rod along x is seen from above), or the one that holds
     * y (a rod along z is seen from the front); none if not @p on_a_line.
     */
    std::optional<Vector3>
    plane_normal(const std::vector<const std::vector<Vector3> *> &sets,
                 const bool on_a_line = true)
    {
      Vector3     mean = Vector3::Zero();
      std::size_t n    = 0;
      for (const auto *set : sets)
        for (const Vector3 &p : *set)
          mean += p, ++n;
      mean /= std::max<std::size_t>(n, 1);
      Matrix3 spread = Matrix3::Zero();
      for (const auto *set : sets)
        for (const Vector3 &p : *set)
          spread += (p - mean) * (p - mean).transpose();
      const Eigen::SelfAdjointEigenSolver<Matrix3> axes(spread);
      // Eigenvalues in increasing order: squared spreads.
      const Vector3 variance = axes.eigenvalues().cwiseMax(0);
      if (std::sqrt(variance[0]) > flatness * std::sqrt(variance[2]))
        return std::nullopt;
      if (std::sqrt(variance[1]) > flatness * std::sqrt(variance[2]))
        return Vector3(axes.eigenvectors().col(0));
      if (!on_a_line)
        return std::nullopt;
      const Vector3 line = axes.eigenvectors().col(2);
      for (const Vector3 &axis :
           std::array<Vector3, 2>{{Vector3::UnitZ(), Vector3::UnitY()}})
        {
          const Vector3 in_plane = axis - axis.dot(line) * line;
          if (in_plane.norm() > 0.1)
            return Vector3(line.cross(in_plane).normalized());
        }
      return Vector3::UnitZ();
    }

    /// @p normal turned towards +z, or -y, or +x: the side a reader
    /// expects to look from.
    Vector3
    facing_viewer(const Vector3 &normal)
    {
      for (const Vector3 &side : std::array<Vector3, 3>{
             {Vector3::UnitZ(), Vector3(-Vector3::UnitY()), Vector3::UnitX()}})
        if (std::abs(normal.dot(side)) > 1e-9)
          return normal.dot(side) > 0 ? normal : Vector3(-normal);
      return normal;
    }

    /// Azimuth and elevation (degrees) of the unit direction @p c; within
    /// 1e-6 of a pole (a plane's normal found to rounding), straight from
    /// above or below with x to the right.
    std::array<double, 2>
    angles_of(const Vector3 &c)
    {
      if (std::hypot(c[0], c[1]) < 1e-6)
        return {{-90, c[2] > 0 ? 90.0 : -90.0}};
      return {{std::atan2(c[1], c[0]) / radians_per_degree,
               std::asin(std::clamp(c[2], -1.0, 1.0)) / radians_per_degree}};
    }

    /// 35 degrees above the plane of normal @p normal, from the side of
    /// the usual oblique view (azimuth -60).
    Vector3
    oblique_to(const Vector3 &normal)
    {
      const Vector3 usual(std::cos(-60 * radians_per_degree),
                          std::sin(-60 * radians_per_degree),
                          0);
      Vector3       along = usual - usual.dot(normal) * normal;
      if (along.norm() < 1e-6)
        along = Vector3::UnitZ() - normal[2] * normal;
      return std::sin(35 * radians_per_degree) * normal +
             std::cos(35 * radians_per_degree) * along.normalized();
    }
  } // namespace


  PictureCamera::PictureCamera(const double azimuth_, const double elevation_)
      : azimuth(azimuth_)
      , elevation(elevation_)
  {
    const double a = azimuth * radians_per_degree,
                 e = elevation * radians_per_degree;
    toward_viewer  = Vector3(std::cos(e) * std::cos(a),
                            std::cos(e) * std::sin(a),
                            std::sin(e));
    right          = Vector3(-std::sin(a), std::cos(a), 0);
    up             = toward_viewer.cross(right);
  }


  std::array<double, 3>
  PictureCamera::project(const Vector3 &p) const
  {
    return {{p.dot(right), p.dot(up), p.dot(toward_viewer)}};
  }


  PictureCamera
  choose_camera(const std::vector<Vector3> &undeformed,
                const std::vector<Vector3> &deformed,
                const std::optional<double> azimuth,
                const std::optional<double> elevation)
  {
    std::array<double, 2> chosen = {{-60, 30}};
    if (const auto normal = plane_normal({&undeformed, &deformed}))
      chosen = angles_of(facing_viewer(*normal));
    // A straight rod that leaves its line: no plane to look at it from.
    else if (const auto flat = plane_normal({&undeformed}, false))
      chosen = angles_of(oblique_to(facing_viewer(*flat)));
    return PictureCamera(azimuth.value_or(chosen[0]),
                         elevation.value_or(chosen[1]));
  }
} // namespace rodnet
