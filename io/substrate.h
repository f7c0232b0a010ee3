#ifndef RODNET_IO_SUBSTRATE_H
#define RODNET_IO_SUBSTRATE_H

#include <deal.II/base/parameter_handler.h>

#include <core/supports_and_loads.h>

#include <Eigen/Dense>
#include <optional>
#include <string>

namespace rodnet
{
  /**
   * Subsection "Substrate" of a scene: bonding sites (rod ends, junctions,
   * any vertex) held to a flat substrate, the plane z = const through them,
   * that deforms in its plane by the affine map x -> c + F(lambda) (x - c)
   * of the load factor lambda, F(lambda) = I + lambda H (pop-up assembly,
   * Lestringant & Kochmann section 4.4). H is symmetric, so the map is a
   * pure stretch: the sites translate and clamped sites keep their
   * orientation. Lowered to the supports every model has (a clamp or a
   * pinned vertex with a prescribed displacement ramped by lambda), so
   * nothing else knows of a substrate (doc/morphing.md).
   */
  struct Substrate
  {
    /// Declares subsection Substrate and its entries.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads subsection Substrate; throws std::invalid_argument naming the
    /// entry for a strain that folds or inverts the substrate, for more
    /// than one strain entry, and for a strain without bonding sites.
    static Substrate
    parse(dealii::ParameterHandler &prm);

    /// Whether the substrate moves the sites: the load factor ramps it.
    bool
    moves() const;

    /**
     * Adds the bonding sites to @p spec, after every other support: a
     * clamp (rod end or junction) or a pinned vertex, each with the
     * displacement of the substrate at load factor 1 at its vertex, for a
     * clamped rod end at the midpoint of its end segment (where the clamp
     * of the end segment acts: Korner et al. section 5a). Throws
     * std::invalid_argument naming the entry and the site for a site that
     * is no vertex, rod end or junction, a site that another support of
     * @p spec holds as well, a site named twice and a site off the plane of
     * the first.
     */
    void
    add_sites(const RodNetwork &network, SupportsAndLoads &spec) const;

    /// Substrate/Clamped sites and Substrate/Pinned sites, as given.
    std::string clamped_sites, pinned_sites;
    /// The in-plane displacement gradient H at load factor 1 (x, y).
    Eigen::Matrix2d gradient = Eigen::Matrix2d::Zero();
    /// The point (x, y) that stays put; the sites' centroid if not given.
    std::optional<Eigen::Vector2d> centre;
  };
} // namespace rodnet

#endif
