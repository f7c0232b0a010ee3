#include <core/axis_moment_family.h>
#include <elements/junction_moment.h>

#include <cmath>

namespace rodnet
{
  AxisMomentFamily::AxisMomentFamily(const DofLayout &layout)
      : layout(layout)
  {
  }


  void
  AxisMomentFamily::get_dofs(const unsigned int             s,
                             std::vector<global_dof_index> &dofs) const
  {
    dofs.clear();
    for (unsigned int c = 0; c < 4; ++c)
      dofs.push_back(layout.rotation_dof(moments[s].junction, c));
  }


  namespace
  {
    /// The matrix P with (q Q) = P q for quaternions as (w, x, y, z): the
    /// product (w, v)(W, V) = (w W - v . V, w V + W v + v x V) is linear in
    /// (w, v).
    Eigen::Matrix4d
    right_product_matrix(const Quaternion &Q)
    {
      const Vector3   V = Q.vec();
      Eigen::Matrix4d P;
      P(0, 0)             = Q.w();
      P.block<1, 3>(0, 1) = -V.transpose();
      P.block<3, 1>(1, 0) = V;
      P.block<3, 3>(1, 1) = Q.w() * Matrix3::Identity() - cross_matrix(V);
      return P;
    }
  } // namespace


  void
  AxisMomentFamily::evaluate(const unsigned int  s,
                             const StencilState &state,
                             const Derivatives   derivatives,
                             LocalContribution  &local) const
  {
    const AxisMoment &m = moments[s];
    // Quaternion DoFs store the increment since the reference, q - (1, 0, 0,
    // 0) (DofLayout). Eq. 33 takes the junction's whole rotation q Q, Q the
    // rotation at the reference: theta_u of the increment alone would make
    // the load stiffness depend on where the last step ended (the lever
    // R v1 of doc/continuation.md, "Roll-up under an end moment", re-attached
    // along v1 at every step), and the located bifurcations on the step length.
    Eigen::Vector4d q;
    for (unsigned int c = 0; c < 4; ++c)
      q[c] = state.u[layout.rotation_dof(m.junction, c)] + (c == 0);
    const Quaternion &reference =
      state.configuration.reference_rotation(m.junction);
    const Eigen::Matrix4d P     = right_product_matrix(reference);
    const RotationAngle   angle = rotation_angle_about(m.axis, P * q);
    // theta_u jumps by 2 pi where R v1 passes -v1: continue it from its
    // value at the reference, so that the energy is smooth within a step.
    const double at_reference =
      rotation_angle_about(m.axis,
                           Eigen::Vector4d(reference.w(),
                                           reference.x(),
                                           reference.y(),
                                           reference.z()))
        .angle;
    const double scale = -(m.held ? 1.0 : state.load_factor) * m.moment;
    local.energy =
      scale *
      (at_reference + std::remainder(angle.angle - at_reference, 2 * M_PI));
    if (derivatives == Derivatives::energy)
      return;
    const Eigen::Vector4d gradient = scale * P.transpose() * angle.gradient;
    const Eigen::Matrix4d hessian  = scale * P.transpose() * angle.hessian * P;
    local.store(gradient,
                derivatives == Derivatives::hessian ? &hessian : nullptr);
  }
} // namespace rodnet
