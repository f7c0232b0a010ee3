#ifndef RODNET_ELEMENTS_HINGE_KERNEL_H
#define RODNET_ELEMENTS_HINGE_KERNEL_H

#include <base/registry.h>
#include <elements/quaternion.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Number of local degrees of freedom of a hinge stencil, in the order
   * (x_{i-1}, phi^{i-1}, x_i, phi^i, x_{i+1}): entries 0-2 position of the
   * previous vertex, 3 twist increment of the previous segment, 4-6 position
   * of the hinge vertex, 7 twist increment of the next segment, 8-10 position
   * of the next vertex (Korner et al. eq. 2.10 restricted to one hinge).
   */
  constexpr unsigned int n_hinge_dofs = 11;

  /// Where each block of a hinge stencil starts in its local DoF vector.
  namespace hinge_offsets
  {
    constexpr int prev_vertex = 0;
    constexpr int prev_twist  = 3;
    constexpr int vertex      = 4;
    constexpr int next_twist  = 7;
    constexpr int next_vertex = 8;
  } // namespace hinge_offsets

  using HingeVector = Eigen::Matrix<double, n_hinge_dofs, 1>;
  using HingeMatrix = Eigen::Matrix<double, n_hinge_dofs, n_hinge_dofs>;

  /**
   * Reference data of one hinge: the director frames D^{i-1} and D^i of its
   * two segments in the reference configuration (their third directors are
   * the reference tangents) and, for kernels that track it, the reference
   * twist (Lestringant & Kochmann eq. 12, (tau_i)_star).
   */
  struct HingeReference
  {
    Quaternion frame_prev = Quaternion::Identity();
    Quaternion frame_next = Quaternion::Identity();
    double     twist      = 0.0;
  };

  /**
   * Integrated strains of a hinge, kappa = (bending about d1, bending about
   * d2, twist), and their first and second derivatives with respect to the
   * 11 local degrees of freedom.
   */
  struct HingeStrains
  {
    Vector3                                kappa;
    Eigen::Matrix<double, 3, n_hinge_dofs> gradient;
    std::array<HingeMatrix, 3>             hessian;
  };

  /**
   * The weights of a contracted Hessian as a function of the strains: the
   * stress of a material at the strains of a stencil, which a kernel's
   * evaluate_weighted() asks for once it has computed them.
   */
  class StrainWeights
  {
  public:
    /// The weights at the (integrated) strains @p kappa.
    virtual Vector3
    at(const Vector3 &kappa) const = 0;

  protected:
    ~StrainWeights() = default;
  };

  /**
   * evaluate_weighted() from a kernel's three Hessians: @p kernel evaluates
   * strains, gradient and Hessians into @p result, and @p weighted is
   * sum_c w_c d^2 kappa_c / du^2 with w = @p weights at the strains. Any
   * kernel with evaluate(dofs, reference, result, with_hessian) can use it.
   */
  template <class Kernel, class Reference>
  void
  weighted_from_hessians(const Kernel        &kernel,
                         const HingeVector   &dofs,
                         const Reference     &reference,
                         const StrainWeights &weights,
                         HingeStrains        &result,
                         HingeMatrix         &weighted)
  {
    kernel.evaluate(dofs, reference, result, true);
    const Vector3 w = weights.at(result.kappa);
    weighted        = w[0] * result.hessian[0];
    for (unsigned int c = 1; c < 3; ++c)
      weighted += w[c] * result.hessian[c];
  }

  /**
   * weighted_gradient() from a kernel's strain gradient: returns the strains
   * and puts into @p weighted sum_c w_c d kappa_c / du with w = @p weights
   * at the strains. Any kernel with evaluate(dofs, reference, result,
   * with_hessian) can use it.
   */
  template <class Kernel, class Reference>
  Vector3
  gradient_from_jacobian(const Kernel        &kernel,
                         const HingeVector   &dofs,
                         const Reference     &reference,
                         const StrainWeights &weights,
                         HingeVector         &weighted)
  {
    HingeStrains strains; // its Hessians are not used (nor initialized)
    kernel.evaluate(dofs, reference, strains, false);
    weighted.noalias() =
      strains.gradient.transpose() * weights.at(strains.kappa);
    return strains.kappa;
  }

  /**
   * A hinge kernel: a stateless function of the local degrees of freedom
   * (current positions, twist increments from the reference) and the
   * reference data, returning the bending and twisting strains with their
   * derivatives. Implementations are thread-safe (const, no scratch members).
   */
  class HingeKernel
  {
  public:
    virtual ~HingeKernel() = default;

    /// Name under which the kernel is selected in a scene.
    virtual std::string
    name() const = 0;

    /// Strains only (for output, reference reset and line searches).
    virtual Vector3
    strains(const HingeVector &dofs, const HingeReference &reference) const = 0;

    /**
     * Strains with their gradient, and their Hessians if @p with_hessian.
     * Throws ParallelTransportSingular where a segment tangent has flipped
     * with respect to its reference.
     */
    virtual void
    evaluate(const HingeVector    &dofs,
             const HingeReference &reference,
             HingeStrains         &result,
             bool                  with_hessian) const = 0;

    /**
     * Strains and gradient into @p result, as evaluate(), and into
     * @p weighted the Hessians summed with the weights that @p weights
     * gives at the strains: sum_c w_c d^2 kappa_c / du^2, the geometric part
     * of an energy's Hessian with stress w (Korner et al. eq. 4.5).
     * result.hessian is scratch. The default sums evaluate()'s Hessians; a
     * kernel whose Hessian terms are linear in a weighting overrides it
     * with one contracted evaluation.
     */
    virtual void
    evaluate_weighted(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const StrainWeights  &weights,
                      HingeStrains         &result,
                      HingeMatrix          &weighted) const
    {
      weighted_from_hessians(*this, dofs, reference, weights, result, weighted);
    }

    /**
     * Returns the strains and puts into @p weighted the gradient of
     * sum_c w_c kappa_c with w = @p weights at the strains, held fixed: the
     * energy gradient for the stress w, all that an assembly of the
     * gradient alone needs. The default contracts evaluate()'s strain
     * gradient; a kernel overrides it where the contraction saves work.
     */
    virtual Vector3
    weighted_gradient(const HingeVector    &dofs,
                      const HingeReference &reference,
                      const StrainWeights  &weights,
                      HingeVector          &weighted) const
    {
      return gradient_from_jacobian(*this, dofs, reference, weights, weighted);
    }
  };

  /// The registry of hinge measures. A new measure is a HingeKernel in a
  /// file pair of its own, registered there with one
  /// RODNET_REGISTER_HINGE_KERNEL line.
  Registry<HingeKernel> &
  hinge_kernel_registry();

  /// Creates the kernel called @p name ("simple", "classic", ...); throws
  /// std::invalid_argument listing the known names otherwise.
  std::unique_ptr<HingeKernel>
  create_hinge_kernel(const std::string &name);

  /// The names accepted by create_hinge_kernel(), sorted.
  std::vector<std::string>
  hinge_kernel_names();
} // namespace rodnet

/// Registers HingeKernel class @p classname (unqualified, inside namespace
/// rodnet) under @p name.
#define RODNET_REGISTER_HINGE_KERNEL(classname, name, description)        \
  namespace                                                               \
  {                                                                       \
    const bool rodnet_registered_##classname = [] {                       \
      rodnet::hinge_kernel_registry().add(name, description, [] {         \
        return std::unique_ptr<rodnet::HingeKernel>(new classname());     \
      });                                                                 \
      return true;                                                        \
    }();                                                                  \
  }

#endif
