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
    stencil_of_cell.assign(network.n_segments(),
                           dealii::numbers::invalid_unsigned_int);
    for (unsigned int s = 0; s < layout.segments().size(); ++s)
      if (!network.rods()[layout.segments()[s].rod].inextensible)
        {
          stencil_of_cell[layout.segments()[s].cell] = segments.size();
          segments.push_back(s);
        }
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


  MaterialResponse<1>
  StretchFamily::response_without_derivatives(const unsigned int  s,
                                              const StencilState &state,
                                              const double        time_step,
                                              double             *updated) const
  {
    const SegmentStencil &stencil = segment(s);
    const double          l0 = state.configuration.rest_length(stencil.cell);
    StretchStrain         stretch;
    evaluate_stretch(state.configuration.segment_dofs(state.u, stencil),
                     l0,
                     stretch,
                     false);
    return materials[stencil.rod]->segment_increment(
      stretch.strain - state.configuration.segment_eigenstrain(stencil.cell),
      l0,
      state.history.block(*this, s),
      time_step,
      updated);
  }


  void
  StretchFamily::update_internal_variables(const unsigned int  s,
                                           const StencilState &state,
                                           double             *updated) const
  {
    response_without_derivatives(s, state, state.time_step, updated);
  }


  std::optional<double>
  StretchFamily::segment_axial_force(const unsigned int  cell,
                                     const StencilState &state) const
  {
    const unsigned int s = stencil_of_cell[cell];
    if (s == dealii::numbers::invalid_unsigned_int)
      return std::nullopt;
    // The stress of the elastic strain, as in evaluate(), over no time
    // step: N = dw/d(strain) / l0.
    return response_without_derivatives(s, state, 0.0, nullptr).stress[0] /
           state.configuration.rest_length(segment(s).cell);
  }


  void
  StretchFamily::write_internal_variables(const InternalVariables &history,
                                          InternalVariableFields  &fields) const
  {
    for (unsigned int s = 0; s < n_stencils(); ++s)
      {
        const SegmentStencil &stencil = segment(s);
        const auto            names =
          materials[stencil.rod]->segment_internal_variable_names();
        for (unsigned int m = 0; m < names.size(); ++m)
          fields.at_cells(names[m])[stencil.cell] = history.block(*this, s)[m];
      }
  }
} // namespace rodnet
