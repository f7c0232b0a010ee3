#include <families/bending_response.h>
#include <families/hinge_family.h>

namespace rodnet
{
  HingeFamily::HingeFamily(
    const DofLayout                                       &layout,
    const std::vector<std::unique_ptr<HingeKernel>>       &kernels,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : layout(layout)
      , kernels(kernels)
      , materials(materials)
  {
  }


  unsigned int
  HingeFamily::n_stencils() const
  {
    return layout.hinges().size();
  }


  void
  HingeFamily::get_dofs(const unsigned int             s,
                        std::vector<global_dof_index> &dofs) const
  {
    const auto &stencil = layout.hinges()[s].dofs;
    dofs.assign(stencil.begin(), stencil.end());
  }


  BendingStencil<HingeKernel, HingeReference>
  HingeFamily::stencil_at(const unsigned int s, const StencilState &state) const
  {
    const HingeStencil  &stencil = layout.hinges()[s];
    const Configuration &config  = state.configuration;
    return {*kernels[stencil.rod],
            config.hinge_dofs(state.u, stencil),
            config.hinge_reference(s),
            *materials[stencil.rod],
            config.voronoi_length(s),
            state.history.block(*this, s),
            config.natural_strains(s)};
  }


  void
  HingeFamily::evaluate(const unsigned int  s,
                        const StencilState &state,
                        const Derivatives   derivatives,
                        LocalContribution  &local) const
  {
    evaluate_bending(stencil_at(s, state), state.time_step, derivatives, local);
  }


  unsigned int
  HingeFamily::n_internal_variables(const unsigned int s) const
  {
    return materials[layout.hinges()[s].rod]->n_hinge_internal_variables();
  }


  void
  HingeFamily::update_internal_variables(const unsigned int  s,
                                         const StencilState &state,
                                         double             *updated) const
  {
    bending_increment(stencil_at(s, state), state.time_step, updated);
  }
} // namespace rodnet
