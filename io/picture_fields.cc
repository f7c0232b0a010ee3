#include <base/nearest_names.h>
#include <io/picture_fields.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace rodnet
{
  PictureGroups
  picture_groups(const std::vector<std::string>              &listed,
                 const std::vector<std::vector<std::string>> &rod_groups)
  {
    const std::string entry = "entry \"Output/Picture groups\": ";
    // "all" holds every rod (io/rod_groups.h).
    std::vector<std::string> known{"all"};
    for (const std::vector<std::string> &groups : rod_groups)
      for (const std::string &group : groups)
        if (std::find(known.begin(), known.end(), group) == known.end())
          known.push_back(group);
    if (listed.empty())
      throw std::invalid_argument(
        entry +
        "Picture field = group colours the rods by the groups this "
        "entry lists; the groups of this geometry are " +
        quoted_list(known));
    if (listed.size() > max_picture_groups)
      throw std::invalid_argument(
        entry + std::to_string(listed.size()) + " groups, more than the " +
        std::to_string(max_picture_groups) + " colours a picture tells apart");
    for (std::size_t g = 0; g < listed.size(); ++g)
      if (std::find(known.begin(), known.end(), listed[g]) == known.end())
        throw std::invalid_argument(
          entry + "no rod is in group \"" + listed[g] +
          "\"; the groups of this geometry are " +
          quoted_list(nearest_names(known, listed[g], 8)));
      else if (std::count(listed.begin(), listed.end(), listed[g]) > 1)
        throw std::invalid_argument(entry + "the group \"" + listed[g] +
                                    "\" is listed twice");
    PictureGroups picture{listed, std::vector<int>(rod_groups.size(), -1)};
    for (std::size_t r = 0; r < rod_groups.size(); ++r)
      for (std::size_t g = 0; g < listed.size() && picture.rod_group[r] < 0;
           ++g)
        if (listed[g] == "all" ||
            std::find(rod_groups[r].begin(), rod_groups[r].end(), listed[g]) !=
              rod_groups[r].end())
          picture.rod_group[r] = g;
    return picture;
  }


  std::vector<OutputFields::Field>
  network_fields(const RodNetwork &network, const PictureGroups &groups)
  {
    const unsigned int  n_segments = network.n_segments();
    OutputFields::Field rod{"rod", 1, std::vector<double>(n_segments), "-"};
    OutputFields::Field group{"group",
                              1,
                              std::vector<double>(n_segments, NAN),
                              "-"};
    if (!groups.names.empty() &&
        groups.rod_group.size() != network.rods().size())
      throw std::invalid_argument(
        "network_fields: groups of " + std::to_string(groups.rod_group.size()) +
        " rods for a network of " + std::to_string(network.rods().size()));
    for (unsigned int r = 0; r < network.rods().size(); ++r)
      for (const unsigned int cell : network.rods()[r].segments)
        {
          rod.values[cell] = r;
          if (!groups.names.empty() && groups.rod_group[r] >= 0)
            group.values[cell] = groups.rod_group[r];
        }
    if (groups.names.empty())
      return {rod};
    return {rod, group};
  }


  std::string
  picture_label(const std::string &name,
                const std::string &unit,
                const unsigned int components)
  {
    // Symbols, and whether the components are global (x, y, z).
    static const std::vector<std::tuple<std::string, std::string, bool>>
                      symbols{{"displacement", "u", true},
              {"curvature", "kappa", false},
              {"d1", "d1", true},
              {"d2", "d2", true}};
    const std::size_t bracket = name.find('[');
    std::string       base    = name.substr(0, bracket);
    bool              global  = true;
    for (const auto &[field, symbol, axes] : symbols)
      if (base == field)
        {
          base   = symbol;
          global = axes;
        }
    std::replace(base.begin(), base.end(), '_', ' ');
    std::string label = base;
    if (bracket != std::string::npos)
      {
        const char k = name[bracket + 1];
        label += std::string("_") + (global ? char('x' + (k - '1')) : k);
      }
    else if (components == 3)
      label = "|" + base + "|";
    return unit.empty() || unit == "-" ? label : label + " (" + unit + ")";
  }


  PictureFieldCatalogue::PictureFieldCatalogue(
    const RodNetwork           &network,
    const std::vector<Vector3> &deformed,
    const OutputFields         &fields,
    const PictureGroups        &groups)
      : displacement{"displacement", 3, {}, "m"}
      , network_field_list(network_fields(network, groups))
      , group_names(groups.names)
  {
    if (deformed.size() != network.n_vertices())
      throw std::invalid_argument("PictureFieldCatalogue: positions of " +
                                  std::to_string(deformed.size()) +
                                  " vertices for a network of " +
                                  std::to_string(network.n_vertices()));
    for (unsigned int v = 0; v < deformed.size(); ++v)
      {
        const Vector3 u = deformed[v] - network.vertex(v);
        displacement.values.insert(displacement.values.end(),
                                   u.data(),
                                   u.data() + 3);
      }
    sources.push_back({&displacement, false});
    for (const OutputFields::Field &field : network_field_list)
      sources.push_back({&field, true});
    for (const OutputFields::Field &field : fields.vertex_fields)
      sources.push_back({&field, false});
    for (const OutputFields::Field &field : fields.segment_fields)
      sources.push_back({&field, true});
    // A field that does not fit the network would be read past its end.
    const unsigned int n_segments = network.n_segments();
    for (const Source &source : sources)
      {
        const OutputFields::Field &field = *source.field;
        const unsigned int         n =
          source.per_segment ? n_segments : deformed.size();
        if (!(field.components == 1 || field.components == 3) ||
            field.values.size() != std::size_t(field.components) * n)
          throw std::invalid_argument(
            "PictureFieldCatalogue: the field \"" + field.name + "\" has " +
            std::to_string(field.values.size()) + " values for " +
            std::to_string(n) +
            (source.per_segment ? " segments" : " vertices"));
      }
  }


  std::vector<std::string>
  PictureFieldCatalogue::names() const
  {
    std::vector<std::string> list;
    for (const Source &source : sources)
      {
        list.push_back(source.field->name);
        for (unsigned int k = 1; source.field->components == 3 && k <= 3; ++k)
          list.push_back(source.field->name + "[" + std::to_string(k) + "]");
      }
    return list;
  }


  PictureField
  PictureFieldCatalogue::select(const std::string &name) const
  {
    const std::vector<std::string> known = names();
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw std::invalid_argument("no field \"" + name +
                                  "\" to colour the picture by (nearest: " +
                                  quoted_list(nearest_names(known, name, 3)) +
                                  "); the fields are " + quoted_list(known));
    // "name[k]": component k of a vector field; "name": its length.
    const std::size_t bracket = name.find('[');
    const Source     &source =
      *std::find_if(sources.begin(), sources.end(), [&](const Source &s) {
        return s.field->name == name.substr(0, bracket);
      });
    const OutputFields::Field &field = *source.field;
    PictureField               picked{name,
                        field.unit,
                        picture_label(name, field.unit, field.components),
                        source.per_segment,
                        {},
                        field.interior_vertices_only,
                        {}};
    if (name == "group")
      picked.categories = group_names;
    for (std::size_t i = 0; i < field.values.size(); i += field.components)
      {
        const double *value = &field.values[i];
        if (field.components == 1)
          picked.values.push_back(value[0]);
        else if (bracket == std::string::npos)
          picked.values.push_back(std::hypot(value[0], value[1], value[2]));
        else
          picked.values.push_back(value[name[bracket + 1] - '1']);
      }
    return picked;
  }
} // namespace rodnet
