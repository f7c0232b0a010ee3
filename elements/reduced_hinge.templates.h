#ifndef RODNET_ELEMENTS_REDUCED_HINGE_TEMPLATES_H
#define RODNET_ELEMENTS_REDUCED_HINGE_TEMPLATES_H

#include <elements/reduced_hinge.h>
#include <elements/segment_kinematics.h>

namespace rodnet
{
  template <class Kinematics>
  void
  ReducedHinge<Kinematics>::evaluate(const HingeVector    &dofs,
                                     const HingeReference &reference,
                                     HingeStrains         &result,
                                     const bool            with_hessian) const
  {
    reduced::evaluate<Kinematics>(dofs, reference, result, with_hessian);
  }


  template <class Kinematics>
  void
  ReducedHinge<Kinematics>::evaluate_weighted(const HingeVector    &dofs,
                                              const HingeReference &reference,
                                              const StrainWeights  &weights,
                                              HingeStrains         &result,
                                              HingeMatrix &weighted) const
  {
    reduced::evaluate_weighted<Kinematics>(dofs,
                                           reference,
                                           weights,
                                           result,
                                           weighted);
  }


  template <class Kinematics>
  Vector3
  ReducedHinge<Kinematics>::weighted_gradient(const HingeVector    &dofs,
                                              const HingeReference &reference,
                                              const StrainWeights  &weights,
                                              HingeVector &weighted) const
  {
    return reduced::weighted_gradient<Kinematics>(dofs,
                                                  reference,
                                                  weights,
                                                  weighted);
  }
} // namespace rodnet

#endif
