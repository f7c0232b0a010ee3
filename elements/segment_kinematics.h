#ifndef RODNET_ELEMENTS_SEGMENT_KINEMATICS_H
#define RODNET_ELEMENTS_SEGMENT_KINEMATICS_H

#include <elements/hinge_kernel.h>
#include <elements/parallel_transport.h>

namespace rodnet
{
  /**
   * Variations of a segment's director frame, shared by the hinge kernels
   * that differentiate in closed form (simple, classic).
   *
   * A segment frame depends on the node positions through the edge
   * e = x_{j+1} - x_j only, so its variations are computed in the reduced
   * variables y = (delta e, delta phi), and a hinge works in
   * (y^{i-1}, y^i): 8 variables instead of 11, and no zero blocks.
   */
  namespace reduced
  {
    using SegmentJacobian = Eigen::Matrix<double, 3, 4>;
    using SegmentHessian  = Eigen::Matrix4d;
    using Jacobian        = Eigen::Matrix<double, 3, 8>;
    using Hessian         = Eigen::Matrix<double, 8, 8>;

    /**
     * Chain rule through e^{i-1} = x_i - x_{i-1} and e^i = x_{i+1} - x_i:
     * returns m C, where C is the 8 x 11 Jacobian of the reduced variables
     * with respect to the hinge DoFs.
     */
    template <int rows>
    Eigen::Matrix<double, rows, n_hinge_dofs>
    to_hinge_dofs(const Eigen::Matrix<double, rows, 8> &m)
    {
      using namespace hinge_offsets;
      Eigen::Matrix<double, rows, n_hinge_dofs> r;
      r.template middleCols<3>(prev_vertex) = -m.template middleCols<3>(0);
      r.col(prev_twist)                     = m.col(3);
      r.template middleCols<3>(vertex) =
        m.template middleCols<3>(0) - m.template middleCols<3>(4);
      r.col(next_twist)                     = m.col(7);
      r.template middleCols<3>(next_vertex) = m.template middleCols<3>(4);
      return r;
    }

    /// C^T h C for the 8 x 11 Jacobian C of the reduced variables.
    HingeMatrix
    hessian_in_hinge_dofs(const Hessian &h);

    /// What the kinematics of a hinge are built for.
    enum class Needs
    {
      /// weighted_gradient() only.
      weighted_gradient,
      /// strain_jacobian() too.
      jacobian,
      /// weighted_hessian() too.
      hessian
    };

    /**
     * HingeKernel::evaluate() for a kernel whose @p Kinematics, built from
     * (dofs, reference, Needs), give the strains kappa, the 3 x 8
     * strain_jacobian() and the 8 x 8 weighted_hessian(w) in the reduced
     * variables.
     */
    template <class Kinematics>
    void
    evaluate(const HingeVector    &dofs,
             const HingeReference &reference,
             HingeStrains         &result,
             const bool            with_hessian)
    {
      const Kinematics hinge(dofs,
                             reference,
                             with_hessian ? Needs::hessian : Needs::jacobian);
      result.kappa    = hinge.kappa;
      result.gradient = to_hinge_dofs<3>(hinge.strain_jacobian());
      if (!with_hessian)
        return;
      for (unsigned int c = 0; c < 3; ++c)
        result.hessian[c] =
          hessian_in_hinge_dofs(hinge.weighted_hessian(Vector3::Unit(c)));
    }

    /// HingeKernel::evaluate_weighted() by one weighted_hessian() of
    /// @p Kinematics, as evaluate().
    template <class Kinematics>
    void
    evaluate_weighted(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const StrainWeights  &weights,
                      HingeStrains         &result,
                      HingeMatrix          &weighted)
    {
      const Kinematics hinge(dofs, reference, Needs::hessian);
      result.kappa    = hinge.kappa;
      result.gradient = to_hinge_dofs<3>(hinge.strain_jacobian());
      weighted =
        hessian_in_hinge_dofs(hinge.weighted_hessian(weights.at(hinge.kappa)));
    }

