#ifndef RODNET_MATERIALS_DR_BEAM_ENERGY_H
#define RODNET_MATERIALS_DR_BEAM_ENERGY_H

#include <deal.II/base/exceptions.h>

#include <materials/rod_stiffness.h>

#include <array>

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
   *
   * @p Strains and @p Stress are the element's DrBeamStrains and
   * DrBeamStress (elements/dr_beam_kernel.h), or any types with their
   * members stretch, twist, tilt[2] and turn[2]: the law needs no
   * kinematics, the model (core/dr_model.cc) brings the two together.
   * Without @p stress, @p Stress is of no matter.
   */
  template <class Strains, class Stress = Strains>
  double
  dr_beam_energy(const RodStiffness &k,
                 const double        rest_length,
                 const Strains      &s,
                 Stress             *stress = nullptr)
  {
    Assert(rest_length > 0., dealii::ExcMessage("rest length <= 0"));
    const double inverse_length = 1.0 / rest_length;

    // Eqs. 10-11: the end rotations couple through the beam's 4-2-2-4
    // stiffness, 2 EI / L0 (x_a^2 + x_a x_b + x_b^2).
    const auto bending = [](const std::array<double, 2> &x) {
      return x[0] * x[0] + x[0] * x[1] + x[1] * x[1];
    };
    const double tilt_rigidity = 2.0 * k.EI2 * inverse_length;
    const double turn_rigidity = 2.0 * k.EI1 * inverse_length;

    if (stress)
      {
        // Eqs. 8-11.
        stress->stretch = k.EA * inverse_length * s.stretch;
        stress->twist   = k.GJ * inverse_length * s.twist;
        stress->tilt    = {{tilt_rigidity * (2.0 * s.tilt[0] + s.tilt[1]),
                            tilt_rigidity * (s.tilt[0] + 2.0 * s.tilt[1])}};
        stress->turn    = {{turn_rigidity * (2.0 * s.turn[0] + s.turn[1]),
                            turn_rigidity * (s.turn[0] + 2.0 * s.turn[1])}};
      }
    return 0.5 * inverse_length *
             (k.EA * s.stretch * s.stretch + k.GJ * s.twist * s.twist) +
           tilt_rigidity * bending(s.tilt) + turn_rigidity * bending(s.turn);
  }
} // namespace rodnet

#endif
