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
