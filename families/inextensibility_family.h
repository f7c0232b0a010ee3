#ifndef RODNET_FAMILIES_INEXTENSIBILITY_FAMILY_H
#define RODNET_FAMILIES_INEXTENSIBILITY_FAMILY_H

#include <core/dof_layout.h>
#include <core/dof_values.h>
#include <core/element_family.h>
#include <materials/rod_material.h>

#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Exact inextensibility of the segments of inextensible rods (Korner et
   * al. eq. 4.4) by Lagrange multipliers. Each stencil is one segment
   * (x_j, x_{j+1}) with its multiplier DoF mu_j, one of the family's own
   * block (own_dofs(): one multiplier per segment of the inextensible rods,
   * in the order of DofLayout::segments()) and contributes the term of the
   * Lagrangian L_j = k_j mu_j g_j,   g_j = (|x_{j+1} - x_j|^2 - l_j^2) / (2
   * l_j), where g_j, the Green-Lagrange strain (|e|^2 / l^2 - 1) / 2 times l,
   * is a length that vanishes exactly where the segment keeps its rest length
   * l_j. Stationarity of the sum of the energy and these terms is the
   * first-order optimality (KKT) condition of the constrained minimization
   * (Nocedal & Wright eq. 12.34), and Newton on it is the SQP method the
   * paper uses; the assembled Hessian is the KKT matrix
   *   [ H + sum_j k_j mu_j grad^2 g_j ,  G^T ]
   *   [ G                             ,  0   ],  G_j = k_j grad g_j.
   *
   * The scale k_j = (largest bending rigidity)/l_j^3 (N/m), the stiffness
   * of a hinge at that segment, makes the constraint rows forces and the
   * multipliers dimensionless with entries of the tangent's size. The axial
   * force of the segment (tension positive) is
   *   N_j = k_j mu_j |x_{j+1} - x_j| / l_j = k_j mu_j at the constraint
   * (axial_force()). A segment whose ends are both held needs no
   * multiplier: its constraint has no free DoF and would make the KKT matrix
   * singular; the model holds such multipliers at zero
   * (DeclaredDof::held_where_supports_hold) and the family leaves their
   * stencils out (hold_own_dofs()).
   */
  class InextensibilityFamily : public ElementFamily
  {
  public:
    /**
     * The segments of @p layout on the inextensible rods of @p network
     * (Rod::inextensible), with the scales from the rods' @p materials at
     * the rest lengths of @p configuration. Throws, naming the rod, where a
     * material has no positive bending rigidity to scale with.
     */
    InextensibilityFamily(
      const DofLayout                                       &layout,
      const RodNetwork                                      &network,
      const Configuration                                   &configuration,
      const std::vector<std::shared_ptr<const RodMaterial>> &materials);

    /// Whether any rod of @p network is inextensible (the family has
    /// stencils).
    static bool
    applies_to(const RodNetwork &network);

    std::string
    name() const override
    {
      return "inextensibility";
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

    /// One multiplier per segment, labelled "rod 0 segment 2 (its
    /// length)", held where both its vertices are.
    std::vector<DeclaredDof>
    own_dofs() const override;

    void
    number_own_dofs(global_dof_index first) override;

    /// Leaves out the stencils whose multiplier is held.
    void
    hold_own_dofs(const std::vector<bool> &held) override;

    /// The scale k of the multiplier of cell @p cell (N/m), 0 where the
    /// segment has none in this family (or it is held).
    double
    scale(unsigned int cell) const;

    /// The axial force N = k mu |e| / l (tension positive) of segment
    /// @p cell in state @p u of @p configuration, 0 where the segment has
    /// no free multiplier.
    double
    axial_force(unsigned int         cell,
                const DofValues     &u,
                const Configuration &configuration) const;

    /// axial_force(), for every segment: the family constrains segment
    /// lengths.
    std::optional<double>
    segment_axial_force(unsigned int        cell,
                        const StencilState &state) const override
    {
      return axial_force(cell, state.u, state.configuration);
    }

  private:
    struct Stencil
    {
      unsigned int segment; ///< index into DofLayout::segments()
      /// Its index in the block until number_own_dofs(), then global.
      global_dof_index multiplier;
      double           scale;
      unsigned int     along_rod; ///< the segment's index along its rod
    };
    const DofLayout     &layout;
    std::vector<Stencil> stencils;
    /// Per cell, the index of its stencil in @ref stencils or none.
    std::vector<unsigned int> stencil_of_cell;
  };

  /**
   * Scale k = (largest rigidity of @p material's hinge at zero strain) /
   * @p rest_length^3 of an inextensibility multiplier (see
   * InextensibilityFamily).
   */
  double
  inextensibility_scale(const RodMaterial &material, double rest_length);
} // namespace rodnet

#endif
