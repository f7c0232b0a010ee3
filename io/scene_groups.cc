#include <io/rod_groups.h>
#include <io/scene.h>

#include <algorithm>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// "entry "Group <group>/<entry>": ".
    std::string
    group_entry(const std::string &group, const std::string &entry)
    {
      return "entry \"" + group_subsection_prefix + group + "/" + entry +
             "\": ";
    }
  } // namespace

  void
  Scene::parse_rod_groups(dealii::ParameterHandler &prm,
                          const EntryNode          &entries)
  {
    std::vector<RodGroupSettings> settings;
    for (const EntryNode &section : entries.children)
      if (const auto name =
            name_in_title(section.name, group_subsection_prefix))
        {
          prm.enter_subsection(section.name);
          settings.push_back(parse_rod_group(prm, *name));
          prm.leave_subsection();
        }
    const std::vector<std::vector<std::string>> groups = groups_of_rods();
    const auto describe = [this](const unsigned int r) { return rod_name(r); };
    const std::vector<RodSettings> rods =
      resolve_rod_groups(groups, settings, describe);

    rod_material.clear();
    rod_activation.clear();
    for (unsigned int r = 0; r < rods.size(); ++r)
      {
        rod_material.push_back(material_index(rods[r]));
        rod_activation.push_back(rods[r].activation);
        if (rods[r].director)
          orient_beam(r, *rods[r].director, rods[r].director_group, describe);
        if (rods[r].segments > 0)
          split_beam(r, rods[r].segments, rods[r].segments_group, describe);
      }
    for (unsigned int m = 1; m < scene_materials.size(); ++m)
      if (std::find(rod_material.begin(), rod_material.end(), m) ==
          rod_material.end())
        throw std::invalid_argument(
          "subsection \"" + scene_materials[m].subsection +
          "\": no rod takes this material; give it to a group (\"" +
          group_subsection_prefix + "<name>/Material = " +
          *name_in_title(scene_materials[m].subsection,
                         material_subsection_prefix) +
          "\") or remove it");
  }

  std::vector<std::vector<std::string>>
  Scene::groups_of_rods() const
  {
    // build_rod_network() makes beam b rod b.
    std::vector<std::vector<std::string>> groups(graph ? graph->beams.size() :
                                                         rod_points.size());
    for (std::size_t b = 0; graph && b < graph->beams.size(); ++b)
      groups[b] = graph->beams[b].groups;
    return groups;
  }

  std::string
  Scene::rod_name(const unsigned int r) const
  {
    if (!graph)
      return "rod " + std::to_string(r);
    const RodGraph::Beam &beam = graph->beams[r];
    return "beam " + std::to_string(r) + " (" + graph->nodes[beam.from].name +
           " to " + graph->nodes[beam.to].name + ")";
  }

  void
  Scene::orient_beam(const unsigned int                              b,
                     const Vector3                                  &d1,
                     const std::string                              &group,
                     const std::function<std::string(unsigned int)> &describe)
  {
    if (!graph)
      throw std::invalid_argument(
        group_entry(group, "Director d1") +
        "these rods are not a network's beams; Geometry/Director d1 orients "
        "them");
    RodGraph::Beam &beam = graph->beams[b];
    const Vector3   tangent =
      graph->nodes[beam.to].position - graph->nodes[beam.from].position;
    // Where d1 is (nearly) parallel to the beam no frame is orthogonal to
    // both; build_rod_network() would refuse it, without the entry.
    if (d1.cross(tangent).norm() <= 1e-6 * d1.norm() * tangent.norm())
      throw std::invalid_argument(group_entry(group, "Director d1") +
                                  "d1 is parallel to " + describe(b) +
                                  "; give a direction across the beam");
    beam.director_hint = d1;
  }

  void
  Scene::split_beam(const unsigned int                              b,
                    const unsigned int                              segments,
                    const std::string                              &group,
                    const std::function<std::string(unsigned int)> &describe)
  {
    if (!graph)
      throw std::invalid_argument(
        group_entry(group, "Segments") +
        "these rods are not a network's beams; Geometry/Segments splits "
        "them");
    RodGraph::Beam &beam = graph->beams[b];
    if (!beam.interior.empty())
      throw std::invalid_argument(
        group_entry(group, "Segments") + describe(b) +
        " is a chain of the mesh, which keeps the segments the mesh gives "
        "it; refine the mesh instead, or leave the entry at 0");
    beam.segments = segments;
  }
} // namespace rodnet
