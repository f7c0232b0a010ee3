#ifndef RODNET_FAMILIES_BODY_WEIGHT_FAMILY_H
#define RODNET_FAMILIES_BODY_WEIGHT_FAMILY_H

#include <core/element_family.h>

#include <memory>
#include <vector>

namespace rodnet
{
  class RodModel;

  /// The weight @p weight = m g (N, at load factor 1) of a rigid body whose
  /// centre is at @p offset r_0 from the vertex of junction @p junction
  /// (RigidBody::centre_offset, global axes at the undeformed
  /// configuration).
  struct BodyWeight
  {
    unsigned int junction;
    Vector3      weight;
    Vector3      offset;
  };

  /**
   * The part of the weight of rigid bodies off their vertex that turns with
   * the junction: of the load potential -lambda m g . (x_j + R r_0) the
   * point force lambda m g at x_j is a dead load (rigid_body_weight()), and
   * -lambda m g . R r_0 is a stencil of the junction's four quaternion DoFs
   * q (the increment since the reference), R = R(q Q) the rotation from
   * the undeformed configuration, Q the one at the reference: with p = q
   * normalized, R(q Q) r_0 = R(q) b, b = R(Q) r_0, and m g . R(q) b =
   * q^T A q / q^T q with A quadratic in the components (doc/dynamics.md,
   * "Rigid bodies"). Its gradient on q is the moment R r_0 x m g; its
   * Hessian the load stiffness of the lever.
   */
  class BodyWeightFamily : public ElementFamily
  {
  public:
    BodyWeightFamily(const DofLayout &layout, std::vector<BodyWeight> weights);

    std::string
    name() const override
    {
      return "weight of rigid bodies off their vertex";
    }

    unsigned int
    n_stencils() const override
    {
      return weights.size();
    }

    void
    get_dofs(unsigned int                   s,
             std::vector<global_dof_index> &dofs) const override;

    void
    evaluate(unsigned int        s,
             const StencilState &state,
             Derivatives         derivatives,
             LocalContribution  &local) const override;

    /// The weight is a dead load ramped with the load factor.
    bool
    follows_load_factor() const override
    {
      return !weights.empty();
    }

  private:
    const DofLayout        &layout;
    std::vector<BodyWeight> weights;
  };

  /// The BodyWeightFamily of the bodies of @p model (not finalized) with a
  /// centre off their vertex under the gravitational acceleration
  /// @p gravity, or none if there is none.
  std::unique_ptr<ElementFamily>
  body_weight_family(const RodModel &model, const Vector3 &gravity);
} // namespace rodnet

#endif