    /// HingeKernel::weighted_gradient() by the 1 x 8 weighted_gradient(w)
    /// of @p Kinematics.
    template <class Kinematics>
    Vector3
    weighted_gradient(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const StrainWeights  &weights,
                      HingeVector          &weighted)
    {
      const Kinematics hinge(dofs, reference, Needs::weighted_gradient);
      weighted =
        to_hinge_dofs<1>(hinge.weighted_gradient(weights.at(hinge.kappa)))
          .transpose();
      return hinge.kappa;
    }
  } // namespace reduced

  /**
   * Director frame d^j of a segment with its first and second hat
   * variations. The hat vectors are spatial (delta d = delta d-hat d / 2 as
   * quaternions, delta d_I = delta d-hat x d_I as vectors): delta d-hat =
   * first * y (Korner et al. eq. 3.5), and delta^2 d-hat is kept in
   * factored form, see second_variation().
   */
  struct SegmentKinematics
  {
    /// The frame of the segment with edge @p edge and twist increment
    /// @p twist_increment from @p reference_frame (Korner eq. 2.8); with
    /// @p second_order the data of second_variation() too.
    SegmentKinematics(const Vector3    &edge,
                      double            twist_increment,
                      const Quaternion &reference_frame,
                      bool              second_order);

    /**
     * The symmetric matrix of the quadratic form w . delta^2 d-hat in y
     * (eqs. 3.1, 3.2, 3.5). M delta^2 t reduces to -2 M delta e (t . delta
     * e) / l^2 since M t = 0.
     */
    reduced::SegmentHessian
    second_variation(const Vector3 &w) const;

    double                   length;
    Vector3                  t;
    Quaternion               frame;
    Matrix3                  M;
    reduced::SegmentJacobian first;
    Vector3                  k_over_l;
    Matrix3                  k_tau;
  };

  // Defined here so that the kernels inline them.

  inline HingeMatrix
  reduced::hessian_in_hinge_dofs(const Hessian &h)
  {
    return to_hinge_dofs<n_hinge_dofs>(to_hinge_dofs<8>(h).transpose());
  }


  inline SegmentKinematics::SegmentKinematics(const Vector3    &edge,
                                              const double      twist_increment,
                                              const Quaternion &reference_frame,
                                              const bool        second_order)
      : length(edge.norm())
      , t(edge * (1.0 / length))
  {
    const Vector3 T = reference_frame._transformVector(Vector3::UnitZ());
    // Eq. 2.8; current_director_frame() would recompute T.
    frame = parallel_transport(T, t) * rotation_about(T, twist_increment) *
            reference_frame;

    // Binormal of eq. 3.4; k is orthogonal to t, so M t = 0 and the
    // projector (I - t t^T) / l of eq. 3.1 is absorbed in M / l.
    // Reciprocals once: a division costs several multiplications.
    const double  one_plus_cosine = 1.0 + T.dot(t);
    const Vector3 k               = (2.0 / one_plus_cosine) * T.cross(t);
    const double  inverse_length  = 1.0 / length;
    M                             = cross_matrix(t) - 0.5 * t * k.transpose();
    first.leftCols<3>()           = inverse_length * M;
    first.col(3)                  = t;
    if (!second_order)
      return;

    // Eq. 3.2 in the variable e, with delta t = Q delta e (eq. 3.1),
    // k . delta t = (k / l) . delta e and T . delta t = tau . delta e.
    k_over_l          = inverse_length * k;
    const Vector3 tau = inverse_length * (T - T.dot(t) * t);
    k_tau = (k_over_l * tau.transpose() + tau * k_over_l.transpose()) /
            (4.0 * one_plus_cosine);
  }


  inline reduced::SegmentHessian
  SegmentKinematics::second_variation(const Vector3 &w) const
  {
    const Vector3           Mw = M.transpose() * w / (length * length);
    const Vector3           Qw = (w - t.dot(w) * t) / length;
    reduced::SegmentHessian h;
    h.topLeftCorner<3, 3>() =
      -(Mw * t.transpose() + t * Mw.transpose()) + t.dot(w) * k_tau -
      0.25 * (Qw * k_over_l.transpose() + k_over_l * Qw.transpose());
    // delta phi delta t of eq. 3.5.
    h.block<3, 1>(0, 3) = 0.5 * Qw;
    h.block<1, 3>(3, 0) = 0.5 * Qw.transpose();
    h(3, 3)             = 0.0;
    return h;
  }
} // namespace rodnet

#endif
