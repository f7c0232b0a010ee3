#ifndef RODNET_IO_PICTURE_CAMERA_H
#define RODNET_IO_PICTURE_CAMERA_H

#include <elements/quaternion.h>

#include <array>
#include <optional>
#include <vector>

namespace rodnet
{
  /**
   * An orthographic camera given by the direction towards it: azimuth a
   * (degrees, in the xy-plane counter-clockwise from x) and elevation e
   * (degrees above the xy-plane, -90 to 90), the direction
   * (cos e cos a, cos e sin a, sin e). The screen's right is
   * (-sin a, cos a, 0) and its up the projection of z (of y seen from
   * straight above: a = -90, e = 90 shows x to the right, y up).
   */
  struct PictureCamera
  {
    PictureCamera(double azimuth, double elevation);

    /// Screen x, screen y and depth (larger: nearer the viewer) of @p p.
    std::array<double, 3>
    project(const Vector3 &p) const;

    double  azimuth, elevation;
    Vector3 toward_viewer, right, up;
  };

  /**
   * The camera that shows @p undeformed and @p deformed (the positions of
   * the same vertices) best: where both lie in one plane, straight at that
   * plane; where the undeformed shape spans a plane and the deformed one
   * leaves it (a lattice that buckles out of its plane), obliquely, 35
   * degrees above that plane; otherwise the oblique view a = -60, e = 30. A
   * given @p azimuth or @p elevation replaces the chosen one.
   */
  PictureCamera
  choose_camera(const std::vector<Vector3> &undeformed,
                const std::vector<Vector3> &deformed,
                std::optional<double>       azimuth,
                std::optional<double>       elevation);
} // namespace rodnet

#endif
