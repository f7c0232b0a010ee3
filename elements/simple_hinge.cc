#include <elements/reduced_hinge.templates.h>
#include <elements/segment_kinematics.h>
#include <elements/simple_hinge.h>

namespace rodnet
{
  namespace
  {
    using namespace hinge_offsets;

    /// Eq. 2.11, in the hemisphere Re(q) >= 0 (see the class documentation).
    Quaternion
    rotation_gradient(const Quaternion &frame_prev,
                      const Quaternion &frame_next)
    {
      Quaternion q = frame_prev.conjugate() * frame_next;
      if (q.w() < 0.0)
        q.coeffs() = -q.coeffs();
      return q;
    }
  } // namespace


  std::string
  SimpleHinge::name() const
  {
    return "simple";
  }


  Vector3
  SimpleHinge::strains(const HingeVector    &dofs,
                       const HingeReference &reference) const
  {
    const Vector3 prev_tangent =
      (dofs.segment<3>(vertex) - dofs.segment<3>(prev_vertex)).normalized();
    const Vector3 next_tangent =
      (dofs.segment<3>(next_vertex) - dofs.segment<3>(vertex)).normalized();
    const Quaternion q =
      rotation_gradient(current_director_frame(reference.frame_prev,
                                               prev_tangent,
                                               dofs[prev_twist]),
                        current_director_frame(reference.frame_next,
                                               next_tangent,
                                               dofs[next_twist]));
    return 2.0 * q.vec();
  }


  namespace reduced
  {
    /**
     * One evaluation of the measure: both segments' kinematics, the
     * rotation gradient q = s + v and the Jacobian of its hat variation,
     * from which the gradient and any weighted sum of the strains'
     * Hessians follow.
     */
    struct SimpleHingeKinematics
    {
      SimpleHingeKinematics(const HingeVector    &dofs,
                            const HingeReference &reference,
                            const reduced::Needs  needs)
          : prev(dofs.segment<3>(vertex) - dofs.segment<3>(prev_vertex),
                 dofs[prev_twist],
                 reference.frame_prev,
                 needs == reduced::Needs::hessian)
          , next(dofs.segment<3>(next_vertex) - dofs.segment<3>(vertex),
                 dofs[next_twist],
                 reference.frame_next,
                 needs == reduced::Needs::hessian)
      {
        const Quaternion q = rotation_gradient(prev.frame, next.frame);
        s                  = q.w();
        v                  = q.vec();
        kappa              = 2.0 * v;
        if (needs == reduced::Needs::weighted_gradient)
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
        return prev.frame._transformVector(seen_through_w(weights));
      }

      /// weights . d kappa / d y (1 x 8) without the Jacobian: a .
      /// (-first^{i-1}, first^i).
      Eigen::Matrix<double, 1, 8>
      weighted_gradient(const Vector3 &weights) const
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
      reduced::Jacobian
      strain_jacobian() const
      {
        return W.lazyProduct(dq);
      }

      /**
       * sum_c weights_c d^2 kappa_c / d y^2 (8 x 8): every term of eqs.
       * 3.6-3.7 is linear in the weights it is seen through, so the
       * weighted sum is one evaluation.
       */
      reduced::Hessian
      weighted_hessian(const Vector3 &weights) const
      {
        const Vector3    a = spatial_weight(weights);
        reduced::Hessian h;
        h.topLeftCorner<4, 4>()     = -prev.second_variation(a);
        h.bottomRightCorner<4, 4>() = next.second_variation(a);
        h.topRightCorner<4, 4>().setZero();
        h.bottomLeftCorner<4, 4>().setZero();

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
        return h;
      }

      SegmentKinematics prev, next;
      double            s;
      /// Eq. 2.13.
      Vector3           kappa;
      Vector3           v;
      reduced::Jacobian dq;
      Matrix3           W;
    };
  } // namespace reduced


  template class ReducedHinge<reduced::SimpleHingeKinematics>;

  RODNET_REGISTER_HINGE_KERNEL(SimpleHinge,
                               "simple",
                               "Korner, Audoly & Bhattacharya (2021): simple "
                               "bending and twisting measures")
} // namespace rodnet
