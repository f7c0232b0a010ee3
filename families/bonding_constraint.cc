#include <deal.II/base/utilities.h>

#include <core/rod_model.h>
#include <core/vertex_selector.h>
#include <families/bonding_constraint.h>
#include <families/inextensibility_family.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The largest constraint scale EI / l^3 (inextensibility_scale()) of
    /// the segments at vertex @p v of @p model's network.
    double
    stiffest_segment_scale(const RodModel &model, const unsigned int v)
    {
      const DofLayout &layout = model.layout();
      double           scale  = 0;
      for (const SegmentStencil &segment : layout.segments())
        for (const unsigned int end : segment.vertices)
          if (layout.vertex_dof(end, 0) == layout.vertex_dof(v, 0))
            scale =
              std::max(scale,
                       inextensibility_scale(model.material(segment.rod),
                                             model.configuration().rest_length(
                                               segment.cell)));
      return scale;
    }

    /// The three position DoFs of vertex @p v.
    std::array<global_dof_index, 3>
    position_dofs(const DofLayout &layout, const unsigned int v)
    {
      return {{layout.vertex_dof(v, 0),
               layout.vertex_dof(v, 1),
               layout.vertex_dof(v, 2)}};
    }

    /// The point "x, y, z" in @p text, or none where it is not three
    /// numbers (a vertex name).
    std::optional<Vector3>
    bond_point(const std::string &text)
    {
      const auto xyz = dealii::Utilities::split_string_list(text, ',');
      if (xyz.size() != 3)
        return std::nullopt;
      try
        {
          const auto p = dealii::Utilities::string_to_double(xyz);
          return Vector3(p[0], p[1], p[2]);
        }
      catch (const std::exception &)
        {
          return std::nullopt;
        }
    }
  } // namespace


  BondingConstraintFamily::BondingConstraintFamily(const RodModel   &model,
                                                   std::vector<Bond> given)
  {
    const DofLayout  &layout  = model.layout();
    const RodNetwork &network = model.network();
    for (Bond &bond : given)
      {
        BondData data{bond, position_dofs(layout, bond.vertex), {}, {}, 0};
        double   scale = stiffest_segment_scale(model, bond.vertex);
        if (bond.other)
          {
            data.dofs_b = position_dofs(layout, *bond.other);
            if (data.dofs_b == data.dofs_a)
              throw std::invalid_argument("bond \"" + bond.name +
                                          "\" ties a vertex to itself");
            data.closed_gap =
              network.vertex(*bond.other) - network.vertex(bond.vertex);
            scale = std::max(scale, stiffest_segment_scale(model, *bond.other));
          }
        else
          data.closed_gap = bond.point - network.vertex(bond.vertex);
        if (!data.closed_gap.allFinite())
          throw std::invalid_argument("bond \"" + bond.name +
                                      "\": the point is not finite");
        refuse_repeated(data);
        if (!(scale > 0 && std::isfinite(scale)))
          throw std::invalid_argument(
            "bond \"" + bond.name +
            "\": the rods at its vertices have no positive bending rigidity "
            "to scale the constraint");
        data.scale = scale;
        bonds.push_back(std::move(data));
      }
  }


  void
  BondingConstraintFamily::refuse_repeated(const BondData &data) const
  {
    // Two bonds of one vertex to points, or of one pair of vertices, give
    // equal constraint rows: a singular KKT tangent.
    for (const BondData &earlier : bonds)
      {
        const bool same_pair =
          data.bond.other && earlier.bond.other &&
          ((earlier.dofs_a == data.dofs_a && earlier.dofs_b == data.dofs_b) ||
           (earlier.dofs_a == data.dofs_b && earlier.dofs_b == data.dofs_a));
        const bool same_point = !data.bond.other && !earlier.bond.other &&
                                earlier.dofs_a == data.dofs_a;
        if (same_pair || same_point)
          throw std::invalid_argument(
            "bond \"" + data.bond.name + "\" ties what bond \"" +
            earlier.bond.name +
            "\" ties already (its constraints would be redundant)");
      }
  }


  void
  BondingConstraintFamily::get_dofs(const unsigned int             s,
                                    std::vector<global_dof_index> &dofs) const
  {
    const BondData    &data = bonds[s / 3];
    const unsigned int c    = s % 3;
    dofs.assign(1, data.dofs_a[c]);
    if (data.bond.other)
      dofs.push_back(data.dofs_b[c]);
    dofs.push_back(first_multiplier + s);
  }


  void
  BondingConstraintFamily::evaluate(const unsigned int  s,
                                    const StencilState &state,
                                    const Derivatives   derivatives,
                                    LocalContribution  &local) const
  {
    // g = u_a,c - u_b,c - lambda gap_c (the DoFs are displacements); the
    // term k mu g is bilinear: its Hessian has k in the multiplier's row
    // and column only.
    const BondData    &data = bonds[s / 3];
    const unsigned int c    = s % 3;
    const bool         pair = data.bond.other.has_value();
    const double       k    = data.scale;
    const double       mu   = state.u[first_multiplier + s];
    double g = state.u[data.dofs_a[c]] - state.load_factor * data.closed_gap[c];
    if (pair)
      g -= state.u[data.dofs_b[c]];
    local.energy = k * mu * g;
    if (derivatives == Derivatives::energy)
      return;
    const unsigned int n = pair ? 3 : 2;
    // The multiplier's column of the Hessian: d(k g)/d(u_a, u_b, mu).
    Eigen::VectorXd column = Eigen::VectorXd::Zero(n);
    column[0]              = k;
    if (pair)
      column[1] = -k;
    Eigen::VectorXd gradient = mu * column;
    gradient[n - 1]          = k * g;
    Eigen::MatrixXd hessian  = Eigen::MatrixXd::Zero(n, n);
    hessian.col(n - 1)       = column;
    hessian.row(n - 1)       = column.transpose();
    local.store(gradient,
                derivatives == Derivatives::hessian ? &hessian : nullptr);
  }


  bool
  BondingConstraintFamily::follows_load_factor() const
  {
    return std::any_of(bonds.begin(), bonds.end(), [](const BondData &data) {
      return data.closed_gap != Vector3::Zero();
    });
  }


  std::vector<DeclaredDof>
  BondingConstraintFamily::own_dofs() const
  {
    std::vector<DeclaredDof> dofs;
    for (unsigned int b = 0; b < bonds.size(); ++b)
      for (unsigned int c = 0; c < 3; ++c)
        dofs.push_back({DofRole::multiplier,
                        bonds[b].bond.vertex,
                        "bond " + std::to_string(b) + " (" +
                          bonds[b].bond.name + "), its " +
                          std::string(1, "xyz"[c]) + " component",
                        {"bond_force", 3, c, -bonds[b].scale, "N"}});
    return dofs;
  }


  void
  BondingConstraintRequest::declare_parameters(
    dealii::ParameterHandler &prm) const
  {
    prm.declare_entry("Bonds",
                      "",
                      dealii::Patterns::Anything(),
                      "Vertices tied by Lagrange multipliers: \"a = b; c = "
                      "x, y, z\" (to a vertex, to a point; vertices as in "
                      "Point forces); gaps close with the load factor. [-]");
  }


  void
  BondingConstraintRequest::parse_parameters(dealii::ParameterHandler &prm)
  {
    bond_texts.clear();
    for (const std::string &text :
         dealii::Utilities::split_string_list(prm.get("Bonds"), ';'))
      if (!text.empty())
        bond_texts.push_back(text);
  }


  std::unique_ptr<ElementFamily>
  BondingConstraintRequest::create(const RodModel &model) const
  {
    const std::string entry = "Bonding constraints/Bonds";
    std::vector<Bond> bonds;
    for (const std::string &text : bond_texts)
      {
        const auto sides = dealii::Utilities::split_string_list(text, '=');
        if (sides.size() != 2 || sides[0].empty() || sides[1].empty())
          throw std::invalid_argument(
            "entry \"" + entry + "\": \"" + text +
            "\" is not \"a = b\" (a vertex, then a vertex or a point x, y, "
            "z)");
        Bond bond;
        bond.name   = text;
        bond.vertex = select_vertex(model.network(), sides[0], entry);
        if (const std::optional<Vector3> point = bond_point(sides[1]))
          bond.point = *point;
        else
          bond.other = select_vertex(model.network(), sides[1], entry);
        bonds.push_back(bond);
      }
    try
      {
        return std::make_unique<BondingConstraintFamily>(model,
                                                         std::move(bonds));
      }
    catch (const std::invalid_argument &e)
      {
        throw std::invalid_argument("entry \"" + entry + "\": " + e.what());
      }
  }

  RODNET_REGISTER_ELEMENT_FAMILY(BondingConstraintRequest,
                                 "Bonding constraints",
                                 "Lagrange multipliers that tie a vertex to a "
                                 "point or to another vertex")
} // namespace rodnet
