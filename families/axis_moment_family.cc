#include <elements/junction_moment.h>
#include <families/axis_moment_family.h>

namespace rodnet
{
  AxisMomentFamily::AxisMomentFamily(const DofLayout        &layout,
                                     std::vector<AxisMoment> moments)
      : layout(layout)
      , moments(std::move(moments))
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


  void
  AxisMomentFamily::evaluate(const unsigned int  s,
                             const StencilState &state,
                             const Derivatives   derivatives,
                             LocalContribution  &local) const
  {
    const AxisMoment &m = moments[s];
    // Quaternion DoFs store q - (1, 0, 0, 0) (DofLayout).
    Eigen::Vector4d q;
    for (unsigned int c = 0; c < 4; ++c)
      q[c] = state.u[layout.rotation_dof(m.junction, c)] + (c == 0);
    const RotationAngle angle = rotation_angle_about(m.axis, q);
    const double        scale = -state.load_factor * m.moment;
    local.energy              = scale * angle.angle;
    if (derivatives == Derivatives::energy)
      return;
    const Eigen::Vector4d gradient = scale * angle.gradient;
    const Eigen::Matrix4d hessian  = scale * angle.hessian;
    local.store(gradient,
                derivatives == Derivatives::hessian ? &hessian : nullptr);
  }
} // namespace rodnet
