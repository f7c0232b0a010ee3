#include <deal.II/base/exceptions.h>

#include <materials/dr_beam_energy.h>

namespace rodnet
{
  double
  dr_beam_energy(const RodStiffness  &k,
                 const double         rest_length,
                 const DrBeamStrains &s,
                 DrBeamStress        *stress)
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
