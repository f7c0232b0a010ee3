#ifndef RODNET_MATERIALS_INPUT_LIMITS_H
#define RODNET_MATERIALS_INPUT_LIMITS_H

namespace rodnet
{
  /**
   * Largest magnitude of a number rodnet accepts as input (every number in
   * a scene entry, every material parameter) and of the section constants
   * and rigidities computed from them. No rod quantity in SI units comes
   * near it (a steel cable's EA is about 1e9 N), while products of three
   * such numbers, as residuals, energies and their squares form them, stay
   * below the overflow of a double (1.8e308): a value past it is a typo or
   * a test of the program, never a rod, and is refused rather than left to
   * turn into a non-finite residual.
   */
  inline constexpr double max_input_magnitude = 1e100;
} // namespace rodnet

#endif
