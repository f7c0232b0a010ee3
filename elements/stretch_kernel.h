#ifndef RODNET_ELEMENTS_STRETCH_KERNEL_H
#define RODNET_ELEMENTS_STRETCH_KERNEL_H

#include <elements/quaternion.h>

namespace rodnet
{
  /// Local degrees of freedom of a segment: (x_j, x_{j+1}).
  constexpr unsigned int n_segment_dofs = 6;

  using SegmentVector = Eigen::Matrix<double, n_segment_dofs, 1>;
  using SegmentMatrix = Eigen::Matrix<double, n_segment_dofs, n_segment_dofs>;

  /// Axial strain of a segment and its derivatives.
  struct StretchStrain
  {
    double        strain;
    SegmentVector gradient;
    SegmentMatrix hessian;
  };

  /**
   * Engineering axial strain of a segment, epsilon = |x_{j+1} - x_j| / l0 - 1
   * (Lestringant & Kochmann eq. 10 for one segment), with its first and
   * second derivatives with respect to (x_j, x_{j+1}). @p rest_length is the
   * undeformed length l0.
   */
  void
  evaluate_stretch(const SegmentVector &dofs,
                   double               rest_length,
                   StretchStrain       &result,
                   bool                 with_hessian);
} // namespace rodnet

#endif
