#ifndef RODNET_FAMILIES_HINGE_FAMILY_H
#define RODNET_FAMILIES_HINGE_FAMILY_H

#include <core/configuration.h>
#include <core/dof_layout.h>
#include <elements/hinge_kernel.h>
#include <families/bending_family.h>

namespace rodnet
{
  /**
   * The hinges of every rod (Korner et al. eq. 2.10): bending and twisting
   * of two consecutive segments, with the natural strains of the
   * Configuration. The stencil kind of HingeFamily.
   */
  struct HingeStencils
  {
    using Kernel    = HingeKernel;
    using Reference = HingeReference;

    static constexpr const char *name = "hinges";
    /// Its internal variables are drawn at the hinge's vertex.
    static constexpr bool drawn = true;

    static constexpr auto stencils        = &DofLayout::hinges;
    static constexpr auto dofs            = &Configuration::hinge_dofs;
    static constexpr auto reference       = &Configuration::hinge_reference;
    static constexpr auto voronoi_length  = &Configuration::voronoi_length;
    static constexpr auto natural_strains = &Configuration::natural_strains;
  };

  /// The hinge family: bending and twisting of every rod's hinges.
  using HingeFamily = BendingFamily<HingeStencils>;
} // namespace rodnet

#endif
