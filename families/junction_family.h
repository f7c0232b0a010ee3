#ifndef RODNET_FAMILIES_JUNCTION_FAMILY_H
#define RODNET_FAMILIES_JUNCTION_FAMILY_H

#include <core/configuration.h>
#include <core/dof_layout.h>
#include <elements/junction_kernel.h>
#include <families/bending_family.h>

namespace rodnet
{
  /**
   * The junction elements (Lestringant & Kochmann eq. 4): a rod's segment
   * at a junction or rotation handle and the ghost segment that the
   * junction's quaternion turns, bent and twisted like a hinge of the rod.
   * Stress free where built: the ghost frame starts as the segment's
   * (Configuration), so there are no natural strains but those of
   * activation fields (Configuration::junction_natural_strains()). The
   * stencil kind of JunctionFamily.
   */
  struct JunctionStencils
  {
    using Kernel    = JunctionKernel;
    using Reference = JunctionReference;

    static constexpr const char *name = "junction elements";
    /// Not drawn: a junction's vertex is shared by several rods.
    static constexpr bool drawn = false;

    static constexpr auto stencils  = &DofLayout::junctions;
    static constexpr auto dofs      = &Configuration::junction_dofs;
    static constexpr auto reference = &Configuration::junction_reference;
    static constexpr auto voronoi_length =
      &Configuration::junction_voronoi_length;
    static constexpr auto natural_strains =
      &Configuration::junction_natural_strains;
  };

  /**
   * The junction family: bending and twisting of every junction element,
   * and the DoFs of the junctions' rotations, which it declares as its own
   * block (four DoFs of DofRole::rotation per junction with a rotation,
   * numbered in the order of the junctions).
   */
  class JunctionFamily : public BendingFamily<JunctionStencils>
  {
  public:
    /// Per rod: @p kernels and @p materials; the junctions of @p network
    /// (all must outlive the family).
    JunctionFamily(
      const DofLayout                                       &layout,
      const RodNetwork                                      &network,
      const std::vector<std::unique_ptr<JunctionKernel>>    &kernels,
      const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    /// The quaternion (w, x, y, z) of each junction with a rotation,
    /// labelled as messages name the junction.
    std::vector<DeclaredDof>
    own_dofs() const override;

    /// The mean of the rods' JunctionKernel::relative_cost(): 0.8 of a
    /// hinge for the simple measure with the exact spin, 17 otherwise.
    double
    relative_cost() const override
    {
      return cost;
    }

  private:
    const RodNetwork &network;
    double            cost;
  };
} // namespace rodnet

#endif
