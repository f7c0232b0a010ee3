#include <core/configuration.h>
#include <elements/stretch_kernel.h>
#include <materials/developable_ribbon_law.h>

#include <families/inextensibility_family.h>

namespace rodnet
{
  double
  inextensibility_scale(const RodMaterial &material, const double rest_length)
  {
    // A developable ribbon's hinges are priced by its law.
    if (const DevelopableRibbonLaw *law = material.developable_ribbon())
      return law->bending_modulus() /
             (rest_length * rest_length * rest_length);
    // The hinge's tangent at zero strain is the rigidity over the length.
    const MaterialResponse<3> response =
      material.hinge_energy(Eigen::Vector3d::Zero(), rest_length);
    return response.tangent.diagonal().maxCoeff() / (rest_length * rest_length);
  }


  InextensibilityFamily::InextensibilityFamily(
    const DofLayout                                       &layout,
    const Configuration                                   &configuration,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials,
    const std::vector<bool>                               &skipped)
      : layout(layout)
  {
    const auto &segments = layout.segments();
    for (unsigned int s = 0; s < segments.size(); ++s)
      {
        const unsigned int cell = segments[s].cell;
        if (cell_scales.size() <= cell)
          cell_scales.resize(cell + 1, 0.0);
        if (!layout.has_multiplier(cell) || skipped[cell])
          continue;
        const double scale =
          inextensibility_scale(*materials[segments[s].rod],
                                configuration.rest_length(cell));
        if (!(scale > 0 && std::isfinite(scale)))
          throw std::invalid_argument(
            "inextensible rod " + std::to_string(segments[s].rod) +
            ": its material has no positive bending rigidity to scale the "
            "inextensibility constraint of segment " +
            std::to_string(cell));
        stencils.push_back({s, layout.multiplier_dof(cell), scale});
        cell_scales[cell] = scale;
      }
  }


  void
  InextensibilityFamily::get_dofs(const unsigned int             s,
                                  std::vector<global_dof_index> &dofs) const
  {
    const auto &segment = layout.segments()[stencils[s].segment].dofs;
    dofs.assign(segment.begin(), segment.end());
    dofs.push_back(stencils[s].multiplier);
  }


  void
  InextensibilityFamily::evaluate(const unsigned int  s,
                                  const StencilState &state,
                                  const Derivatives   derivatives,
                                  LocalContribution  &local) const
  {
    const Stencil        &stencil = stencils[s];
    const SegmentStencil &segment = layout.segments()[stencil.segment];
    const double          l0 = state.configuration.rest_length(segment.cell);
    const SegmentVector x  = state.configuration.segment_dofs(state.u, segment);
    const Vector3       e  = x.tail<3>() - x.head<3>();
    const double        mu = state.u[stencil.multiplier];
    const double        k  = stencil.scale;
    const double        g  = (e.squaredNorm() - l0 * l0) / (2 * l0);

    local.energy = k * mu * g;
    if (derivatives == Derivatives::energy)
      return;
    // grad g = (-e, e) / l0; grad^2 g = [I -I; -I I] / l0.
    Eigen::Matrix<double, 7, 1> gradient;
    gradient.head<3>()     = -k * mu / l0 * e;
    gradient.segment<3>(3) = k * mu / l0 * e;
    gradient[6]            = k * g;
    if (derivatives == Derivatives::gradient)
      {
        local.store(gradient,
                    static_cast<const Eigen::Matrix<double, 7, 7> *>(nullptr));
        return;
      }
    Eigen::Matrix<double, 7, 7> hessian = Eigen::Matrix<double, 7, 7>::Zero();
    const Eigen::Matrix3d block = k * mu / l0 * Eigen::Matrix3d::Identity();
    hessian.block<3, 3>(0, 0)   = block;
    hessian.block<3, 3>(3, 3)   = block;
    hessian.block<3, 3>(0, 3)   = -block;
    hessian.block<3, 3>(3, 0)   = -block;
    hessian.block<3, 1>(0, 6)   = -k / l0 * e;
    hessian.block<3, 1>(3, 6)   = k / l0 * e;
    hessian.block<1, 3>(6, 0)   = -k / l0 * e.transpose();
    hessian.block<1, 3>(6, 3)   = k / l0 * e.transpose();
    local.store(gradient, &hessian);
  }


  double
  InextensibilityFamily::scale(const unsigned int cell) const
  {
    return cell < cell_scales.size() ? cell_scales[cell] : 0.0;
  }
} // namespace rodnet
