#include <elements/parallel_transport.h>
#include <elements/simple_hinge.h>

namespace rodnet
{
  namespace
  {
    using namespace hinge_offsets;

    // A segment frame depends on the node positions through the edge
    // e = x_{j+1} - x_j only, so its variations are computed in the reduced
    // variables y = (delta e, delta phi) and the hinge works in
    // (y^{i-1}, y^i): 8 variables instead of 11, and no zero blocks.
    using SegmentJacobian = Eigen::Matrix<double, 3, 4>;
    using SegmentHessian  = Eigen::Matrix4d;
    using ReducedJacobian = Eigen::Matrix<double, 3, 8>;
    using ReducedHessian  = Eigen::Matrix<double, 8, 8>;

    /**
     * Director frame d^j of a segment with its first and second hat
     * variations. The hat vectors are spatial (delta d = delta d-hat d / 2):
     * delta d-hat = first * y (Korner et al. eq. 3.5), and delta^2 d-hat is
     * kept in factored form, see second_variation().
     */
    struct SegmentKinematics
    {
      /// With @p second_order the data of second_variation() too.
      SegmentKinematics(const Vector3    &edge,
                        const double      twist_increment,
                        const Quaternion &reference_frame,
                        const bool        second_order)
          : length(edge.norm())
          , t(edge / length)
      {
        const Vector3 T = reference_frame._transformVector(Vector3::UnitZ());
        // Eq. 2.8; current_director_frame() would recompute T.
        frame = parallel_transport(T, t) * rotation_about(T, twist_increment) *
                reference_frame;

        // Binormal of eq. 3.4; k is orthogonal to t, so M t = 0 and the
        // projector (I - t t^T) / l of eq. 3.1 is absorbed in M / l.
        const double  one_plus_cosine = 1.0 + T.dot(t);
        const Vector3 k               = 2.0 * T.cross(t) / one_plus_cosine;
        M                   = cross_matrix(t) - 0.5 * t * k.transpose();
        first.leftCols<3>() = M / length;
        first.col(3)        = t;
        if (!second_order)
          return;

        // Eq. 3.2 in the variable e, with delta t = Q delta e (eq. 3.1),
        // k . delta t = (k / l) . delta e and T . delta t = tau . delta e.
        k_over_l          = k / length;
        const Vector3 tau = (T - T.dot(t) * t) / length;
        k_tau = (k_over_l * tau.transpose() + tau * k_over_l.transpose()) /
                (4.0 * one_plus_cosine);
      }

      /**
       * The symmetric matrix of the quadratic form w . delta^2 d-hat in y
       * (eqs. 3.1, 3.2, 3.5). M delta^2 t reduces to -2 M delta e (t . delta
       * e) / l^2 since M t = 0.
       */
      SegmentHessian
      second_variation(const Vector3 &w) const
      {
        const Vector3  Mw = M.transpose() * w / (length * length);
        const Vector3  Qw = (w - t.dot(w) * t) / length;
        SegmentHessian h;
        h.topLeftCorner<3, 3>() =
          -(Mw * t.transpose() + t * Mw.transpose()) + t.dot(w) * k_tau -
          0.25 * (Qw * k_over_l.transpose() + k_over_l * Qw.transpose());
        // delta phi delta t of eq. 3.5.
        h.block<3, 1>(0, 3) = 0.5 * Qw;
        h.block<1, 3>(3, 0) = 0.5 * Qw.transpose();
        h(3, 3)             = 0.0;
        return h;
      }

      double          length;
      Vector3         t;
      Quaternion      frame;
      Matrix3         M;
      SegmentJacobian first;
      Vector3         k_over_l;
      Matrix3         k_tau;
    };

    /**
     * Chain rule through e^{i-1} = x_i - x_{i-1} and e^i = x_{i+1} - x_i:
     * returns m C, where C is the 8 x 11 Jacobian of the reduced variables
     * with respect to the hinge DoFs.
     */
    template <int rows>
    Eigen::Matrix<double, rows, n_hinge_dofs>
    to_hinge_dofs(const Eigen::Matrix<double, rows, 8> &m)
    {
      Eigen::Matrix<double, rows, n_hinge_dofs> r;
      r.template middleCols<3>(prev_vertex) = -m.template middleCols<3>(0);
      r.col(prev_twist)                     = m.col(3);
      r.template middleCols<3>(vertex) =
        m.template middleCols<3>(0) - m.template middleCols<3>(4);
      r.col(next_twist)                     = m.col(7);
      r.template middleCols<3>(next_vertex) = m.template middleCols<3>(4);
      return r;
    }

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


  namespace
  {
    /**
     * One evaluation of the measure: both segments' kinematics, the
     * rotation gradient q = s + v and the Jacobian of its hat variation,
     * from which the gradient and any weighted sum of the strains'
     * Hessians follow.
     */
    /// What a HingeKinematics is built for.
    enum class Needs
    {
      /// weighted_gradient() only.
      weighted_gradient,
      /// strain_jacobian() too.
      jacobian,
      /// weighted_hessian() too.
      hessian
    };

