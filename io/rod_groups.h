#ifndef RODNET_IO_ROD_GROUPS_H
#define RODNET_IO_ROD_GROUPS_H

#include <deal.II/base/parameter_handler.h>

#include <core/rod_network.h>
#include <io/activation_fields.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * What a scene's subsection "Group <name>" gives the rods of one group:
   * a material, an orientation of d1 and a number of segments, each
   * optional. The group "all" holds every rod; the others are the groups
   * the generator or the network file tags beams with
   * (RodGraph::Beam::groups).
   */
  struct RodGroupSettings
  {
    /// The group's name, as in the subsection's title.
    std::string name;
    /// The material subsection's name ("soft" for "Material soft"); empty:
    /// not given.
    std::string material;
    /// d1 of the group's beams (made orthogonal to each beam); not given:
    /// the beam's own.
    std::optional<Vector3> director;
    /// Segments of each beam of the group; 0: not given.
    unsigned int segments = 0;
    /// The items of its activation entries (activation_entries()).
    std::vector<ActivationItem> activation;
  };

  /// What the groups give one rod, and which group gave it (for messages).
  struct RodSettings
  {
    std::string            material, material_group;
    std::optional<Vector3> director;
    std::string            director_group;
    unsigned int           segments = 0;
    std::string            segments_group;
    /// The activation items of all its groups: they add.
    std::vector<ActivationItem> activation;
  };

  /// The title prefix of a group subsection, "Group ".
  inline const std::string group_subsection_prefix = "Group ";

  /// The title prefix of a named material subsection, "Material ".
  inline const std::string material_subsection_prefix = "Material ";

  /// The name in the subsection title @p title after @p prefix ("soft" of
  /// "Material soft"); none if @p title does not start with @p prefix or
  /// names nothing after it.
  std::optional<std::string>
  name_in_title(const std::string &title, const std::string &prefix);

  /// Declares the entries of a group subsection (the current one).
  void
  declare_rod_group(dealii::ParameterHandler &prm);

  /// Reads the group subsection @p name (current), refusing a zero
  /// director, naming the entry.
  RodGroupSettings
  parse_rod_group(const dealii::ParameterHandler &prm, const std::string &name);

  /**
   * The settings of every rod, rod r in the groups @p rod_groups[r] (and
   * in "all"). Throws std::invalid_argument naming the subsection: a group
   * no rod belongs to (with the nearest names there are), and two groups
   * that give one rod two materials, two directors or two segment counts,
   * naming the rod with @p describe_rod. Activation items of several
   * groups of one rod add.
   */
  std::vector<RodSettings>
  resolve_rod_groups(
    const std::vector<std::vector<std::string>>    &rod_groups,
    const std::vector<RodGroupSettings>            &settings,
    const std::function<std::string(unsigned int)> &describe_rod);
} // namespace rodnet

#endif
