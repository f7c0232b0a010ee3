#ifndef RODNET_ELEMENTS_SIMPLE_MEASURE_H
#define RODNET_ELEMENTS_SIMPLE_MEASURE_H

#include <elements/segment_kinematics.h>

namespace rodnet
{
  namespace reduced
  {
    /// Korner et al. eq. 2.11, in the hemisphere Re(q) >= 0 (SimpleHinge).
    inline Quaternion
    rotation_gradient(const Quaternion &frame_prev,
                      const Quaternion &frame_next)
    {
      Quaternion q = frame_prev.conjugate() * frame_next;
      if (q.w() < 0.0)
        q.coeffs() = -q.coeffs();
      return q;
    }

    /**
     * The simple measure kappa = 2 Im(conj(d^{i-1}) d^i) (Korner et al. eqs.
     * 2.11, 2.13) of two frames, each given with its spatial hat variation
     * in 4 reduced variables of its own: `frame`, `first` (3 x 4, delta
     * d-hat = first y) and `second_variation(w)` (the 4 x 4 matrix of
     * w . delta^2 d-hat), as SegmentKinematics gives them for a segment.
     * The rotation gradient q = s + v and the Jacobian of its hat variation
     * give the gradient and any weighted sum of the strains' Hessians in
     * the 8 variables (y^{i-1}, y^i), eqs. 3.6-3.7.
     */
    class SimpleMeasure
    {
    public:
      template <class Prev, class Next>
      SimpleMeasure(const Prev &prev, const Next &next, const Needs needs)
          : prev_frame(prev.frame)
      {
        const Quaternion q = rotation_gradient(prev.frame, next.frame);
        s                  = q.w();
        v                  = q.vec();
        kappa              = 2.0 * v;
        if (needs == Needs::weighted_gradient)
          return;

        // Eq. 3.6: the hat variations of d^{i-1} and d^i are spatial
        // vectors; the rotation gradient lives in the material frame of
        // d^{i-1}, hence the pull-back by conj(d^{i-1}).
        const Matrix3 pull_back = prev.frame.toRotationMatrix().transpose();
        // Eq. 3.7: Im(delta q-hat q) = (s I - v_x) delta q-hat.
        W                           = s * Matrix3::Identity() - cross_matrix(v);
        dq.leftCols<4>().noalias()  = -pull_back * prev.first;
        dq.rightCols<4>().noalias() = pull_back * next.first;
      }

      /// weights . d kappa / d y (1 x 8) without the Jacobian: a .
      /// (-first^{i-1}, first^i).
      template <class Prev, class Next>
      Eigen::Matrix<double, 1, 8>
      weighted_gradient(const Prev    &prev,
                        const Next    &next,
                        const Vector3 &weights) const
      {
        const Eigen::Matrix<double, 1, 3> a =
          spatial_weight(weights).transpose();
        Eigen::Matrix<double, 1, 8> g;
        g.leftCols<4>().noalias()  = -a * prev.first;
        g.rightCols<4>().noalias() = a * next.first;
        return g;
      }

      /// d kappa / d y (3 x 8): delta kappa = 2 Im(delta q) = Im(delta
      /// q-hat q), as delta q = delta q-hat q / 2.
      Jacobian
      strain_jacobian() const
      {
        return W.lazyProduct(dq);
      }

      /**
       * sum_c weights_c d^2 kappa_c / d y^2 (8 x 8): every term of eqs.
       * 3.6-3.7 is linear in the weights it is seen through, so the
       * weighted sum is one evaluation.
       */
      template <class Prev, class Next>
      Hessian
      weighted_hessian(const Prev    &prev,
                       const Next    &next,
                       const Vector3 &weights) const
      {
        const Vector3 a = spatial_weight(weights);
        Hessian       h;
        h.topLeftCorner<4, 4>()     = -prev.second_variation(a);
        h.bottomRightCorner<4, 4>() = next.second_variation(a);
        h.topRightCorner<4, 4>().setZero();
        h.bottomLeftCorner<4, 4>().setZero();
        add_product_terms(weights, h);
        return h;
      }

      /// Eq. 2.13.
      Vector3 kappa;

    private:
      /// W^T @p weights, with W = s I - v_x of eq. 3.7.
      Vector3
      seen_through_w(const Vector3 &weights) const
      {
        return s * weights + v.cross(weights);
      }

      /// The spatial vector a with weights . W delta q-hat = a . (delta
      /// d-hat^i - delta d-hat^{i-1}): the pull-back's transpose is the
      /// rotation by d^{i-1}.
      Vector3
      spatial_weight(const Vector3 &weights) const
      {
        return prev_frame._transformVector(seen_through_w(weights));
      }

      /// The terms of eqs. 3.6-3.7 that are products of first variations.
      void
      add_product_terms(const Vector3 &weights, Hessian &h) const
      {
        // Second term of eq. 3.6, delta q-hat x (conj(d^{i-1}) delta
        // d-hat^{i-1}) seen through W^T weights, symmetrized: the Hessian
        // is the symmetric matrix of the quadratic form.
        const Eigen::Matrix<double, 3, 4> crossed =
          cross_matrix(seen_through_w(weights)).lazyProduct(dq.leftCols<4>());
        const Eigen::Matrix<double, 8, 4> cross_term =
          dq.transpose().lazyProduct(crossed);
        h.leftCols<4>() += 0.5 * cross_term;
        h.topRows<4>() += 0.5 * cross_term.transpose();

        // -|delta q-hat|^2 / 2 of eq. 3.7.
        h.noalias() -= (0.5 * v.dot(weights)) * dq.transpose().lazyProduct(dq);
      }

      Quaternion prev_frame;
      double     s;
      Vector3    v;
      Jacobian   dq;
      Matrix3    W;
    };
  } // namespace reduced
} // namespace rodnet

#endif
