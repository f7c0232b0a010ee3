#ifndef RODNET_ELEMENTS_JUNCTION_KERNEL_H
#define RODNET_ELEMENTS_JUNCTION_KERNEL_H

#include <elements/hinge_kernel.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Number of local degrees of freedom of a junction element (Lestringant &
   * Kochmann 2020, eq. 4), in the order of junction_dofs.
   */
  constexpr unsigned int n_junction_dofs = 11;

  static_assert(n_junction_dofs == n_hinge_dofs,
                "the junction reuses the hinge's vector and strain types");

  /// Local DoF vector of a junction.
  using JunctionVector = HingeVector;
  /// Strains of a junction with their derivatives, as for a hinge.
  using JunctionStrains = HingeStrains;

  /// Offsets of the blocks of a junction's local DoF vector.
  namespace junction_dofs
  {
    /// x_a: first vertex of the physical segment along the rod.
    constexpr unsigned int first_vertex = 0;
    /// x_b: second vertex of the physical segment along the rod.
    constexpr unsigned int second_vertex = 3;
    /// Twist increment of the physical segment from its reference.
    constexpr unsigned int twist = 6;
    /// (w, x, y, z) of the junction's incremental rotation, not necessarily
    /// unit (L&K eq. 19); the identity is (1, 0, 0, 0).
    constexpr unsigned int rotation = 7;
  } // namespace junction_dofs

  /// How the spin angle of the ghost segment follows the junction rotation.
  enum class GhostSpin
  {
    /// The angle of eq. 6 for finite rotations (L&K appendix B).
    exact,
    /// The small-rotation approximation of eq. 8, the sine of the exact
    /// angle.
    small_rotation
  };

  /**
   * Reference data of a junction element.
   */
  struct JunctionReference
  {
    /// Reference director frame of the physical segment (third director =
    /// reference tangent, from x_a to x_b).
    Quaternion segment_frame = Quaternion::Identity();
    /// Reference frame of the ghost segment (third director = reference
    /// ghost tangent t~*, along the rod).
    Quaternion ghost_frame = Quaternion::Identity();
    /// True if the rod starts at the junction (the ghost segment precedes
    /// the physical one and x_a is the junction vertex), false if it ends
    /// there (x_b is the junction vertex and the ghost follows).
    bool ghost_first = false;
    /// Reference twist (tau_i)_star of the classic measure (L&K eq. 12),
    /// as HingeReference::twist with the segments taken in the rod's order
    /// (ghost then physical if ghost_first, else physical then ghost).
    double twist = 0.0;
  };

  /**
   * The junction element of Lestringant & Kochmann (2020), section 2.2: a
   * physical segment tied to a ghost segment whose orientation follows the
   * rigid rotation R(q) of the junction. The ghost segment has the tangent
   * t~ = R t~* (eq. 5), the spin angle w~ of eq. 6,
   * R(t~*, w~) = P_{t~}^{t~*} R, and the directors
   * d~_I = P_{t~*}^{t~} R(t~*, w~) d~_I* (eq. 1); for the exact spin these
   * are R d~_I*. The bending and twisting strains are those of a regular
   * hinge between the physical and the ghost segment (end of L&K section
   * 2.3), with either measure:
   * - "simple": Korner et al. eqs. 2.11 and 2.13, as SimpleHinge;
   * - "classic": L&K eqs. 11 and 12, as ClassicHinge, with w~ as the twist
   *   increment of the ghost segment.
   *
   * The simple measure with the exact spin is differentiated in closed form
   * (elements/simple_junction.h). The others come from forward automatic
   * differentiation (Sacado) in six reduced variables, the central-chart
   * coordinates (elements/central_chart.h) of the unit tangent and of the
   * unit rotation, and the twist, carried back to the 11 DoFs in closed
   * form. The class is stateless and thread-safe.
   */
  class JunctionKernel
  {
  public:
    /// Throws std::invalid_argument naming the known measures if
    /// @p measure is not one of junction_measure_names().
    explicit JunctionKernel(const std::string &measure,
                            GhostSpin          spin = GhostSpin::exact);

    /// The measure, "simple" or "classic".
    std::string
    name() const;

    /// Strains (bending about d1, bending about d2, twist).
    Vector3
    strains(const JunctionVector    &dofs,
            const JunctionReference &reference) const;

    /**
     * Strains with their gradient, and their Hessians if @p with_hessian.
     * Throws ParallelTransportSingular where a transport between opposite
     * vectors would be needed, std::invalid_argument for a zero quaternion,
     * a zero-length segment or non-finite input.
     */
    void
    evaluate(const JunctionVector    &dofs,
             const JunctionReference &reference,
             JunctionStrains         &result,
             bool                     with_hessian) const;

    /// As HingeKernel::evaluate_weighted(): strains and gradient, and the
    /// Hessians summed with the weights at the strains.
    void
    evaluate_weighted(const JunctionVector    &dofs,
                      const JunctionReference &reference,
                      const StrainWeights     &weights,
                      JunctionStrains         &result,
                      HingeMatrix             &weighted) const;

    /// As HingeKernel::weighted_gradient().
    Vector3
    weighted_gradient(const JunctionVector    &dofs,
                      const JunctionReference &reference,
                      const StrainWeights     &weights,
                      HingeVector             &weighted) const;

    /// The cost of an evaluation with its Hessian relative to a simple
    /// hinge's (bench/family_costs, 20 x 20 welded lattice, 2026-12-07):
    /// 0.81 in closed form, 16.7 by automatic differentiation.
    double
    relative_cost() const
    {
      return closed_form() ? 0.8 : 17.0;
    }

  private:
    /// The simple measure with the exact spin, in closed form.
    bool
    closed_form() const
    {
      return simple && spin == GhostSpin::exact;
    }

    bool      simple;
    GhostSpin spin;
  };

  /// The measures accepted by JunctionKernel.
  std::vector<std::string>
  junction_measure_names();

  /**
   * Spin angle w~ of a ghost segment with reference tangent
   * @p reference_tangent under the rotation by the (raw, nonzero)
   * quaternion @p q = (w, x, y, z) (L&K eqs. 5, 6, 8). The exact angle lies
   * in [-pi, pi].
   */
  double
  ghost_spin(const Eigen::Vector4d &q,
             const Vector3         &reference_tangent,
             GhostSpin              spin);

  /// Current frame of a ghost segment of reference frame
  /// @p reference_frame under the rotation @p q (L&K eqs. 1, 5, 6).
  Quaternion
  ghost_frame(const Eigen::Vector4d &q,
              const Quaternion      &reference_frame,
              GhostSpin              spin);
} // namespace rodnet

#endif
