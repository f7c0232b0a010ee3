#ifndef RODNET_FAMILIES_STRETCH_FAMILY_H
#define RODNET_FAMILIES_STRETCH_FAMILY_H

#include <core/element_family.h>
#include <materials/rod_material.h>

#include <memory>
#include <vector>

namespace rodnet
{
  /**
   * The segments of every extensible rod: axial strain l/l0 - 1 of each
   * segment (elements/stretch_kernel.h), less the eigenstrain of
   * activation fields (Configuration::segment_eigenstrain()), priced by its
   * rod's material. The
   * segments of inextensible rods (Rod::inextensible), which keep their
   * length by a multiplier (InextensibilityFamily), store no energy and are
   * left out.
   * Internal variables: the material's segment variables, per segment.
   */
  class StretchFamily : public ElementFamily
  {
  public:
    /// The segments of the extensible rods of @p network; per rod:
    /// @p materials (must outlive the family).
    StretchFamily(
      const DofLayout                                       &layout,
      const RodNetwork                                      &network,
      const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    std::string
    name() const override
    {
      return "segments";
    }

    unsigned int
    n_stencils() const override;

    /// A tenth of a hinge (bench/family_costs).
    double
    relative_cost() const override
    {
      return 0.1;
    }

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

    /// The material's axial force (N) at the committed internal variables,
    /// for the extensible segments.
    std::optional<double>
    segment_axial_force(unsigned int        cell,
                        const StencilState &state) const override;

    /// The material's segment variables per cell.
    void
    write_internal_variables(const InternalVariables &history,
                             InternalVariableFields  &fields) const override;

  private:
    /// The material's response of stencil @p s at @p state's committed
    /// internal variables over @p time_step (the updated ones into
    /// @p updated where not null), its stress only.
    MaterialResponse<1>
    response_without_derivatives(unsigned int        s,
                                 const StencilState &state,
                                 double              time_step,
                                 double             *updated) const;

    /// The segment of stencil @p s.
    const SegmentStencil &
    segment(unsigned int s) const
    {
      return layout.segments()[segments[s]];
    }

    const DofLayout &layout;
    /// Indices into layout.segments() of the extensible segments.
    std::vector<unsigned int> segments;
    /// Per cell, its stencil, or invalid for a segment of an inextensible
    /// rod.
    std::vector<unsigned int>                              stencil_of_cell;
    const std::vector<std::shared_ptr<const RodMaterial>> &materials;
  };
} // namespace rodnet

#endif
