// The helical spring of scenes/helical_spring.prm, shared by its validation
// test (tests/validation/helical_spring.cc) and the study of turns and
// segments per turn (bench/helical_spring.cc): steel wire of radius 1 mm on
// a coil of radius 10 mm, pitch 4 mm, E = 2e11 Pa, nu = 0.3, clamped on the
// coil at both ends, the upper clamp moved by -0.1 mm along the axis.
#ifndef RODNET_TESTS_COMMON_HELICAL_SPRING_H
#define RODNET_TESTS_COMMON_HELICAL_SPRING_H

#include <deal.II/base/parameter_handler.h>

#include "run_scene_text.h"
#include <cmath>
#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace testing
  {
    namespace spring
    {
      constexpr double coil_radius = 0.01;
      constexpr double rise        = 4e-3 / (2 * M_PI); ///< per radian
      constexpr double wire_radius = 1e-3;
      constexpr double E           = 2e11;
      constexpr double G           = E / (2 * (1 + 0.3));
      /// Of the upper clamp along z, as in the scene.
      constexpr double displacement = -1e-4;
    } // namespace spring

    /// k = G d^4 / (8 D^3 n) of the close-coiled spring of @p turns turns.
    inline double
    close_coiled_stiffness(const double turns)
    {
      using namespace spring;
      return G * std::pow(2 * wire_radius, 4) /
             (8 * std::pow(2 * coil_radius, 3) * turns);
    }

    inline double
    spring_pitch_angle()
    {
      return std::atan(spring::rise / spring::coil_radius);
    }

    /// VALIDATION.md: the pitch multiplies the compliance by
    /// (cos^2 a + (GJ/EI) sin^2 a) / cos^2 a, GJ/EI = 1 / (1 + nu).
    inline double
    validation_md_stiffness(const double turns)
    {
      const double c                    = std::cos(spring_pitch_angle());
      const double s                    = std::sin(spring_pitch_angle());
      const double torsion_over_bending = 2 * spring::G / spring::E;
      return close_coiled_stiffness(turns) * c * c /
             (c * c + torsion_over_bending * s * s);
    }

    /**
     * Castigliano on the ideal spring (the load on the axis, no end moments
     * but its own): the moment R F about e_theta is a torque R F cos a and a
     * bending moment R F sin a along the whole wire of length
     * L = 2 pi R n / cos a, and the axial force F sin a stretches it:
     *   1/k = L R^2 (cos^2 a / GJ + sin^2 a / EI) + L sin^2 a / EA
     * (doc/validation.md, "Helical spring").
     */
    inline double
    ideal_spring_stiffness(const double turns)
    {
      using namespace spring;
      const double a = spring_pitch_angle();
      const double c = std::cos(a), s = std::sin(a);
      const double A  = M_PI * std::pow(wire_radius, 2);
      const double I  = M_PI * std::pow(wire_radius, 4) / 4;
      const double L  = 2 * M_PI * coil_radius * turns / c;
      const double R2 = coil_radius * coil_radius;
      return 1.0 / (L * R2 * (c * c / (G * 2 * I) + s * s / (E * I)) +
                    L * s * s / (E * A));
    }

    /**
     * k = -force / displacement of scenes/helical_spring.prm run as shipped,
     * or, where @p turns is not 0, with @p turns turns of
     * @p segments_per_turn segments (both vertices of the upper clamp
     * moved); with hinge kernel @p kernel. Throws if the run fails.
     */
    inline double
    helical_spring_stiffness(const unsigned int turns,
                             const unsigned int segments_per_turn,
                             const std::string &kernel)
    {
      dealii::ParameterHandler prm;
      Scene::declare_parameters(prm);
      prm.parse_input(RODNET_SOURCE_DIR "/scenes/helical_spring.prm");
      std::string changes = "subsection Geometry\n"
                            "  set Hinge kernel = " +
                            kernel + "\nend\n";
      if (turns > 0)
        {
          const unsigned int n = turns * segments_per_turn;
          changes += "subsection Geometry\n"
                     "  set Turns = " +
                     std::to_string(turns) +
                     "\n  set Segments = " + std::to_string(n) +
                     "\nend\n"
                     "subsection Supports\n"
                     "  set Prescribed displacements = end: z=-1e-4; " +
                     std::to_string(n - 1) + ": z=-1e-4\nend\n";
        }
      prm.parse_input_from_string(changes + "subsection Output\n"
                                            "  set Write VTU = false\n"
                                            "  set Plot = false\n"
                                            "end\n");
      const RunSummary run = run_scene(Scene(prm), "helical_spring", nullptr);
      // Two rows: the unloaded state (step 0) and the one load step.
      if (!run.failure.empty() || run.rows.size() != 2)
        throw std::runtime_error("helical spring: " + run.failure);
      return run.rows.back()[probe_column(run, "force")] / spring::displacement;
    }
  } // namespace testing
} // namespace rodnet

#endif
