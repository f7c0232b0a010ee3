#ifndef RODNET_ELEMENTS_REDUCED_HINGE_H
#define RODNET_ELEMENTS_REDUCED_HINGE_H

#include <elements/hinge_kernel.h>

namespace rodnet
{
  /**
   * A hinge kernel differentiated in closed form in the reduced variables of
   * segment_kinematics.h: evaluate(), evaluate_weighted() and
   * weighted_gradient() are those of reduced::evaluate() and its siblings
   * for @p Kinematics, built from (dofs, reference, reduced::Needs) with
   * kappa, strain_jacobian(), weighted_hessian(w) and weighted_gradient(w).
   * A kernel derives from it and adds its name() and strains().
   *
   * The members are defined in reduced_hinge.templates.h, which only the
   * file that defines @p Kinematics includes, and instantiated there.
   */
  template <class Kinematics>
  class ReducedHinge : public HingeKernel
  {
  public:
    void
    evaluate(const HingeVector    &dofs,
             const HingeReference &reference,
             HingeStrains         &result,
             bool                  with_hessian) const override;

    /// One evaluation of the weighted Hessian in the reduced variables
    /// (three times less work than three Hessians).
    void
    evaluate_weighted(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const StrainWeights  &weights,
                      HingeStrains         &result,
                      HingeMatrix          &weighted) const override;

    /// The contraction without the 3 x 11 strain gradient.
    Vector3
    weighted_gradient(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const StrainWeights  &weights,
                      HingeVector          &weighted) const override;
  };
} // namespace rodnet

#endif
