#include <elements/reduced_hinge.templates.h>
#include <elements/simple_hinge.h>
#include <elements/simple_measure.h>

namespace rodnet
{
  using namespace hinge_offsets;


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
      reduced::rotation_gradient(current_director_frame(reference.frame_prev,
                                                        prev_tangent,
                                                        dofs[prev_twist]),
                                 current_director_frame(reference.frame_next,
                                                        next_tangent,
                                                        dofs[next_twist]));
    return 2.0 * q.vec();
  }


  namespace reduced
  {
    /// One evaluation of the measure for both segments of a hinge.
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
          , measure(prev, next, needs)
          , kappa(measure.kappa)
      {
      }

      Eigen::Matrix<double, 1, 8>
      weighted_gradient(const Vector3 &weights) const
      {
        return measure.weighted_gradient(prev, next, weights);
      }

      reduced::Jacobian
      strain_jacobian() const
      {
        return measure.strain_jacobian();
      }

      reduced::Hessian
      weighted_hessian(const Vector3 &weights) const
      {
        return measure.weighted_hessian(prev, next, weights);
      }

      SegmentKinematics prev, next;
      SimpleMeasure     measure;
      /// Eq. 2.13.
      Vector3 kappa;
    };
  } // namespace reduced


  template class ReducedHinge<reduced::SimpleHingeKinematics>;

  RODNET_REGISTER_HINGE_KERNEL(SimpleHinge,
                               "simple",
                               "Korner, Audoly & Bhattacharya (2021): simple "
                               "bending and twisting measures")
} // namespace rodnet
