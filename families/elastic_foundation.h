#ifndef RODNET_FAMILIES_ELASTIC_FOUNDATION_H
#define RODNET_FAMILIES_ELASTIC_FOUNDATION_H

#include <core/element_family.h>
#include <core/family_request.h>
#include <core/rod_network.h>

#include <optional>
#include <vector>

namespace rodnet
{
  /// The constants of an elastic foundation (scene subsection "Elastic
  /// foundation").
  struct ElasticFoundationParameters
  {
    /// Winkler modulus k: force per unit length per unit displacement
    /// (N/m^2). 0: no foundation.
    double stiffness = 0;
    /// The unit direction the springs act along; none: all directions.
    std::optional<Vector3> direction;
    /// The rods that rest on the foundation; empty: all.
    std::vector<unsigned int> rods;
  };

  /**
   * A Winkler foundation (Hetenyi 1946): springs of modulus k per unit
   * undeformed length that pull every vertex of the chosen rods back to its
   * undeformed position X, along one direction n only (a rod resting on the
   * ground, n the vertical) or in every direction (a rod bonded to a soft
   * substrate). Lumped to the vertices by their undeformed Voronoi lengths
   * l_v (half of each adjacent segment of a chosen rod), the energy is
   *   W = sum_v k l_v / 2 |P (x_v - X_v)|^2,  P = n n^T or the identity,
   * a stencil of the three position DoFs of each vertex, with the constant
   * Hessian k l_v P. A vertex shared by rods at a junction is one stencil
   * that sums the lengths of every chosen rod.
   */
  class ElasticFoundation : public ElementFamily
  {
  public:
    /// Throws std::invalid_argument for a negative or non-finite modulus,
    /// a zero direction or a rod that @p network does not have.
    ElasticFoundation(const RodNetwork                  &network,
                      const DofLayout                   &layout,
                      const ElasticFoundationParameters &parameters);

    std::string
    name() const override
    {
      return "elastic foundation";
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

  private:
    struct Stencil
    {
      std::array<global_dof_index, 3> dofs;
      /// k l_v: the spring constant of the vertex (N/m).
      double spring;
    };

    std::vector<Stencil> stencils;
    /// P: the projection onto the springs' direction, or the identity.
    Eigen::Matrix3d projection;
  };

  /// The scene entries of the elastic foundation (its FamilyRequest).
  class ElasticFoundationRequest : public FamilyRequest
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    bool
    requested() const override
    {
      return parameters.stiffness > 0;
    }

    std::unique_ptr<ElementFamily>
    create(const RodModel &model) const override;

  private:
    ElasticFoundationParameters parameters;
  };
} // namespace rodnet

#endif
