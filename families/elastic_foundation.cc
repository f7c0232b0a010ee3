#include <deal.II/base/utilities.h>

#include <core/rod_model.h>
#include <families/elastic_foundation.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// P = n n^T for the unit direction @p n, the identity for none.
    Eigen::Matrix3d
    spring_projection(const std::optional<Vector3> &direction)
    {
      if (!direction)
        return Eigen::Matrix3d::Identity();
      const double length = direction->norm();
      if (!(length > 0) || !std::isfinite(length))
        throw std::invalid_argument(
          "elastic foundation: the direction of the springs must be a "
          "nonzero vector");
      const Vector3 n = *direction / length;
      return n * n.transpose();
    }

    /// Whether rod @p rod rests on the foundation; throws for a rod the
    /// network does not have.
    std::vector<bool>
    chosen_rods(const RodNetwork &network, const std::vector<unsigned int> &rods)
    {
      const unsigned int n_rods = network.rods().size();
      std::vector<bool>  chosen(n_rods, rods.empty());
      for (const unsigned int r : rods)
        {
          if (r >= n_rods)
            throw std::invalid_argument(
              "elastic foundation: rod " + std::to_string(r) +
              " does not exist; the network has " + std::to_string(n_rods) +
              " rods (numbered from 0)");
          chosen[r] = true;
        }
      return chosen;
    }
  } // namespace


  ElasticFoundation::ElasticFoundation(
    const RodNetwork                  &network,
    const DofLayout                   &layout,
    const ElasticFoundationParameters &parameters)
      : projection(spring_projection(parameters.direction))
  {
    if (!(parameters.stiffness >= 0) || !std::isfinite(parameters.stiffness))
      throw std::invalid_argument(
        "elastic foundation: the modulus k must be finite and not negative");
    const std::vector<bool> chosen = chosen_rods(network, parameters.rods);
    // Voronoi lengths per position DoF triplet: the ends of rods at a
    // junction share one (DofLayout), hence one spring.
    std::map<global_dof_index, unsigned int> stencil_of;
    for (const SegmentStencil &segment : layout.segments())
      {
        if (!chosen[segment.rod])
          continue;
        const double half = 0.5 * (network.vertex(segment.vertices[1]) -
                                   network.vertex(segment.vertices[0]))
                                    .norm();
        for (const unsigned int v : segment.vertices)
          {
            const global_dof_index first = layout.vertex_dof(v, 0);
            const auto [it, added] =
              stencil_of.emplace(first, stencils.size());
            if (added)
              stencils.push_back({{{first,
                                    layout.vertex_dof(v, 1),
                                    layout.vertex_dof(v, 2)}},
                                  0.0});
            stencils[it->second].spring += parameters.stiffness * half;
          }
      }
  }


  void
  ElasticFoundation::get_dofs(const unsigned int             s,
                              std::vector<global_dof_index> &dofs) const
  {
    dofs.assign(stencils[s].dofs.begin(), stencils[s].dofs.end());
  }


  void
  ElasticFoundation::evaluate(const unsigned int  s,
                              const StencilState &state,
                              const Derivatives   derivatives,
                              LocalContribution  &local) const
  {
    const Stencil &stencil = stencils[s];
    // The DoFs are the displacement x - X of the vertex.
    Vector3 u;
    for (unsigned int c = 0; c < 3; ++c)
      u[c] = state.u[stencil.dofs[c]];
    const Vector3 force = stencil.spring * (projection * u);
    local.energy        = 0.5 * u.dot(force);
    if (derivatives == Derivatives::energy)
      return;
    const Eigen::Matrix3d hessian = stencil.spring * projection;
    local.store(force,
                derivatives == Derivatives::hessian ? &hessian : nullptr);
  }


  void
  ElasticFoundationRequest::declare_parameters(
    dealii::ParameterHandler &prm) const
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Stiffness",
                      "0",
                      Double(0),
                      "Winkler modulus k of the foundation the rods rest "
                      "on: force per unit length per unit displacement; 0 "
                      "for none. [N/m^2]");
    prm.declare_entry("Direction",
                      "all",
                      Anything(),
                      "The springs' direction, \"x, y, z\" (the vertical "
                      "of a rod on the ground), or \"all\" (a rod bonded "
                      "to a substrate). [-]");
    prm.declare_entry("Rods",
                      "all",
                      Anything(),
                      "Rods on the foundation: \"all\" or rod numbers "
                      "\"0, 2\". [-]");
  }


  void
  ElasticFoundationRequest::parse_parameters(dealii::ParameterHandler &prm)
  {
    parameters.stiffness        = prm.get_double("Stiffness");
    const std::string direction = prm.get("Direction");
    parameters.direction.reset();
    if (direction != "all")
      {
        const auto xyz = dealii::Utilities::split_string_list(direction, ',');
        try
          {
            if (xyz.size() != 3)
              throw std::invalid_argument("");
            const auto n = dealii::Utilities::string_to_double(xyz);
            parameters.direction = Vector3(n[0], n[1], n[2]);
          }
        catch (const std::exception &)
          {
            throw std::invalid_argument(
              "entry \"Elastic foundation/Direction\": \"" + direction +
              "\" is neither \"all\" nor a vector x, y, z");
          }
        if (parameters.direction->norm() == 0)
          throw std::invalid_argument(
            "entry \"Elastic foundation/Direction\": the direction is the "
            "zero vector; give the direction the springs act along");
      }
    parameters.rods.clear();
    const std::string rods = prm.get("Rods");
    if (rods != "all")
      try
        {
          for (const int r : dealii::Utilities::string_to_int(
                 dealii::Utilities::split_string_list(rods, ',')))
            {
              if (r < 0)
                throw std::invalid_argument("");
              parameters.rods.push_back(r);
            }
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(
            "entry \"Elastic foundation/Rods\": \"" + rods +
            "\" is neither \"all\" nor a list of rod numbers");
        }
  }


  std::unique_ptr<ElementFamily>
  ElasticFoundationRequest::create(const RodModel &model) const
  {
    try
      {
        return std::make_unique<ElasticFoundation>(model.network(),
                                                   model.layout(),
                                                   parameters);
      }
    catch (const std::invalid_argument &e)
      {
        throw std::invalid_argument(
          std::string("section \"Elastic foundation\": ") + e.what());
      }
  }

  RODNET_REGISTER_ELEMENT_FAMILY(ElasticFoundationRequest,
                                 "Elastic foundation",
                                 "Winkler springs per unit length that hold "
                                 "the rods to their undeformed positions")
} // namespace rodnet
