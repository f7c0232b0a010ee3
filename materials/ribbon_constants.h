#ifndef RODNET_MATERIALS_RIBBON_CONSTANTS_H
#define RODNET_MATERIALS_RIBBON_CONSTANTS_H

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace rodnet
{
  /// Constants of a ribbon material: an isotropic plate material and the
  /// rectangular section of a thin strip (thickness well below width).
  struct RibbonConstants
  {
    double young_modulus; ///< Y (Pa)
    double poisson_ratio; ///< nu (-), in (-1, 0.5]
    double width;         ///< w (m), the full width, along the director d1
    double thickness;     ///< h (m), along the director d2, below w
  };

  /// Declares "Young's modulus", "Poisson's ratio", "Width" and
  /// "Thickness" in the current subsection; @p poisson_help and
  /// @p width_help say what the material makes of nu and w.
  void
  declare_ribbon_constants(dealii::ParameterHandler &prm,
                           const std::string        &poisson_help,
                           const std::string        &width_help);

  /// Reads the entries of declare_ribbon_constants().
  RibbonConstants
  parse_ribbon_constants(dealii::ParameterHandler &prm);

  /// Throws a message naming the entry, prefixed by @p context, unless Y,
  /// w and h are positive and at most 1e100, h < w and nu lies in
  /// (-1, 0.5].
  void
  check_ribbon_constants(const std::string     &context,
                         const RibbonConstants &constants);
} // namespace rodnet

#endif
