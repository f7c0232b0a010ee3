#ifndef RODNET_ELEMENTS_CLASSIC_HINGE_H
#define RODNET_ELEMENTS_CLASSIC_HINGE_H

#include <elements/reduced_hinge.h>

namespace rodnet
{
  /**
   * The classic discrete elastic rod measures in the time-parallel form of
   * Lestringant and Kochmann (2020), section 2.3:
   * - bending, eq. 11: kappa^I = k_i . (d_I^{i-1} + d_I^i) / 2 for I = 1, 2,
   *   with the curvature binormal k_i = 2 t^{i-1} x t^i / (1 + t^{i-1}.t^i);
   * - twist, eq. 12: tau_i = (tau_i)_star + phi^i - phi^{i-1} + gamma_i,
   *   with (tau_i)_star = HingeReference::twist and gamma_i the holonomy of
   *   the loop of tangents (T^{i-1}, T^i, t^i, t^{i-1}).
   * The directors are those of Korner et al. eq. 2.8 (L&K eq. 1).
   *
   * If HingeReference::twist is the twist of the reference configuration,
   * i.e. the signed angle about T^i from P_{T^{i-1}}^{T^i} D_1^{i-1} to
   * D_1^i, then tau_i is the signed angle about t^i from
   * P_{t^{i-1}}^{t^i} d_1^{i-1} to d_1^i (modulo 2 pi), i.e. the classic
   * spatial-parallel-transport twist of the current configuration.
   *
   * Gradient and Hessians are closed forms in the reduced variables of
   * segment_kinematics.h (see classic_hinge.cc for their derivation);
   * tests/elements/hinge_derivatives.cc checks them against finite
   * differences and against automatic differentiation of eqs. 11-12.
   */
  namespace reduced
  {
    class ClassicHingeKinematics;
  }

  class ClassicHinge : public ReducedHinge<reduced::ClassicHingeKinematics>
  {
  public:
    std::string
    name() const override;

    Vector3
    strains(const HingeVector    &dofs,
            const HingeReference &reference) const override;
  };
} // namespace rodnet

#endif