    struct HingeKinematics
    {
      HingeKinematics(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const Needs           needs)
          : prev(dofs.segment<3>(vertex) - dofs.segment<3>(prev_vertex),
                 dofs[prev_twist],
                 reference.frame_prev,
                 needs == Needs::hessian)
          , next(dofs.segment<3>(next_vertex) - dofs.segment<3>(vertex),
                 dofs[next_twist],
                 reference.frame_next,
                 needs == Needs::hessian)
      {
        const Quaternion q = rotation_gradient(prev.frame, next.frame);
        s                  = q.w();
        v                  = q.vec();

        // Eq. 3.6: the hat variations of d^{i-1} and d^i are spatial
        // vectors; the rotation gradient lives in the material frame of
        // d^{i-1}, hence the pull-back by conj(d^{i-1}).
        const Matrix3 pull_back = prev.frame.toRotationMatrix().transpose();

        // Eq. 3.7: Im(delta q-hat q) = (s I - v_x) delta q-hat.
        W           = s * Matrix3::Identity() - cross_matrix(v);
        A.noalias() = W * pull_back;
        if (needs == Needs::weighted_gradient)
          return;
        dq.leftCols<4>().noalias()  = -pull_back * prev.first;
        dq.rightCols<4>().noalias() = pull_back * next.first;
      }

      /// weights . d kappa / d y (1 x 8) without the Jacobian: W dq = A
      /// (-first^{i-1}, first^i).
      Eigen::Matrix<double, 1, 8>
      weighted_gradient(const Vector3 &weights) const
      {
        const Eigen::Matrix<double, 1, 3> a = weights.transpose() * A;
        Eigen::Matrix<double, 1, 8>       g;
        g.leftCols<4>().noalias()  = -a * prev.first;
        g.rightCols<4>().noalias() = a * next.first;
        return g;
      }

      /// d kappa / d y (3 x 8): delta kappa = 2 Im(delta q) = Im(delta
      /// q-hat q), as delta q = delta q-hat q / 2.
      ReducedJacobian
      strain_jacobian() const
      {
        return W.lazyProduct(dq);
      }

      /**
       * sum_c weights_c d^2 kappa_c / d y^2 (8 x 8): every term of eqs.
       * 3.6-3.7 is linear in the row of W or of A it is seen through, so
       * the weighted sum is one evaluation with the weighted rows.
       */
      ReducedHessian
      weighted_hessian(const Vector3 &weights) const
      {
        const Vector3  a = A.transpose() * weights;
        ReducedHessian h;
        h.topLeftCorner<4, 4>()     = -prev.second_variation(a);
        h.bottomRightCorner<4, 4>() = next.second_variation(a);
        h.topRightCorner<4, 4>().setZero();
        h.bottomLeftCorner<4, 4>().setZero();

        // Second term of eq. 3.6, delta q-hat x (conj(d^{i-1}) delta
        // d-hat^{i-1}) seen through W^T weights, symmetrized: the Hessian
        // is the symmetric matrix of the quadratic form.
        const Eigen::Matrix<double, 3, 4> crossed =
          cross_matrix(W.transpose() * weights).lazyProduct(dq.leftCols<4>());
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
      Vector3           v;
      ReducedJacobian   dq;
      Matrix3           W, A;
    };

    /// C^T h C for the 8 x 11 Jacobian C of the reduced variables.
    HingeMatrix
    hessian_in_hinge_dofs(const ReducedHessian &h)
    {
      return to_hinge_dofs<n_hinge_dofs>(to_hinge_dofs<8>(h).transpose());
    }
  } // namespace


  void
  SimpleHinge::evaluate(const HingeVector    &dofs,
                        const HingeReference &reference,
                        HingeStrains         &result,
                        const bool            with_hessian) const
  {
    const HingeKinematics hinge(dofs,
                                reference,
                                with_hessian ? Needs::hessian : Needs::jacobian);
    result.kappa    = 2.0 * hinge.v;
    result.gradient = to_hinge_dofs<3>(hinge.strain_jacobian());
    if (!with_hessian)
      return;
    for (unsigned int c = 0; c < 3; ++c)
      result.hessian[c] =
        hessian_in_hinge_dofs(hinge.weighted_hessian(Vector3::Unit(c)));
  }


  void
  SimpleHinge::evaluate_weighted(const HingeVector    &dofs,
                                 const HingeReference &reference,
                                 const StrainWeights  &weights,
                                 HingeStrains         &result,
                                 HingeMatrix          &weighted) const
  {
    const HingeKinematics hinge(dofs, reference, Needs::hessian);
    result.kappa    = 2.0 * hinge.v;
    result.gradient = to_hinge_dofs<3>(hinge.strain_jacobian());
    weighted =
      hessian_in_hinge_dofs(hinge.weighted_hessian(weights.at(result.kappa)));
  }

  Vector3
  SimpleHinge::weighted_gradient(const HingeVector    &dofs,
                                 const HingeReference &reference,
                                 const StrainWeights  &weights,
                                 HingeVector          &weighted) const
  {
    const HingeKinematics hinge(dofs, reference, Needs::weighted_gradient);
    const Vector3         kappa = 2.0 * hinge.v;
    weighted = to_hinge_dofs<1>(hinge.weighted_gradient(weights.at(kappa)))
                 .transpose();
    return kappa;
  }

  RODNET_REGISTER_HINGE_KERNEL(SimpleHinge,
                               "simple",
                               "Korner, Audoly & Bhattacharya (2021): simple "
                               "bending and twisting measures")
} // namespace rodnet
