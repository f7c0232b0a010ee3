// Subsection Substrate: bonding sites that follow a flat substrate as it
// deforms in its plane (pop-up assembly, Lestringant & Kochmann section
// 4.4; doc/morphing.md, "Substrate loading").
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <core/vertex_selector.h>
#include <io/scene_entries.h>
#include <io/substrate.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    using scene_entries::number;

    const std::string clamped_entry = "Substrate/Clamped sites";
    const std::string pinned_entry  = "Substrate/Pinned sites";

    /// A bonding site: what holds it and where the substrate carries it.
    struct BondingSite
    {
      std::string entry;
      std::string text;
      /// A clamped rod end or junction; none for a pinned site.
      std::optional<std::variant<RodEnd, unsigned int>> clamp;
      /// The vertex the substrate's displacement is prescribed at.
      unsigned int vertex;
      /// Every vertex the site holds (a clamp of a rod end holds two).
      std::vector<unsigned int> held;
      /// The point of the substrate the site is bonded at.
      Vector3 point;
    };

    /// The vertex whose position DoFs @p v shares: a junction's own vertex
    /// for the rod ends it ties, @p v otherwise.
    unsigned int
    position_owner(const RodNetwork &network, const unsigned int v)
    {
      const auto junction = network.junction_at(v);
      return junction ? network.junctions()[*junction].vertex : v;
    }

    /// Every vertex the supports of @p spec hold, by its position owner,
    /// with the name of the first support that holds it.
    std::map<unsigned int, std::string>
    vertices_held(const RodNetwork &network, const SupportsAndLoads &spec)
    {
      std::map<unsigned int, std::string> held;
      const auto hold = [&](const unsigned int v, const std::string &name) {
        held.emplace(position_owner(network, v), name);
      };
      for (const SupportsAndLoads::Clamp &clamp : spec.clamps)
        if (const auto *end = std::get_if<RodEnd>(&clamp.target))
          {
            const auto        &vertices = network.rods()[end->rod].vertices;
            const unsigned int n        = vertices.size();
            hold(network.end_vertex(*end), clamp.name);
            hold(vertices[end->at_start ? 1 : n - 2], clamp.name);
          }
        else
          hold(network.junctions()[std::get<unsigned int>(clamp.target)].vertex,
               clamp.name);
      for (const SupportsAndLoads::FixedComponents &f : spec.fixed_components)
        hold(f.vertex, f.name);
      for (const SupportsAndLoads::AxisLoad &r : spec.rotations)
        hold(r.vertex, r.where);
      return held;
    }

    /// The site @p text of Substrate/Clamped sites: a rod end, bonded at
    /// the midpoint of its end segment, or a junction with a rotation.
    BondingSite
    clamped_site(const RodNetwork &network, const std::string &text)
    {
      BondingSite site{clamped_entry, text, {}, 0, {}, Vector3::Zero()};
      const auto  target = select_rod_end(network, text, clamped_entry);
      site.clamp         = target;
      if (const auto *end = std::get_if<RodEnd>(&target))
        {
          const auto        &vertices = network.rods()[end->rod].vertices;
          const unsigned int n        = vertices.size();
          const unsigned int inner    = vertices[end->at_start ? 1 : n - 2];
          site.vertex                 = network.end_vertex(*end);
          site.held                   = {site.vertex, inner};
          site.point =
            0.5 * (network.vertex(site.vertex) + network.vertex(inner));
          return site;
        }
      const Junction &j = network.junctions()[std::get<unsigned int>(target)];
      if (!j.has_rotation())
        throw std::invalid_argument(
          "entry \"" + clamped_entry + "\": \"" + text +
          "\" is the pinned junction \"" + j.name +
          "\", which has no rotation to clamp; give it in \"" + pinned_entry +
          "\", or clamp the rod ends there one by one");
      site.vertex = j.vertex;
      site.held   = {j.vertex};
      site.point  = network.vertex(j.vertex);
      return site;
    }

    /// The site @p text of Substrate/Pinned sites: any vertex.
    BondingSite
    pinned_site(const RodNetwork &network, const std::string &text)
    {
      const unsigned int v = select_vertex(network, text, pinned_entry);
      return {pinned_entry, text, std::nullopt, v, {v}, network.vertex(v)};
    }

    /// Refuses a site that another support, or another site, holds.
    void
    require_held_once(const RodNetwork                    &network,
                      const std::vector<BondingSite>      &sites,
                      std::map<unsigned int, std::string> &held)
    {
      for (const BondingSite &site : sites)
        for (const unsigned int v : site.held)
          {
            const auto [other, added] =
              held.emplace(position_owner(network, v),
                           site.entry + ": " + site.text);
            if (!added)
              throw std::invalid_argument(
                "entry \"" + site.entry + "\": the bonding site \"" +
                site.text + "\" holds " + network.describe_vertex(v) +
                ", which \"" + other->second +
                "\" holds as well; a bonding site takes its position from "
                "the substrate alone: remove one of the two");
          }
    }

    /// Refuses sites off the plane z = const of the first site.
    void
    require_one_plane(const std::vector<BondingSite> &sites)
    {
      double extent = 0;
      for (const BondingSite &site : sites)
        extent = std::max(extent, (site.point - sites[0].point).norm());
      for (const BondingSite &site : sites)
        if (std::abs(site.point.z() - sites[0].point.z()) > 1e-9 * extent)
          throw std::invalid_argument(
            "entry \"" + site.entry + "\": the bonding site \"" + site.text +
            "\" lies at z = " + number(site.point.z()) +
            ", off the substrate, the plane z = " + number(sites[0].point.z()) +
            " of \"" + sites[0].text +
            "\"; bonding sites lie on the flat substrate");
    }

    /// "x, y" of Substrate/Centre, or none where the entry is empty.
    std::optional<Eigen::Vector2d>
    parse_centre(const std::string &text)
    {
      if (dealii::Utilities::trim(text).empty())
        return std::nullopt;
      const auto xy = dealii::Utilities::split_string_list(text, ',');
      try
        {
          if (xy.size() != 2)
            throw std::invalid_argument("");
          const auto v = dealii::Utilities::string_to_double(xy);
          return Eigen::Vector2d(v[0], v[1]);
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(
            "entry \"Substrate/Centre\": \"" + text +
            "\" should read \"<x>, <y>\", or be empty for the centroid of the "
            "bonding sites");
        }
    }

    /// The displacement gradient at load factor 1 of the one strain entry
    /// that is given; throws naming the entries where several are.
    Eigen::Matrix2d
    parse_gradient(dealii::ParameterHandler &prm)
    {
      const double compression = prm.get_double("Compressive strain");
      const double prestretch  = prm.get_double("Released prestretch");
      const auto   e           = dealii::Utilities::string_to_double(
        dealii::Utilities::split_string_list(prm.get("In-plane strain")));
      const bool in_plane = e[0] != 0 || e[1] != 0 || e[2] != 0;
      if ((compression != 0) + (prestretch != 0) + in_plane > 1)
        throw std::invalid_argument(
          "subsection \"Substrate\": give one of \"Compressive strain\", "
          "\"Released prestretch\" and \"In-plane strain\", not several");
      if (!(compression < 1))
        throw std::invalid_argument(
          "entry \"Substrate/Compressive strain\": " + number(compression) +
          " would shrink the substrate to a point or turn it inside out "
          "(the distances between bonding sites become 1 - " +
          number(compression) + " of their bonded ones); it must be below 1");
      if (!(prestretch > -1))
        throw std::invalid_argument(
          "entry \"Substrate/Released prestretch\": " + number(prestretch) +
          " is no stretch of a substrate (the stretched length over the "
          "relaxed one, minus 1, is above -1)");
      if (in_plane)
        {
          Eigen::Matrix2d h;
          h << e[0], e[2], e[2], e[1];
          const Eigen::Vector2d stretches =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(
              Eigen::Matrix2d::Identity() + h)
              .eigenvalues();
          if (!(stretches.minCoeff() > 0))
            throw std::invalid_argument(
              "entry \"Substrate/In-plane strain\": the substrate's "
              "principal stretch " +
              number(stretches.minCoeff()) +
              " at load factor 1 folds or inverts it; every principal "
              "stretch 1 + e must stay positive");
          return h;
        }
      const double shrink = compression + prestretch / (1 + prestretch);
      return -shrink * Eigen::Matrix2d::Identity();
    }
  } // namespace

  void
  Substrate::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    prm.enter_subsection("Substrate");
    prm.declare_entry("Clamped sites",
                      "",
                      Anything(),
                      "Rod ends ([rod:]start|end, bonded at the end "
                      "segment's midpoint) or junctions (@name) clamped to "
                      "the substrate, comma-separated. [-]");
    prm.declare_entry("Pinned sites",
                      "",
                      Anything(),
                      "Vertices pinned to the substrate, comma-separated. "
                      "[-]");
    prm.declare_entry("Compressive strain",
                      "0",
                      Double(),
                      "Equi-biaxial, at load factor 1: distances between "
                      "sites shrink to 1 - lambda eps of their bonded ones "
                      "(the |eps| of L&K Figs. 9-10); below 1. [-]");
    prm.declare_entry("Released prestretch",
                      "0",
                      Double(),
                      "Equi-biaxial prestretch eps_pre at bonding, released "
                      "at load factor 1: compressive strain eps_pre / (1 + "
                      "eps_pre). [-]");
    prm.declare_entry("In-plane strain",
                      "0, 0, 0",
                      scene_entries::vector_pattern(),
                      "e_xx, e_yy, e_xy: symmetric displacement gradient at "
                      "load factor 1 (a pure stretch). [-]");
    prm.declare_entry("Centre",
                      "",
                      Anything(),
                      "x, y: the point that stays put; empty: the sites' "
                      "centroid. [m]");
    prm.leave_subsection();
  }

  Substrate
  Substrate::parse(dealii::ParameterHandler &prm)
  {
    Substrate s;
    prm.enter_subsection("Substrate");
    s.clamped_sites = prm.get("Clamped sites");
    s.pinned_sites  = prm.get("Pinned sites");
    s.centre        = parse_centre(prm.get("Centre"));
    s.gradient      = parse_gradient(prm);
    prm.leave_subsection();
    const auto no_sites = [](const std::string &list) {
      return dealii::Utilities::trim(list).empty();
    };
    if (s.moves() && no_sites(s.clamped_sites) && no_sites(s.pinned_sites))
      throw std::invalid_argument(
        "subsection \"Substrate\": the substrate is strained but nothing is "
        "bonded to it; give \"Clamped sites\" or \"Pinned sites\"");
    return s;
  }

  bool
  Substrate::moves() const
  {
    return gradient.norm() > 0;
  }

  void
  Substrate::add_sites(const RodNetwork &network, SupportsAndLoads &spec) const
  {
    std::vector<BondingSite> sites;
    for (const std::string &text :
         dealii::Utilities::split_string_list(clamped_sites, ','))
      sites.push_back(clamped_site(network, text));
    for (const std::string &text :
         dealii::Utilities::split_string_list(pinned_sites, ','))
      sites.push_back(pinned_site(network, text));
    if (sites.empty())
      return;
    std::map<unsigned int, std::string> held = vertices_held(network, spec);
    require_held_once(network, sites, held);
    require_one_plane(sites);

    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const BondingSite &site : sites)
      c += site.point.head<2>() / sites.size();
    if (centre)
      c = *centre;
    for (const BondingSite &site : sites)
      {
        // The affine map x -> c + (I + H)(x - c) at load factor 1; the
        // models ramp the displacement with the load factor.
        const Eigen::Vector2d d    = gradient * (site.point.head<2>() - c);
        const std::string     name = site.entry + ": " + site.text;
        if (site.clamp)
          spec.clamps.push_back({name, *site.clamp});
        spec.fixed_components.push_back(
          {name, site.vertex, {{true, true, true}}, Vector3(d[0], d[1], 0)});
      }
  }
} // namespace rodnet
