#ifndef RODNET_FAMILIES_BENDING_FAMILY_H
#define RODNET_FAMILIES_BENDING_FAMILY_H

#include <core/element_family.h>
#include <materials/rod_material.h>

#include <memory>
#include <vector>

namespace rodnet
{
  template <class Kernel, class Reference>
  struct BendingStencil;

  /**
   * Bending and twisting of pairs of frames, measured by a kernel per rod and
   * priced by the rod's material, with the natural strains of the
   * Configuration. Hinges (HingeFamily) and junction elements
   * (JunctionFamily) are this family over two stencil kinds; @p Stencils
   * says which: its Kernel and Reference types, the family's name, and the
   * members of DofLayout and Configuration that give the stencils and their
   * DoFs, reference, Voronoi length and natural strains (hinge_family.h,
   * junction_family.h). Internal variables: the material's hinge variables,
   * per stencil.
   */
  template <class Stencils>
  class BendingFamily : public ElementFamily
  {
  public:
    using Kernel    = typename Stencils::Kernel;
    using Reference = typename Stencils::Reference;

    /// Per rod: @p kernels and @p materials (must outlive the family).
    BendingFamily(
      const DofLayout                                       &layout,
      const std::vector<std::unique_ptr<Kernel>>            &kernels,
      const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    std::string
    name() const override
    {
      return Stencils::name;
    }

    unsigned int
    n_stencils() const override;

    void
    get_dofs(unsigned int                   s,
             std::vector<global_dof_index> &dofs) const override;

    void
    evaluate(unsigned int        s,
             const StencilState &state,
             Derivatives         derivatives,
             LocalContribution  &local) const override;

    unsigned int
    n_internal_variables(unsigned int s) const override;

    void
    update_internal_variables(unsigned int        s,
                              const StencilState &state,
                              double             *updated) const override;

    /// The material's hinge variables at the middle vertex of each
    /// stencil, where Stencils::drawn.
    void
    write_internal_variables(const InternalVariables &history,
                             InternalVariableFields  &fields) const override;

  private:
    /// The stencils of this kind in the layout.
    const auto &
    stencils() const
    {
      return (layout.*Stencils::stencils)();
    }

    /// Stencil @p s at @p state.
    BendingStencil<Kernel, Reference>
    stencil_at(unsigned int s, const StencilState &state) const;

    const DofLayout                                       &layout;
    const std::vector<std::unique_ptr<Kernel>>            &kernels;
    const std::vector<std::shared_ptr<const RodMaterial>> &materials;
  };
} // namespace rodnet

#endif
