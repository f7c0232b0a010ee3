#ifndef RODNET_CORE_AXIS_MOMENT_FAMILY_H
#define RODNET_CORE_AXIS_MOMENT_FAMILY_H

#include <core/element_family.h>

#include <algorithm>
#include <vector>

namespace rodnet
{
  /// A moment @p moment (N m, at load factor 1) about the fixed unit
  /// @p axis, applied at the quaternion of junction @p junction; a
  /// @p held one keeps its full value at every load factor.
  struct AxisMoment
  {
    unsigned int junction;
    Vector3      axis;
    double       moment;
    bool         held = false;
  };

  /**
   * Applied moments about fixed axes at junction quaternions: the load
   * potential -lambda M theta_u(q Q) of each (Lestringant & Kochmann
   * eqs. 32-33), a stencil of the junction's four quaternion DoFs q (the
   * increment since the reference) with Q the rotation at the reference:
   * a function of the junction's whole rotation, so the load does not
   * depend on where the steps ended. At a state where R v1 is orthogonal
   * to u its load stiffness is that of a quasi-tangential moment with the
   * lever R v1 (doc/continuation.md, "Roll-up under an end moment").
   */
  class AxisMomentFamily : public ElementFamily
  {
  public:
    /// No moments yet (add()); @p layout must outlive the family.
    explicit AxisMomentFamily(const DofLayout &layout);

    /// Adds the moment @p moment, a stencil of its own (before the model
    /// is finalized).
    void
    add(const AxisMoment &moment)
    {
      moments.push_back(moment);
    }

    std::string
    name() const override
    {
      return "applied moments";
    }

    unsigned int
    n_stencils() const override
    {
      return moments.size();
    }

    void
    get_dofs(unsigned int                   s,
             std::vector<global_dof_index> &dofs) const override;

    void
    evaluate(unsigned int        s,
             const StencilState &state,
             Derivatives         derivatives,
             LocalContribution  &local) const override;

    /// Whether a moment is ramped (not held) and not zero.
    bool
    follows_load_factor() const override
    {
      return std::any_of(moments.begin(),
                         moments.end(),
                         [](const AxisMoment &m) {
                           return !m.held && m.moment != 0;
                         });
    }

  private:
    const DofLayout        &layout;
    std::vector<AxisMoment> moments;
  };
} // namespace rodnet

#endif
