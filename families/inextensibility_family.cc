#include <core/configuration.h>
#include <elements/stretch_kernel.h>
#include <families/inextensibility_family.h>
#include <materials/developable_ribbon_law.h>

namespace rodnet
{
  double
  inextensibility_scale(const RodMaterial &material, const double rest_length)
  {
    // A developable ribbon's hinges are priced by its law.
    if (const DevelopableRibbonLaw *law = material.developable_ribbon())
      return law->bending_modulus() / (rest_length * rest_length * rest_length);
    // The hinge's tangent at zero strain is the rigidity over the length.
    const MaterialResponse<3> response =
      material.hinge_energy(Eigen::Vector3d::Zero(), rest_length);
    return response.tangent.diagonal().maxCoeff() / (rest_length * rest_length);
  }


  InextensibilityFamily::InextensibilityFamily(
    const DofLayout                                       &layout,
    const RodNetwork                                      &network,
    const Configuration                                   &configuration,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : layout(layout)
      , stencil_of_cell(network.n_segments(),
                        dealii::numbers::invalid_unsigned_int)
  {
    const auto  &segments = layout.segments();
    unsigned int along    = 0;
    for (unsigned int s = 0; s < segments.size(); ++s)
      {
        const unsigned int rod  = segments[s].rod;
        const unsigned int cell = segments[s].cell;
        along = s > 0 && segments[s - 1].rod == rod ? along + 1 : 0;
        if (!network.rods()[rod].inextensible)
          continue;
        const double scale =
          inextensibility_scale(*materials[rod],
                                configuration.rest_length(cell));
        if (!(scale > 0 && std::isfinite(scale)))
          throw std::invalid_argument(
            "inextensible rod " + std::to_string(rod) +
            ": its material has no positive bending rigidity to scale the "
            "inextensibility constraint of segment " +
            std::to_string(cell));
        stencil_of_cell[cell] = stencils.size();
        stencils.push_back(
          {s, static_cast<global_dof_index>(stencils.size()), scale, along});
      }
  }


  bool
  InextensibilityFamily::applies_to(const RodNetwork &network)
  {
    return network.any_rod(&Rod::inextensible);
  }


  std::vector<DeclaredDof>
  InextensibilityFamily::own_dofs() const
  {
    std::vector<DeclaredDof> dofs;
    for (unsigned int t = 0; t < stencils.size(); ++t)
      {
        const SegmentStencil &segment = layout.segments()[stencils[t].segment];
        DeclaredDof           dof;
        dof.vertex = segment.vertices[0];
        dof.label  = "rod " + std::to_string(segment.rod) + " segment " +
                    std::to_string(stencils[t].along_rod) + " (its length)";
        dof.held_where_supports_hold = true;
        dofs.push_back(std::move(dof));
      }
    return dofs;
  }


  void
  InextensibilityFamily::number_own_dofs(const global_dof_index first)
  {
    for (Stencil &stencil : stencils)
      stencil.multiplier += first;
  }


  void
  InextensibilityFamily::hold_own_dofs(const std::vector<bool> &held)
  {
    std::vector<Stencil> kept;
    for (unsigned int t = 0; t < stencils.size(); ++t)
      {
        const unsigned int cell = layout.segments()[stencils[t].segment].cell;
        stencil_of_cell[cell] =
          held[t] ? dealii::numbers::invalid_unsigned_int : kept.size();
        if (!held[t])
          kept.push_back(stencils[t]);
      }
    stencils = std::move(kept);
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
    return cell < stencil_of_cell.size() &&
               stencil_of_cell[cell] != dealii::numbers::invalid_unsigned_int ?
             stencils[stencil_of_cell[cell]].scale :
             0.0;
  }


  double
  InextensibilityFamily::axial_force(const unsigned int   cell,
                                     const DofValues     &u,
                                     const Configuration &configuration) const
  {
    const double k = scale(cell);
    if (k == 0)
      return 0.0;
    return k * u[stencils[stencil_of_cell[cell]].multiplier] *
           configuration.segment_length(u, cell) /
           configuration.rest_length(cell);
  }
} // namespace rodnet
