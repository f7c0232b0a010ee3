#include <families/bending_family.templates.h>
#include <families/junction_family.h>

namespace rodnet
{
  template class BendingFamily<JunctionStencils>;

  JunctionFamily::JunctionFamily(
    const DofLayout                                       &layout,
    const RodNetwork                                      &network,
    const std::vector<std::unique_ptr<JunctionKernel>>    &kernels,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : BendingFamily<JunctionStencils>(layout, kernels, materials)
      , network(network)
      , cost(1.0)
  {
    if (kernels.empty())
      return;
    double sum = 0;
    for (const auto &kernel : kernels)
      sum += kernel->relative_cost();
    cost = sum / kernels.size();
  }

  std::vector<DeclaredDof>
  JunctionFamily::own_dofs() const
  {
    std::vector<DeclaredDof> dofs;
    for (const Junction &junction : network.junctions())
      if (junction.has_rotation())
        for (unsigned int c = 0; c < 4; ++c)
          {
            DeclaredDof component;
            component.role   = DofRole::rotation;
            component.vertex = junction.vertex;
            component.label  = "junction \"" + junction.name + "\"";
            dofs.push_back(component);
          }
    return dofs;
  }
} // namespace rodnet
