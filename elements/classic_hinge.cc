#include <elements/classic_hinge.h>
#include <elements/parallel_transport.h>
#include <elements/reduced_hinge.templates.h>
#include <elements/segment_kinematics.h>

namespace rodnet
{
  namespace reduced
  {
    using namespace hinge_offsets;

    /**
     * One evaluation of the classic measures (Lestringant & Kochmann eqs.
     * 11-12) and their variations in the reduced variables of
     * segment_kinematics.h.
     *
     * The directors vary as delta d_I^j = omega^j x d_I^j with the spatial
     * hat variation omega^j = first^j y^j of SegmentKinematics, so that
     * - bending, kappa_I = kb . m_I with m_I = (d_I^{i-1} + d_I^i) / 2 and
     *   kb = 2 t^{i-1} x t^i / chi, chi = 1 + t^{i-1} . t^i:
     *   delta kappa_I = delta kb . m_I + sum_j omega^j . (d_I^j x kb) / 2;
     * - twist: tau_i is the signed angle from P_{t^{i-1}}^{t^i} d_1^{i-1} to
     *   d_1^i (modulo 2 pi), a function of the two frames alone, invariant
     *   under a common rotation, turned by alpha when the second frame
     *   turns by alpha about t^i (by -alpha when the first turns about
     *   t^{i-1}), unchanged when the second turns about kb:
     *   delta tau = tbar . (omega^i - omega^{i-1}) with the weighted mean
     *   tangent tbar = (t^{i-1} + t^i) / chi (tbar . t^j = 1, tbar . kb = 0).
     * The second variations differentiate these once more; a weighted sum
     * sum_c w_c kappa_c is one evaluation with the weighted directors
     * dw^j = (w_1 d_1^j + w_2 d_2^j) / 2, since every term is linear in
     * them and in w_3.
     */
    class ClassicHingeKinematics
    {
    public:
      ClassicHingeKinematics(const HingeVector    &dofs,
                             const HingeReference &reference,
                             const reduced::Needs  needs)
          : segment{{{dofs.segment<3>(vertex) - dofs.segment<3>(prev_vertex),
                      dofs[prev_twist],
                      reference.frame_prev,
                      needs == reduced::Needs::hessian},
                     {dofs.segment<3>(next_vertex) - dofs.segment<3>(vertex),
                      dofs[next_twist],
                      reference.frame_next,
                      needs == reduced::Needs::hessian}}}
      {
        const Vector3 &t0 = segment[0].t, &t1 = segment[1].t;
        chi = 1.0 + t0.dot(t1);
        if (!(chi > parallel_transport_tolerance))
          throw ParallelTransportSingular(chi);
        binormal     = 2.0 * t0.cross(t1) / chi;
        mean_tangent = (t0 + t1) / chi;
        for (unsigned int j = 0; j < 2; ++j)
          directors[j] = segment[j].frame.toRotationMatrix();
        if (needs == reduced::Needs::hessian)
          for (unsigned int j = 0; j < 2; ++j)
            projectors[j] =
              (Matrix3::Identity() - segment[j].t * segment[j].t.transpose()) /
              segment[j].length;

        for (unsigned int c = 0; c < 2; ++c)
          kappa[c] =
            0.5 * binormal.dot(directors[0].col(c) + directors[1].col(c));
        kappa[2] = reference.twist + dofs[next_twist] - dofs[prev_twist] +
                   holonomy(reference);
      }

      /// w . d kappa / d y (1 x 8).
      Eigen::Matrix<double, 1, 8>
      weighted_gradient(const Vector3 &w) const
      {
        const Weighted              x(*this, w);
        Eigen::Matrix<double, 1, 8> g;
        for (int j = 0; j < 2; ++j)
          {
            g.segment<4>(4 * j).noalias() =
              x.hat_weight[j].transpose() * segment[j].first;
            g.segment<3>(4 * j) +=
              project(j, x.tangent_gradient[j]).transpose();
          }
        return g;
      }

      /// d kappa / d y (3 x 8).
      reduced::Jacobian
      strain_jacobian() const
      {
        reduced::Jacobian j;
        for (unsigned int c = 0; c < 3; ++c)
          j.row(c) = weighted_gradient(Vector3::Unit(c));
        return j;
      }

