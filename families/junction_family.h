#ifndef RODNET_FAMILIES_JUNCTION_FAMILY_H
#define RODNET_FAMILIES_JUNCTION_FAMILY_H

#include <core/element_family.h>
#include <elements/junction_kernel.h>
#include <materials/rod_material.h>

#include <memory>
#include <vector>

namespace rodnet
{
  template <class Kernel, class Reference>
  struct BendingStencil;

  /**
   * The junction elements (Lestringant & Kochmann eq. 4): a rod's segment
   * at a junction or rotation handle and the ghost segment that the
   * junction's quaternion turns, bent and twisted like a hinge of the rod
   * and priced by its material. Stress free where built: the ghost frame
   * starts as the segment's (Configuration), so there are no natural
   * strains but those of activation fields
   * (Configuration::junction_natural_strains()). Internal variables: the material's hinge variables, per
   * junction element.
   */
  class JunctionFamily : public ElementFamily
  {
  public:
    /// Per rod: @p kernels and @p materials (must outlive the family).
    JunctionFamily(
      const DofLayout                                       &layout,
      const std::vector<std::unique_ptr<JunctionKernel>>    &kernels,
      const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    std::string
    name() const override
    {
      return "junction elements";
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
    BendingStencil<JunctionKernel, JunctionReference>
    stencil_at(unsigned int s, const StencilState &state) const;

    const DofLayout                                       &layout;
    const std::vector<std::unique_ptr<JunctionKernel>>    &kernels;
    const std::vector<std::shared_ptr<const RodMaterial>> &materials;
  };
} // namespace rodnet

#endif
