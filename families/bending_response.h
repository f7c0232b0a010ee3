#ifndef RODNET_FAMILIES_BENDING_RESPONSE_H
#define RODNET_FAMILIES_BENDING_RESPONSE_H

#include <core/element_family.h>
#include <elements/hinge_kernel.h>
#include <materials/rod_material.h>

namespace rodnet
{
  /**
   * A bending-and-twisting stencil (a hinge or a junction element) at a
   * state, as evaluate_bending() and bending_increment() take it: its
   * kernel, local DoFs and reference, and its material data and committed
   * state. Hinges and junction elements differ only in their kernel and
   * reference: @p Kernel is a HingeKernel or a JunctionKernel.
   */
  template <class Kernel, class Reference>
  struct BendingStencil
  {
    const Kernel      &kernel;
    HingeVector        dofs;
    const Reference   &reference;
    const RodMaterial &material;
    /// Undeformed Voronoi length, turning integrated strains into densities.
    double voronoi_length;
    /// Committed internal variables of the stencil (null for none).
    const double *committed;
    /// Natural strains: the material sees kappa - natural.
    Vector3 natural;
  };

  /**
   * The material's condensed increment of @p stencil over @p time_step at
   * its strains (the kernel's less the natural ones), without derivatives
   * with respect to the DoFs; the minimizing internal variables go into
   * @p updated unless it is null (the commit of a converged step,
   * ElementFamily::update_internal_variables()).
   */
  template <class Kernel, class Reference>
  MaterialResponse<3>
  bending_increment(const BendingStencil<Kernel, Reference> &stencil,
                    const double                             time_step,
                    double                                  *updated)
  {
    return stencil.material.hinge_increment(
      stencil.kernel.strains(stencil.dofs, stencil.reference) - stencil.natural,
      stencil.voronoi_length,
      stencil.committed,
      time_step,
      updated);
  }

  /**
   * The stress of a stencil's material as the weights of a kernel's
   * contracted derivatives: at() runs the material's increment at the
   * strains less the natural ones and keeps the whole response.
   */
  template <class Kernel, class Reference>
  struct MaterialAtStrains : StrainWeights
  {
    MaterialAtStrains(const BendingStencil<Kernel, Reference> &stencil,
                      const double                             time_step)
        : stencil(stencil)
        , time_step(time_step)
    {
    }

    Vector3
    at(const Vector3 &kappa) const override
    {
      response = stencil.material.hinge_increment(kappa - stencil.natural,
                                                  stencil.voronoi_length,
                                                  stencil.committed,
                                                  time_step,
                                                  nullptr);
      return response.stress;
    }

    const BendingStencil<Kernel, Reference> &stencil;
    const double                             time_step;
    /// The response at the strains at() was last asked at.
    mutable MaterialResponse<3> response;
  };

  /**
   * The energy of a bending-and-twisting stencil with its derivatives:
   * kernel strains minus natural strains -> material (energy, stress,
   * tangent) -> chain rule, with the elastic part J^T C J and the geometric
   * part sum_k s_k d2kappa_k of the Hessian (Korner et al. eq. 4.5). The
   * material sees the committed internal variables and the time step and
   * writes nothing back (see RodModel::commit_internal_variables()).
   */
  template <class Kernel, class Reference>
  void
  evaluate_bending(const BendingStencil<Kernel, Reference> &stencil,
                   double                                   time_step,
                   Derivatives                              derivatives,
                   LocalContribution                       &local)
  {
    if (derivatives == Derivatives::energy)
      {
        local.energy = bending_increment(stencil, time_step, nullptr).energy;
        return;
      }
    // The material's response once the kernel knows the strains: its
    // stress weighs the kernel's derivatives.
    const MaterialAtStrains<Kernel, Reference> material(stencil, time_step);
    if (derivatives == Derivatives::gradient)
      {
        HingeVector gradient;
        stencil.kernel.weighted_gradient(stencil.dofs,
                                         stencil.reference,
                                         material,
                                         gradient);
        local.energy = material.response.energy;
        local.store(gradient, static_cast<const HingeMatrix *>(nullptr));
        return;
      }
    // Per-thread scratch: three 11 x 11 Hessians are too large to build
    // per stencil.
    thread_local HingeStrains strains;
    HingeMatrix               hessian;
    stencil.kernel.evaluate_weighted(stencil.dofs,
                                     stencil.reference,
                                     material,
                                     strains,
                                     hessian);
    const MaterialResponse<3> &w = material.response;
    local.energy                 = w.energy;
    const Eigen::Matrix<double, 3, n_hinge_dofs> cj =
      w.tangent.lazyProduct(strains.gradient);
    hessian.noalias() += strains.gradient.transpose().lazyProduct(cj);
    local.store(HingeVector(strains.gradient.transpose() * w.stress), &hessian);
  }
} // namespace rodnet

#endif