      /// sum_c w_c d^2 kappa_c / d y^2 (8 x 8).
      reduced::Hessian
      weighted_hessian(const Vector3 &w) const
      {
        const Weighted   x(*this, w);
        reduced::Hessian h = reduced::Hessian::Zero();
        add_binormal_hessian(x, h);
        add_cross_terms(x, w[2], h);
        for (int j = 0; j < 2; ++j)
          {
            // kb . (delta omega^j x dw^j) and tbar . delta omega^j, through
            // the hat weight, and kb . (omega^j x (omega^j x dw^j)).
            const Vector3 &dw = x.directors[j];
            const Matrix3  outer =
              0.5 * (binormal * dw.transpose() + dw * binormal.transpose()) -
              binormal.dot(dw) * Matrix3::Identity();
            h.block<4, 4>(4 * j, 4 * j) +=
              segment[j].second_variation(x.hat_weight[j]) +
              segment[j].first.transpose() * outer * segment[j].first;
          }
        return h;
      }

      Vector3 kappa;

    private:
      /// The weighted quantities shared by the gradient and the Hessian.
      struct Weighted
      {
        Weighted(const ClassicHingeKinematics &k, const Vector3 &w)
        {
          for (unsigned int j = 0; j < 2; ++j)
            directors[j] = 0.5 * (w[0] * k.directors[j].col(0) +
                                  w[1] * k.directors[j].col(1));
          mean = directors[0] + directors[1];
          // f = kb . mean; tangent_gradient[j] = df / dt^j at fixed mean.
          f                 = k.binormal.dot(mean);
          const Vector3 &t0 = k.segment[0].t, &t1 = k.segment[1].t;
          tangent_gradient[0] = (2.0 * t1.cross(mean) - f * t1) / k.chi;
          tangent_gradient[1] = (2.0 * mean.cross(t0) - f * t0) / k.chi;
          hat_weight[0] =
            directors[0].cross(k.binormal) - w[2] * k.mean_tangent;
          hat_weight[1] =
            directors[1].cross(k.binormal) + w[2] * k.mean_tangent;
        }

        std::array<Vector3, 2> directors;
        Vector3                mean;
        double                 f;
        std::array<Vector3, 2> tangent_gradient;
        /// What omega^j is seen through in the first variation.
        std::array<Vector3, 2> hat_weight;
      };

      /// Q^j v = (I - t t^T) v / l: a gradient in t^j as one in e^j.
      Vector3
      project(const int j, const Vector3 &v) const
      {
        const Vector3 &t = segment[j].t;
        return (v - t.dot(v) * t) / segment[j].length;
      }

      /**
       * delta^2 kb . mean at fixed mean: the Hessian of f(t^{i-1}, t^i) =
       * 2 mean . (t^{i-1} x t^i) / chi, carried to the edges by delta t =
       * Q delta e and the Hessian of g . t(e), -((g . t) P + P g t^T +
       * t g^T P) / l^2 with P = I - t t^T.
       */
      void
      add_binormal_hessian(const Weighted &x, reduced::Hessian &h) const
      {
        const Vector3 &t0 = segment[0].t, &t1 = segment[1].t;
        const Vector3 &g0 = x.tangent_gradient[0], &g1 = x.tangent_gradient[1];
        const Matrix3 &q0 = projectors[0], &q1 = projectors[1];
        const Matrix3  h00 = -(t1 * g0.transpose() + g0 * t1.transpose()) / chi;
        const Matrix3  h11 = -(t0 * g1.transpose() + g1 * t0.transpose()) / chi;
        const Matrix3  h01 =
          (-2.0 * cross_matrix(x.mean) - x.f * Matrix3::Identity() -
           t1 * g1.transpose() - g0 * t0.transpose()) /
          chi;
        h.topLeftCorner<3, 3>() = q0 * h00 * q0 + tangent_curvature(0, g0);
        h.block<3, 3>(4, 4)     = q1 * h11 * q1 + tangent_curvature(1, g1);
        h.block<3, 3>(0, 4)     = q0 * h01 * q1;
        h.block<3, 3>(4, 0)     = h.block<3, 3>(0, 4).transpose();
      }

      /// The Hessian of g . t^j(e^j) at fixed g.
      Matrix3
      tangent_curvature(const int j, const Vector3 &g) const
      {
        const Vector3 &t  = segment[j].t;
        const double   l  = segment[j].length;
        const Vector3  pg = g - t.dot(g) * t;
        return -(t.dot(g) * (Matrix3::Identity() - t * t.transpose()) +
                 pg * t.transpose() + t * pg.transpose()) /
               (l * l);
      }

