#ifndef RODNET_MATERIALS_DR_BEAM_ENERGY_H
#define RODNET_MATERIALS_DR_BEAM_ENERGY_H

#include <elements/dr_beam_kernel.h>
#include <materials/linear_elastic_rod.h>

namespace rodnet
{
  /**
   * Energy of one element of the dynamic-relaxation beam (Sakai, Ohsaki &
   * Adriaenssens 2020; bending-active supplement eqs. 8-11, whose forces
   * are the derivatives of)
   *
   *   U = EA / (2 L0) e^2 + GJ / (2 L0) twist^2
   *     + 2 EI2 / L0 (tilt_a^2 + tilt_a tilt_b + tilt_b^2)
   *     + 2 EI1 / L0 (turn_a^2 + turn_a turn_b + turn_b^2),
   *
   * the Euler-Bernoulli beam with end rotations measured in the same sense
   * at both ends. The node normal plays the role of the rod's director d1:
   * the turn bends about it (EI1), the tilt towards it, about t3 (EI2). A
   * circular arc of curvature kappa has end angles of opposite signs,
   * -/+ kappa L / 2, hence U = EI kappa^2 L / 2.
   *
   * Writes dU/dstrains to @p stress unless it is null. @p rest_length L0
   * must be positive.
   */
  double
  dr_beam_energy(const RodStiffness  &k,
                 double               rest_length,
                 const DrBeamStrains &s,
                 DrBeamStress        *stress);
} // namespace rodnet

#endif
