#ifndef RODNET_FAMILIES_DEVELOPABLE_RIBBON_FAMILY_H
#define RODNET_FAMILIES_DEVELOPABLE_RIBBON_FAMILY_H

#include <core/element_family.h>
#include <elements/hinge_kernel.h>
#include <materials/developable_ribbon_law.h>
#include <materials/rod_material.h>

#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * The hinges of inextensible developable ribbons (Korner et al. section
   * 4(b), the Wunderlich model): per hinge i of a rod whose material has a
   * DevelopableRibbonLaw, the term of the Lagrangian
   *   L_i = E(c_1, eta_i, eta'_i) + k (mu_2 c_2 + mu_3 (c_3 - eta_i c_1)),
   * where c = kappa_i are the hinge kernel's strains (the strip is
   * straight and flat when unstressed: natural strains are refused),
   * eta_i the generatrix slope DoF of the hinge, mu_2 and mu_3 the
   * multipliers of the developability constraints kappa_2 = 0,
   * kappa_3 = eta kappa_1 (eq. 4.6), E the
   * law's energy (eq. 4.7) and k = (D w) / l^2 a scale that makes the
   * constraint rows forces (l the hinge's Voronoi length). eta_i, mu_2 and
   * mu_3 are the family's own DoFs (own_dofs(): three per hinge of a
   * developable rod, in the order of DofLayout::hinges()); a hinge whose
   * DoFs the supports hold has its multipliers held at zero. The
   * centerline's inextensibility is the InextensibilityFamily's.
   *
   * eta' is the central difference (eta_{i+1} - eta_{i-1}) / (2 l) of the
   * neighbouring hinges of the rod; at a hinge with one neighbour (the
   * ends of an open rod, beside a handle) the one-sided difference over
   * the segment between them, and 0 at a hinge alone. Across the closure
   * of a Moebius band (an odd Rod::frame_half_turns) the neighbour's eta
   * enters with the opposite sign: the closing hinge measures its strains
   * against the first segment's frame turned by pi about the tangent,
   * which turns d1 into -d1 and the generatrix slope into -eta. At the
   * two hinges beside the closure, Rod::closure_coupling t blends the
   * central difference (weight t) with the one-sided one that leaves the
   * hinge beyond the closure out (1 - t): at t = 0 eta may jump across
   * the closure at no cost, as beside a clamp.
   *
   * Where kappa_1 vanishes, eta is free (the energy and the constraint do
   * not depend on it). As the paper's drag on eta between iterations, the
   * Hessian (not the energy or the gradient) gets drag() on the diagonal
   * of the eta DoFs: a Newton iteration then keeps eta where it is
   * undetermined, and a converged state is unchanged (the drag's force
   * c (eta - eta_previous) vanishes with the step).
   */
  class DevelopableRibbonFamily : public ElementFamily
  {
  public:
    /// The ribbon hinges of @p layout, with the laws of the rods'
    /// @p materials (must outlive the family) and the rods' @p kernels.
    DevelopableRibbonFamily(
      const DofLayout                                       &layout,
      const RodNetwork                                      &network,
      const Configuration                                   &configuration,
      const std::vector<std::unique_ptr<HingeKernel>>       &kernels,
      const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    std::string
    name() const override
    {
      return "developable ribbons";
    }

    unsigned int
    n_stencils() const override
    {
      return stencils.size();
    }

    void
    get_dofs(unsigned int                   s,
             std::vector<global_dof_index> &dofs) const override;

    void
    evaluate(unsigned int        s,
             const StencilState &state,
             Derivatives         derivatives,
             LocalContribution  &local) const override;

    /// Per ribbon hinge its slope eta (a shape DoF), then the multipliers
    /// mu_2 and mu_3, labelled "rod 0 vertex 3 (its generatrix slope)" and
    /// "rod 0 vertex 3 (its developability)".
    std::vector<DeclaredDof>
    own_dofs() const override;

    void
    number_own_dofs(global_dof_index first) override;

    /// Whether any rod of @p network is a developable ribbon.
    static bool
    applies_to(const RodNetwork &network);

    /// The drag on the eta DoF of stencil @p s in the Hessian:
    /// drag_factor D w / l.
    double
    drag(unsigned int s) const;

    /// drag() relative to the hinge's bending stiffness D w / l.
    static constexpr double drag_factor = 1e-8;

  private:
    struct Stencil
    {
      unsigned int hinge;     ///< index into DofLayout::hinges()
      unsigned int along_rod; ///< the hinge vertex's index along its rod
      /// The distinct eta DoFs: the hinge's, then its neighbours'.
      std::vector<global_dof_index> etas;
      /// eta' = sum_j difference[j] eta_DoF[j] (signs and lengths in).
      std::vector<double>         difference;
      const DevelopableRibbonLaw *law;
      double                      drag; ///< drag()
    };

    /**
     * The eta DoFs and coefficients of eta' in @p stencil (its hinge set):
     * the central difference over the neighbouring ribbon hinges
     * @p hinge_at (per vertex: the ribbon hinge centred there, or -1),
     * one-sided at an end, signs flipped across a Moebius closure and
     * blended with the one-sided difference by the rod's closure coupling
     * beside a ring's closure (see the class documentation).
     */
    void
    set_eta_difference(Stencil                         &stencil,
                       const std::vector<unsigned int> &hinge_at,
                       const RodNetwork                &network,
                       const Configuration             &configuration) const;

    /// The state's ribbon variables of stencil @p s: (eta_i, eta', mu_2,
    /// mu_3).
    Eigen::Vector4d
    ribbon_variables(const Stencil &stencil, const StencilState &state) const;

    const DofLayout                                 &layout;
    const std::vector<std::unique_ptr<HingeKernel>> &kernels;
    std::vector<Stencil>                             stencils;
    /// Per hinge of the layout, the index of its eta (mu_2 and mu_3
    /// follow): in the block until number_own_dofs(), then global; invalid
    /// for hinges of other rods.
    std::vector<global_dof_index> first_of_hinge;
  };
} // namespace rodnet

#endif
