#ifndef RODNET_ELEMENTS_SIMPLE_JUNCTION_H
#define RODNET_ELEMENTS_SIMPLE_JUNCTION_H

#include <elements/junction_kernel.h>

namespace rodnet
{
  /**
   * The junction element with the simple measure and the exact ghost spin
   * in closed form, as JunctionKernel("simple", GhostSpin::exact) gives
   * it. With the exact spin of eq. 6, the ghost directors of eq. 1 are
   * R(q) d~_I*: the ghost frame is the unit quaternion r = q / |q| times
   * its reference frame, whose hat variation 2 delta r conj(r) is linear in
   * delta q. The strains are then Korner et al.'s simple measure of the
   * physical segment's frame and this one (reduced::SimpleMeasure), and
   * their derivatives those of SimpleHinge, with the ghost's frame in place
   * of a segment's. Unlike the general kernel, no transport of the ghost
   * tangent is needed, so a ghost tangent turned opposite to its reference
   * is no singularity here.
   */
  namespace simple_junction
  {
    /// Strains (bending about d1, bending about d2, twist).
    Vector3
    strains(const JunctionVector &dofs, const JunctionReference &reference);

    /// As JunctionKernel::evaluate().
    void
    evaluate(const JunctionVector    &dofs,
             const JunctionReference &reference,
             JunctionStrains         &result,
             bool                     with_hessian);

    /// As JunctionKernel::evaluate_weighted(), in one evaluation of the
    /// weighted Hessian.
    void
    evaluate_weighted(const JunctionVector    &dofs,
                      const JunctionReference &reference,
                      const StrainWeights     &weights,
                      JunctionStrains         &result,
                      HingeMatrix             &weighted);

    /// As JunctionKernel::weighted_gradient().
    Vector3
    weighted_gradient(const JunctionVector    &dofs,
                      const JunctionReference &reference,
                      const StrainWeights     &weights,
                      HingeVector             &weighted);
  } // namespace simple_junction
} // namespace rodnet

#endif
