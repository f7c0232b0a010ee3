#ifndef RODNET_FAMILIES_BENDING_FAMILY_TEMPLATES_H
#define RODNET_FAMILIES_BENDING_FAMILY_TEMPLATES_H

#include <families/bending_family.h>
#include <families/bending_response.h>

// Member definitions of BendingFamily, included only by the files that
// instantiate it for a stencil kind (hinge_family.cc, junction_family.cc).

namespace rodnet
{
  template <class Stencils>
  BendingFamily<Stencils>::BendingFamily(
    const DofLayout                                       &layout,
    const std::vector<std::unique_ptr<Kernel>>            &kernels,
    const std::vector<std::shared_ptr<const RodMaterial>> &materials)
      : layout(layout)
      , kernels(kernels)
      , materials(materials)
  {
  }


  template <class Stencils>
  unsigned int
  BendingFamily<Stencils>::n_stencils() const
  {
    return stencils().size();
  }


  template <class Stencils>
  void
  BendingFamily<Stencils>::get_dofs(const unsigned int             s,
                                    std::vector<global_dof_index> &dofs) const
  {
    const auto &stencil = stencils()[s].dofs;
    dofs.assign(stencil.begin(), stencil.end());
  }


  template <class Stencils>
  BendingStencil<typename Stencils::Kernel, typename Stencils::Reference>
  BendingFamily<Stencils>::stencil_at(const unsigned int  s,
                                      const StencilState &state) const
  {
    const auto          &stencil = stencils()[s];
    const Configuration &config  = state.configuration;
    return {*kernels[stencil.rod],
            (config.*Stencils::dofs)(state.u, stencil),
            (config.*Stencils::reference)(s),
            *materials[stencil.rod],
            (config.*Stencils::voronoi_length)(s),
            state.history.block(*this, s),
            (config.*Stencils::natural_strains)(s)};
  }


  template <class Stencils>
  void
  BendingFamily<Stencils>::evaluate(const unsigned int  s,
                                    const StencilState &state,
                                    const Derivatives   derivatives,
                                    LocalContribution  &local) const
  {
    evaluate_bending(stencil_at(s, state), state.time_step, derivatives, local);
  }


  template <class Stencils>
  unsigned int
  BendingFamily<Stencils>::n_internal_variables(const unsigned int s) const
  {
    return materials[stencils()[s].rod]->n_hinge_internal_variables();
  }


  template <class Stencils>
  void
  BendingFamily<Stencils>::update_internal_variables(const unsigned int  s,
                                                     const StencilState &state,
                                                     double *updated) const
  {
    bending_increment(stencil_at(s, state), state.time_step, updated);
  }


  template <class Stencils>
  void
  BendingFamily<Stencils>::write_internal_variables(
    const InternalVariables &history,
    InternalVariableFields  &fields) const
  {
    if constexpr (Stencils::drawn)
      for (unsigned int s = 0; s < n_stencils(); ++s)
        {
          const auto &stencil = stencils()[s];
          const auto  names =
            materials[stencil.rod]->hinge_internal_variable_names();
          for (unsigned int m = 0; m < names.size(); ++m)
            fields.at_vertices(names[m])[stencil.vertices[1]] =
              history.block(*this, s)[m];
        }
    else
      {
        (void)history;
        (void)fields;
      }
  }
} // namespace rodnet

#endif
