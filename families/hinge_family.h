#ifndef RODNET_FAMILIES_HINGE_FAMILY_H
#define RODNET_FAMILIES_HINGE_FAMILY_H

#include <core/element_family.h>
#include <elements/hinge_kernel.h>
#include <materials/rod_material.h>

#include <memory>
#include <vector>

namespace rodnet
{
  template <class Kernel, class Reference>
  struct BendingStencil;

  /**
   * The hinges of every rod (Korner et al. eq. 2.10): bending and twisting
   * of two consecutive segments, measured by the rod's hinge kernel and
   * priced by its material, with the natural strains of the Configuration.
   * Internal variables: the material's hinge variables, per hinge.
   */
  class HingeFamily : public ElementFamily
  {
  public:
    /// Per rod: @p kernels and @p materials (must outlive the family).
    HingeFamily(const DofLayout                                       &layout,
                const std::vector<std::unique_ptr<HingeKernel>>       &kernels,
                const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    std::string
    name() const override
    {
      return "hinges";
    }

    unsigned int
    n_stencils() const override;

    void
    get_dofs(unsigned int s, std::vector<global_dof_index> &dofs) const override;

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

  private:
    /// Stencil @p s at @p state.
    BendingStencil<HingeKernel, HingeReference>
    stencil_at(unsigned int s, const StencilState &state) const;

    const DofLayout                                       &layout;
    const std::vector<std::unique_ptr<HingeKernel>>       &kernels;
    const std::vector<std::shared_ptr<const RodMaterial>> &materials;
  };
} // namespace rodnet

#endif
