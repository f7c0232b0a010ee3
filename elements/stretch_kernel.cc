#include <elements/stretch_kernel.h>

namespace rodnet
{
  void
  evaluate_stretch(const SegmentVector &dofs,
                   const double         rest_length,
                   StretchStrain       &result,
                   const bool           with_hessian)
  {
    const Vector3 edge   = dofs.tail<3>() - dofs.head<3>();
    const double  length = edge.norm();
    const Vector3 t      = edge / length;

    result.strain             = length / rest_length - 1.0;
    result.gradient.head<3>() = -t / rest_length;
    result.gradient.tail<3>() = t / rest_length;
    if (!with_hessian)
      return;

    // d t / d e = (I - t t^T) / |e|: the strain is curved only across the
    // segment.
    const Matrix3 block =
      (Matrix3::Identity() - t * t.transpose()) / (length * rest_length);
    result.hessian.topLeftCorner<3, 3>()     = block;
    result.hessian.bottomRightCorner<3, 3>() = block;
    result.hessian.topRightCorner<3, 3>()    = -block;
    result.hessian.bottomLeftCorner<3, 3>()  = -block;
  }
} // namespace rodnet
