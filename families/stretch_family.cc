#include <elements/stretch_kernel.h>
#include <families/stretch_family.h>

namespace rodnet
{
  StretchFamily::StretchFamily(
    const DofLayout                                       &layout,
    const RodNetwork                                      &network,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : layout(layout)
      , materials(materials)
  {
    for (unsigned int s = 0; s < layout.segments().size(); ++s)
      if (!network.rods()[layout.segments()[s].rod].inextensible)
        segments.push_back(s);
  }


  unsigned int
  StretchFamily::n_stencils() const
  {
    return segments.size();
  }


  void
  StretchFamily::get_dofs(const unsigned int             s,
                          std::vector<global_dof_index> &dofs) const
  {
    const auto &stencil = segment(s).dofs;
    dofs.assign(stencil.begin(), stencil.end());
  }


  void
  StretchFamily::evaluate(const unsigned int  s,
                          const StencilState &state,
                          const Derivatives   derivatives,
                          LocalContribution  &local) const
  {
    const SegmentStencil &stencil = segment(s);
    const double          l0 = state.configuration.rest_length(stencil.cell);
    const bool            with_hessian = derivatives == Derivatives::hessian;
    StretchStrain         stretch;
    evaluate_stretch(state.configuration.segment_dofs(state.u, stencil),
                     l0,
                     stretch,
                     with_hessian);
    const MaterialResponse<1> w = materials[stencil.rod]->segment_increment(
      stretch.strain - state.configuration.segment_eigenstrain(stencil.cell),
      l0,
      state.history.block(*this, s),
      state.time_step,
      nullptr);
    local.energy = w.energy;
    if (derivatives == Derivatives::energy)
      return;
    const SegmentVector gradient = w.stress[0] * stretch.gradient;
    if (!with_hessian)
      {
        local.store(gradient, static_cast<const SegmentMatrix *>(nullptr));
        return;
      }
    // Elastic part EA-like tangent times g g^T plus the geometric part.
    const SegmentMatrix hessian =
      w.tangent(0, 0) * stretch.gradient * stretch.gradient.transpose() +
      w.stress[0] * stretch.hessian;
    local.store(gradient, &hessian);
  }


  unsigned int
  StretchFamily::n_internal_variables(const unsigned int s) const
  {
    return materials[segment(s).rod]->n_segment_internal_variables();
  }


  void
  StretchFamily::update_internal_variables(const unsigned int  s,
                                           const StencilState &state,
                                           double             *updated) const
  {
    const SegmentStencil &stencil = segment(s);
    const double          l0 = state.configuration.rest_length(stencil.cell);
    StretchStrain         stretch;
    evaluate_stretch(state.configuration.segment_dofs(state.u, stencil),
                     l0,
                     stretch,
                     false);
    materials[stencil.rod]->segment_increment(
      stretch.strain - state.configuration.segment_eigenstrain(stencil.cell),
      l0,
      state.history.block(*this, s),
      state.time_step,
      updated);
  }
} // namespace rodnet
