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

    static constexpr auto stencils  = &DofLayout::junctions;
    static constexpr auto dofs      = &Configuration::junction_dofs;
    static constexpr auto reference = &Configuration::junction_reference;
    static constexpr auto voronoi_length =
      &Configuration::junction_voronoi_length;
    static constexpr auto natural_strains =
      &Configuration::junction_natural_strains;
  };

  /// The junction family: bending and twisting of every junction element.
  using JunctionFamily = BendingFamily<JunctionStencils>;
} // namespace rodnet

#endif
