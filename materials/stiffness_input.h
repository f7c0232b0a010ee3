#ifndef RODNET_MATERIALS_STIFFNESS_INPUT_H
#define RODNET_MATERIALS_STIFFNESS_INPUT_H

#include <deal.II/base/parameter_handler.h>

#include <materials/cross_section.h>
#include <materials/rod_stiffness.h>

#include <optional>
#include <string>

namespace rodnet
{
  /// The rigidities a material's "Stiffness input" gives, and for
  /// "section" the cross-section they come from.
  struct StiffnessInput
  {
    RodStiffness                stiffness;
    std::optional<CrossSection> section;
  };

  /// Declares "Stiffness input" (section | direct, default section) in the
  /// current subsection, with the material's help text @p help.
  void
  declare_stiffness_input(dealii::ParameterHandler &prm,
                          const std::string        &help);

  /**
   * Reads the rigidities as "Stiffness input" says. For "section": Young's
   * modulus E from the entry @p modulus_entry, the shear modulus from
   * "Shear modulus" where @p shear_modulus_entry says the material declares
   * it and it is not 0, else E / (2 (1 + nu)) from "Poisson's ratio"; the
   * section from CrossSectionParameters. For "direct": the entries of
   * declare_direct_rigidities(), unchecked (the material's constructor
   * checks them). Throws a message starting with @p context and naming
   * the entry where a modulus or the section is inadmissible.
   */
  StiffnessInput
  parse_stiffness_input(dealii::ParameterHandler &prm,
                        const std::string        &context,
                        const std::string        &modulus_entry,
                        bool                      shear_modulus_entry);
} // namespace rodnet

#endif
