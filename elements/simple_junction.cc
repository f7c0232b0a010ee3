#include <elements/simple_junction.h>
#include <elements/simple_measure.h>

namespace rodnet
{
  namespace
  {
    /**
     * The ghost frame R(q) D~ of a junction with the exact spin, with its
     * hat variations in the four raw components of q. With r = q / |q| and
     * G the 3 x 4 matrix of b -> Im(b conj(r)) (G r = 0):
     * - delta d-hat = 2 Im(delta r conj(r)) = (2 / |q|) G delta q, since
     *   delta r = (I - r r^T) delta q / |q|;
     * - w . delta^2 d-hat = 2 w . Im(delta^2 r conj(r)), as delta r
     *   conj(delta r) is real, with delta^2 r = -2 (r . delta q) (I - r r^T)
     *   delta q / |q|^2 - r |(I - r r^T) delta q|^2 / |q|^2, so the form is
     *   -(4 / |q|^2) (r . delta q)(G^T w . delta q).
     */
    struct GhostFrameKinematics
    {
      GhostFrameKinematics(const Eigen::Vector4d &q,
                           const Quaternion      &reference_frame)
          : inverse_norm(1.0 / q.norm())
          , r(q * inverse_norm)
          , frame(Quaternion(r[0], r[1], r[2], r[3]) * reference_frame)
      {
        const Vector3 v  = r.tail<3>();
        G.col(0)         = -v;
        G.rightCols<3>() = r[0] * Matrix3::Identity() + cross_matrix(v);
        first            = (2.0 * inverse_norm) * G;
      }

      /// The matrix of w . delta^2 d-hat in delta q.
      Eigen::Matrix4d
      second_variation(const Vector3 &w) const
      {
        const Eigen::Vector4d c = G.transpose() * w;
        return (-2.0 * inverse_norm * inverse_norm) *
               (r * c.transpose() + c * r.transpose());
      }

      double                      inverse_norm;
      Eigen::Vector4d             r;
      Quaternion                  frame;
      Eigen::Matrix<double, 3, 4> G;
      Eigen::Matrix<double, 3, 4> first;
    };

    /// One evaluation of the measure for the physical segment and the
    /// ghost, in the rod's order.
    struct SimpleJunctionKinematics
    {
      SimpleJunctionKinematics(const JunctionVector    &dofs,
                               const JunctionReference &reference,
                               const reduced::Needs     needs)
          : segment(dofs.segment<3>(junction_dofs::second_vertex) -
                      dofs.segment<3>(junction_dofs::first_vertex),
                    dofs[junction_dofs::twist],
                    reference.segment_frame,
                    needs == reduced::Needs::hessian)
          , ghost(dofs.segment<4>(junction_dofs::rotation),
                  reference.ghost_frame)
          , ghost_first(reference.ghost_first)
          , measure(ghost_first ?
                      reduced::SimpleMeasure(ghost, segment, needs) :
                      reduced::SimpleMeasure(segment, ghost, needs))
      {
      }

      /// The 8 reduced variables, (y^{i-1}, y^i) in the rod's order, to
      /// the 11 DoFs: the segment's (delta e, delta phi) with
      /// e = x_b - x_a, the ghost's delta q.
      template <int rows>
      Eigen::Matrix<double, rows, n_junction_dofs>
      to_dofs(const Eigen::Matrix<double, rows, 8> &m) const
      {
        const int segment_column = ghost_first ? 4 : 0;
        const int ghost_column   = ghost_first ? 0 : 4;
        Eigen::Matrix<double, rows, n_junction_dofs> r;
        r.template middleCols<3>(junction_dofs::first_vertex) =
          -m.template middleCols<3>(segment_column);
        r.template middleCols<3>(junction_dofs::second_vertex) =
          m.template middleCols<3>(segment_column);
        r.col(junction_dofs::twist) = m.col(segment_column + 3);
        r.template middleCols<4>(junction_dofs::rotation) =
          m.template middleCols<4>(ghost_column);
        return r;
      }

      HingeMatrix
      hessian_in_dofs(const Vector3 &weights) const
      {
        const reduced::Hessian h =
          ghost_first ? measure.weighted_hessian(ghost, segment, weights) :
                        measure.weighted_hessian(segment, ghost, weights);
        return to_dofs<n_junction_dofs>(to_dofs<8>(h).transpose());
      }

      HingeVector
      weighted_gradient_in_dofs(const Vector3 &weights) const
      {
        const Eigen::Matrix<double, 1, 8> g =
          ghost_first ? measure.weighted_gradient(ghost, segment, weights) :
                        measure.weighted_gradient(segment, ghost, weights);
        return to_dofs<1>(g).transpose();
      }

      SegmentKinematics      segment;
      GhostFrameKinematics   ghost;
      bool                   ghost_first;
      reduced::SimpleMeasure measure;
    };
  } // namespace


  namespace simple_junction
  {
    Vector3
    strains(const JunctionVector &dofs, const JunctionReference &reference)
    {
      const Vector3 tangent = (dofs.segment<3>(junction_dofs::second_vertex) -
                               dofs.segment<3>(junction_dofs::first_vertex))
                                .normalized();
      const Quaternion segment =
        current_director_frame(reference.segment_frame,
                               tangent,
                               dofs[junction_dofs::twist]);
      const Eigen::Vector4d r =
        dofs.segment<4>(junction_dofs::rotation).normalized();
      const Quaternion ghost =
        Quaternion(r[0], r[1], r[2], r[3]) * reference.ghost_frame;
      const Quaternion q = reference.ghost_first ?
                             reduced::rotation_gradient(ghost, segment) :
                             reduced::rotation_gradient(segment, ghost);
      return 2.0 * q.vec();
    }


    void
    evaluate(const JunctionVector    &dofs,
             const JunctionReference &reference,
             JunctionStrains         &result,
             const bool               with_hessian)
    {
      const SimpleJunctionKinematics junction(dofs,
                                              reference,
                                              with_hessian ?
                                                reduced::Needs::hessian :
                                                reduced::Needs::jacobian);
      result.kappa    = junction.measure.kappa;
      result.gradient = junction.to_dofs<3>(junction.measure.strain_jacobian());
      if (with_hessian)
        for (unsigned int c = 0; c < 3; ++c)
          result.hessian[c] = junction.hessian_in_dofs(Vector3::Unit(c));
    }


    void
    evaluate_weighted(const JunctionVector    &dofs,
                      const JunctionReference &reference,
                      const StrainWeights     &weights,
                      JunctionStrains         &result,
                      HingeMatrix             &weighted)
    {
      const SimpleJunctionKinematics junction(dofs,
                                              reference,
                                              reduced::Needs::hessian);
      result.kappa    = junction.measure.kappa;
      result.gradient = junction.to_dofs<3>(junction.measure.strain_jacobian());
      weighted = junction.hessian_in_dofs(weights.at(junction.measure.kappa));
    }


    Vector3
    weighted_gradient(const JunctionVector    &dofs,
                      const JunctionReference &reference,
                      const StrainWeights     &weights,
                      HingeVector             &weighted)
    {
      const SimpleJunctionKinematics
        junction(dofs, reference, reduced::Needs::weighted_gradient);
      weighted =
        junction.weighted_gradient_in_dofs(weights.at(junction.measure.kappa));
      return junction.measure.kappa;
    }
  } // namespace simple_junction
} // namespace rodnet
