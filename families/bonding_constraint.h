#ifndef RODNET_FAMILIES_BONDING_CONSTRAINT_H
#define RODNET_FAMILIES_BONDING_CONSTRAINT_H

#include <core/element_family.h>
#include <core/family_request.h>

#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /// One bond: a vertex tied to a point or to another vertex.
  struct Bond
  {
    /// The bonded vertex a (a triangulation vertex).
    unsigned int vertex = 0;
    /// The vertex b it is tied to; none: it is tied to @p point.
    std::optional<unsigned int> other;
    /// The point p it is tied to (where @p other is none).
    Vector3 point = Vector3::Zero();
    /// How the scene wrote it ("0:end = 1:start"), for messages.
    std::string name;
  };

  /**
   * Bonding constraints: each ties a vertex a to a point p, or to another
   * vertex b, with three Lagrange multipliers mu of its own (a DoF block
   * that the family declares, ElementFamily::own_dofs()). The gap closes
   * with the load factor lambda, from the undeformed positions X on:
   *   g(lambda) = x_a - ((1 - lambda) X_a + lambda p)           (point),
   *   g(lambda) = x_a - x_b - (1 - lambda) (X_a - X_b)          (vertex),
   * so a bond whose ends start together holds from the first step, and one
   * across a gap pulls the vertices together over the load steps. The
   * Lagrangian term is k mu . g, one stencil per component: (x_a,c, mu_c)
   * or (x_a,c, x_b,c, mu_c). The scale k is the bending stiffness
   * EI / l^3 of the stiffest segment at the bonded vertices (as the
   * inextensibility constraint's, families/inextensibility_family.h), so
   * that both rows of the KKT tangent are forces: k mu is the force the bond
   * applies to vertex b (and minus it to vertex a, the vertex field
   * "bond_force"). A vertex-to-vertex bond with a gap fixes the gap's
   * direction while it closes; once closed (lambda = 1) it is a ball joint,
   * invariant under rigid motions.
   */
  class BondingConstraintFamily : public ElementFamily
  {
  public:
    /// Throws std::invalid_argument for a bond of a vertex to itself, to a
    /// point that is not finite, a bond repeated, or one at a vertex whose
    /// rods have no bending rigidity.
    BondingConstraintFamily(const RodModel &model, std::vector<Bond> bonds);

    std::string
    name() const override
    {
      return "bonding constraints";
    }

    unsigned int
    n_stencils() const override
    {
      return 3 * bonds.size();
    }

    void
    get_dofs(unsigned int                   s,
             std::vector<global_dof_index> &dofs) const override;

    void
    evaluate(unsigned int        s,
             const StencilState &state,
             Derivatives         derivatives,
             LocalContribution  &local) const override;

    /// Whether a bond closes a gap (its ends start apart).
    bool
    follows_load_factor() const override;

    /// Three multipliers per bond, at its vertex a.
    std::vector<DeclaredDof>
    own_dofs() const override;

    void
    number_own_dofs(global_dof_index first) override
    {
      first_multiplier = first;
    }

  private:
    /// Per bond: its DoFs, the gap at lambda = 1 (p - X_a or X_b - X_a)
    /// that the constraint closes, and its scale k.
    struct BondData
    {
      Bond                            bond;
      std::array<global_dof_index, 3> dofs_a;
      std::array<global_dof_index, 3> dofs_b;
      Vector3                         closed_gap;
      double                          scale;
    };

    /// Throws std::invalid_argument where @p data ties what an earlier
    /// bond ties (a vertex to a point twice, a pair of vertices twice).
    void
    refuse_repeated(const BondData &data) const;

    std::vector<BondData> bonds;
    global_dof_index      first_multiplier = 0;
  };

  /// The scene entries of the bonding constraints (their FamilyRequest):
  /// subsection "Bonding constraints", entry "Bonds".
  class BondingConstraintRequest : public FamilyRequest
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    bool
    requested() const override
    {
      return !bond_texts.empty();
    }

    std::unique_ptr<ElementFamily>
    create(const RodModel &model) const override;

  private:
    /// One "a = b" text per bond.
    std::vector<std::string> bond_texts;
  };
} // namespace rodnet

#endif
