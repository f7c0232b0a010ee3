#ifndef RODNET_SOLVERS_CHECKS_STRAIN_RANGE_H
#define RODNET_SOLVERS_CHECKS_STRAIN_RANGE_H

#include <core/solvable_model.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace rodnet
{
  /// The strains a Kirchhoff rod model is meant for (doc/user_guide.md,
  /// "Stability and strain range").
  struct StrainLimits
  {
    /// Largest |axial strain| |e| / l0 - 1 of a segment.
    double axial = 0.1;
    /// Largest bending strain kappa c of a hinge: the change of curvature
    /// from the undeformed shape times the fiber distance c of the section.
    double bending = 0.1;
    /**
     * Per rod: the fiber distances (c1, c2) of its section (m), c1 for the
     * bending about d1 (fibers along d2), c2 for the bending about d2; NaN
     * where the section is unknown (rigidities given directly), which
     * leaves that rod's bending strain unchecked. Empty: unknown for every
     * rod. The bending strain is |(c1 dkappa_1, c2 dkappa_2)|.
     */
    std::vector<std::array<double, 2>> fiber_distance;
  };

  /// The largest strains of a state and where they are.
  struct StrainRange
  {
    double       axial         = 0; ///< signed, largest in magnitude
    unsigned int axial_rod     = 0;
    unsigned int axial_segment = 0;
    /// NaN where no rod has a known fiber distance.
    double       bending        = std::nan("");
    unsigned int bending_rod    = 0;
    unsigned int bending_vertex = 0; ///< the hinge's vertex along its rod
    bool         in_range       = true;
  };

  /**
   * Measures the axial strain of every segment (the stretch kernel's
   * |e| / l0 - 1) and the bending strain c |kappa - kappa_0| / l of every
   * hinge, with kappa the kernel's integrated curvatures (d1 and d2
   * components; kappa_0 those of the undeformed shape, so that a rod
   * stress-free in a curved shape starts at zero) and l the hinge's Voronoi
   * length, against StrainLimits.
   */
  class StrainMonitor
  {
  public:
    /// The model's reference must be the undeformed configuration (as
    /// before the first step): it gives kappa_0.
    StrainMonitor(const SolvableModel &model, const StrainLimits &limits);

    StrainRange
    evaluate(const VectorType &u) const;

    /// One warning line naming the rod and segment (or vertex) of each
    /// strain past its limit; empty if @p range is in range.
    std::string
    warning(const StrainRange &range) const;

  private:
    const SolvableModel &model;
    StrainLimits         limits;
    std::vector<Vector3> undeformed_curvature; ///< per hinge
  };
} // namespace rodnet

#endif
