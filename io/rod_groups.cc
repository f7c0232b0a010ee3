#include <deal.II/base/utilities.h>

#include <base/nearest_names.h>
#include <io/rod_groups.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The group that holds every rod.
    const std::string every_rod = "all";

    /// Gives @p field the @p value of group @p group, refusing a second
    /// group (@p given_by) that already gave it one for @p rod.
    template <class T>
    void
    give(T                 &field,
         std::string       &given_by,
         const T           &value,
         const std::string &group,
         const std::string &what,
         const std::string &rod)
    {
      if (!given_by.empty())
        throw std::invalid_argument(
          "subsections \"" + group_subsection_prefix + given_by + "\" and \"" +
          group_subsection_prefix + group + "\" both give " + rod + " " + what +
          "; a rod takes one: give it in one of the groups only");
      field    = value;
      given_by = group;
    }

    /// The vector "x, y, z" of @p text; none if it is not three numbers.
    std::optional<Vector3>
    three_numbers(const std::string &text)
    {
      const std::vector<std::string> items =
        dealii::Utilities::split_string_list(text, ',');
      if (items.size() != 3)
        return std::nullopt;
      Vector3 v;
      for (unsigned int c = 0; c < 3; ++c)
        {
          char       *end   = nullptr;
          const char *start = items[c].c_str();
          v[c]              = std::strtod(start, &end);
          if (end == start || *end != '\0')
            return std::nullopt;
        }
      return v;
    }

    /// Refuses a group of @p settings that no rod of @p rod_groups is in.
    void
    require_known_groups(
      const std::vector<std::vector<std::string>> &rod_groups,
      const std::vector<RodGroupSettings>         &settings)
    {
      std::set<std::string> known{every_rod};
      for (const std::vector<std::string> &groups : rod_groups)
        known.insert(groups.begin(), groups.end());
      for (const RodGroupSettings &group : settings)
        if (known.count(group.name) == 0)
          throw std::invalid_argument(
            "subsection \"" + group_subsection_prefix + group.name +
            "\": no rod is in group \"" + group.name +
            "\"; the groups of this geometry are " +
            quoted_list(nearest_names(std::vector<std::string>(known.begin(),
                                                               known.end()),
                                      group.name,
                                      8)));
    }
  } // namespace

  std::optional<std::string>
  name_in_title(const std::string &title, const std::string &prefix)
  {
    if (title.size() <= prefix.size() ||
        title.compare(0, prefix.size(), prefix) != 0)
      return std::nullopt;
    return title.substr(prefix.size());
  }

  void
  declare_rod_group(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Material",
                      "",
                      dealii::Patterns::Anything(),
                      "The material of the group's rods: the name of a "
                      "subsection \"Material <name>\"; empty: subsection "
                      "Material. [-]");
    prm.declare_entry("Director d1",
                      "",
                      dealii::Patterns::Anything(),
                      "Orientation of d1 of the group's beams, made "
                      "orthogonal to each beam (EI1 acts about d1), e.g. 0, "
                      "0, 1; empty: the beam's own (a network file's d1, "
                      "otherwise e_z). Networks only. [-]");
    prm.declare_entry("Segments",
                      "0",
                      dealii::Patterns::Integer(0),
                      "Segments of each straight beam of the group; 0: "
                      "Geometry/Segments. Networks only; a mesh's chain "
                      "keeps the segments the mesh gives it. [-]");
    prm.declare_entry("Natural curvature",
                      "",
                      dealii::Patterns::Anything(),
                      "Activation field: natural curvatures about d1 and d2 "
                      "of the group's rods, ';'-separated items \"k1, k2 "
                      "[on <region>] [fixed]\", each value a number or an "
                      "expression of the arc length s and the rod's length "
                      "L; region: all (the default), \"<s0> to <s1>\", "
                      "\"near ends <d>\"; ramped with the load factor "
                      "unless \"fixed\"; fields add (doc/morphing.md). "
                      "[1/m]");
    prm.declare_entry("Natural twist",
                      "",
                      dealii::Patterns::Anything(),
                      "Activation field: natural twist rate, items as for "
                      "Natural curvature with one value. [rad/m]");
    prm.declare_entry("Axial eigenstrain",
                      "",
                      dealii::Patterns::Anything(),
                      "Activation field: axial eigenstrain, items as for "
                      "Natural curvature with one value. [-]");
  }

  RodGroupSettings
  parse_rod_group(const dealii::ParameterHandler &prm, const std::string &name)
  {
    RodGroupSettings group;
    group.name     = name;
    group.material = prm.get("Material");
    group.segments = prm.get_integer("Segments");
    for (const ActivationEntry &entry : activation_entries())
      for (ActivationItem &item :
           parse_activation_items(name, entry, prm.get(entry.name)))
        group.activation.push_back(std::move(item));
    if (!prm.get("Director d1").empty())
      {
        const std::string entry = "entry \"" + group_subsection_prefix + name +
                                  "/Director d1\": \"" +
                                  prm.get("Director d1") + "\" ";
        const std::optional<Vector3> d1 = three_numbers(prm.get("Director d1"));
        if (!d1)
          throw std::invalid_argument(
            entry + "is not a vector of three numbers, e.g. 0, 0, 1");
        if (!(d1->norm() > 0) || !d1->allFinite())
          throw std::invalid_argument(
            entry + "has no direction; give a non-zero vector, e.g. 0, 0, 1");
        group.director = *d1;
      }
    return group;
  }

  std::vector<RodSettings>
  resolve_rod_groups(
    const std::vector<std::vector<std::string>>    &rod_groups,
    const std::vector<RodGroupSettings>            &settings,
    const std::function<std::string(unsigned int)> &describe_rod)
  {
    require_known_groups(rod_groups, settings);
    std::vector<RodSettings> rods(rod_groups.size());
    for (unsigned int r = 0; r < rods.size(); ++r)
      for (const RodGroupSettings &group : settings)
        {
          const std::vector<std::string> &in = rod_groups[r];
          if (group.name != every_rod &&
              std::find(in.begin(), in.end(), group.name) == in.end())
            continue;
          RodSettings &rod = rods[r];
          rod.activation.insert(rod.activation.end(),
                                group.activation.begin(),
                                group.activation.end());
          if (!group.material.empty())
            give(rod.material,
                 rod.material_group,
                 group.material,
                 group.name,
                 "a material",
                 describe_rod(r));
          if (group.director)
            give(rod.director,
                 rod.director_group,
                 group.director,
                 group.name,
                 "a director d1",
                 describe_rod(r));
          if (group.segments > 0)
            give(rod.segments,
                 rod.segments_group,
                 group.segments,
                 group.name,
                 "a number of segments",
                 describe_rod(r));
        }
    return rods;
  }
} // namespace rodnet
