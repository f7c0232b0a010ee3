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


  BendingStencil<JunctionKernel, JunctionReference>
  JunctionFamily::stencil_at(const unsigned int  s,
                             const StencilState &state) const
  {
    const JunctionStencil &stencil = layout.junctions()[s];
    const Configuration   &config  = state.configuration;
    return {*kernels[stencil.rod],
            config.junction_dofs(state.u, stencil),
            config.junction_reference(s),
            *materials[stencil.rod],
            config.junction_voronoi_length(s),
            state.history.block(*this, s),
            config.junction_natural_strains(s)};
  }


  void
  JunctionFamily::evaluate(const unsigned int  s,
                           const StencilState &state,
                           const Derivatives   derivatives,
                           LocalContribution  &local) const
  {
    evaluate_bending(stencil_at(s, state), state.time_step, derivatives, local);
  }


  unsigned int
  JunctionFamily::n_internal_variables(const unsigned int s) const
  {
    return materials[layout.junctions()[s].rod]->n_hinge_internal_variables();
  }


  void
  JunctionFamily::update_internal_variables(const unsigned int  s,
                                            const StencilState &state,
                                            double             *updated) const
  {
    bending_increment(stencil_at(s, state), state.time_step, updated);
  }
} // namespace rodnet