      /**
       * The products of first variations: 2 delta kb . sum_j (omega^j x
       * dw^j) (bending) and w_3 delta tbar . (omega^i - omega^{i-1})
       * (twist), with delta kb and delta tbar linear in the edges.
       */
      void
      add_cross_terms(const Weighted   &x,
                      const double      w_twist,
                      reduced::Hessian &h) const
      {
        const Vector3 &t0 = segment[0].t, &t1 = segment[1].t;
        // d kb / d e^j and d tbar / d e^j.
        const std::array<Matrix3, 2> kb_jacobian = {
          {(-2.0 * cross_matrix(t1) - binormal * t1.transpose()) *
             projectors[0] / chi,
           (2.0 * cross_matrix(t0) - binormal * t0.transpose()) *
             projectors[1] / chi}};
        const std::array<Matrix3, 2> tbar_jacobian = {
          {(Matrix3::Identity() - mean_tangent * t1.transpose()) *
             projectors[0] / chi,
           (Matrix3::Identity() - mean_tangent * t0.transpose()) *
             projectors[1] / chi}};

        Eigen::Matrix<double, 8, 8> c = Eigen::Matrix<double, 8, 8>::Zero();
        for (int j = 0; j < 2; ++j)
          {
            // Seen from segment j's hat variation: -2 [dw^j]_x first^j for
            // the bending, +-w_3 first^j for the twist.
            const Eigen::Matrix<double, 3, 4> bend =
              -2.0 * cross_matrix(x.directors[j]) * segment[j].first;
            const Eigen::Matrix<double, 3, 4> twist =
              (j == 0 ? -w_twist : w_twist) * segment[j].first;
            for (int k = 0; k < 2; ++k)
              c.block<3, 4>(4 * k, 4 * j).noalias() +=
                kb_jacobian[k].transpose() * bend +
                tbar_jacobian[k].transpose() * twist;
          }
        h += 0.5 * (c + c.transpose());
      }

      /**
       * gamma_i of eq. 12: the rotation about t^i that closes the loop of
       * tangents (T^{i-1}, T^i, t^i, t^{i-1}). The same vector D_1^{i-1},
       * carried T^{i-1} -> t^{i-1} -> t^i (time, then space transport) and
       * T^{i-1} -> T^i -> t^i (space, then time), ends up turned by gamma_i;
       * by Gauss-Bonnet the signed spherical area of the quadrilateral, for
       * |gamma_i| < pi.
       */
      double
      holonomy(const HingeReference &reference) const
      {
        const Vector3 &t0 = segment[0].t, &t1 = segment[1].t;
        const Vector3  T0 = reference.frame_prev * Vector3::UnitZ();
        const Vector3  T1 = reference.frame_next * Vector3::UnitZ();
        const Vector3  D1 = reference.frame_prev * Vector3::UnitX();
        const Vector3  time_then_space =
          parallel_transport(t0, t1) * (parallel_transport(T0, t0) * D1);
        const Vector3 space_then_time =
          parallel_transport(T1, t1) * (parallel_transport(T0, T1) * D1);
        return std::atan2(time_then_space.cross(space_then_time).dot(t1),
                          time_then_space.dot(space_then_time));
      }

      std::array<SegmentKinematics, 2> segment;
      /// Q^j = (I - t t^T) / l, delta t^j = Q^j delta e^j (Hessians only).
      std::array<Matrix3, 2> projectors;
      std::array<Matrix3, 2> directors;
      double                 chi;
      Vector3                binormal, mean_tangent;
    };
  } // namespace reduced


  std::string
  ClassicHinge::name() const
  {
    return "classic";
  }


  Vector3
  ClassicHinge::strains(const HingeVector    &dofs,
                        const HingeReference &reference) const
  {
    return reduced::ClassicHingeKinematics(dofs,
                                           reference,
                                           reduced::Needs::weighted_gradient)
      .kappa;
  }


  template class ReducedHinge<reduced::ClassicHingeKinematics>;

  RODNET_REGISTER_HINGE_KERNEL(
    ClassicHinge,
    "classic",
    "Lestringant & Kochmann (2020): curvature binormal and reference twist")
} // namespace rodnet
