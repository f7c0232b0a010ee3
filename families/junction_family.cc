#include <families/bending_response.h>
#include <families/junction_family.h>

namespace rodnet
{
  JunctionFamily::JunctionFamily(
    const DofLayout                                       &layout,
    const std::vector<std::unique_ptr<JunctionKernel>>    &kernels,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : layout(layout)
      , kernels(kernels)
      , materials(materials)
  {
  }


  unsigned int
  JunctionFamily::n_stencils() const
  {
    return layout.junctions().size();
  }


  void
  JunctionFamily::get_dofs(const unsigned int             s,
                           std::vector<global_dof_index> &dofs) const
  {
    const auto &stencil = layout.junctions()[s].dofs;
    dofs.assign(stencil.begin(), stencil.end());
  }


  void
  JunctionFamily::evaluate(const unsigned int  s,
                           const StencilState &state,
                           const Derivatives   derivatives,
                           LocalContribution  &local) const
  {
    const JunctionStencil &stencil = layout.junctions()[s];
    const Configuration   &config  = state.configuration;
    evaluate_bending(
      *kernels[stencil.rod],
      config.junction_dofs(state.u, stencil),
      config.junction_reference(s),
      {*materials[stencil.rod],
       config.junction_voronoi_length(s),
       state.history.block(InternalVariables::Owner::junction_element, s),
       Vector3::Zero()},
      state.time_step,
      derivatives,
      local);
  }
} // namespace rodnet
