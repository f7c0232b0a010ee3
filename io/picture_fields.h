#ifndef RODNET_IO_PICTURE_FIELDS_H
#define RODNET_IO_PICTURE_FIELDS_H

#include <core/output_fields.h>
#include <core/rod_network.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * The rod groups a picture coloured by "group" tells apart (entry
   * "Output/Picture groups"): their names, in the legend's order, and the
   * one each rod shows.
   */
  struct PictureGroups
  {
    std::vector<std::string> names;
    /// Per rod: the index in names of the first listed group the rod is
    /// in; -1 where it is in none (drawn in a neutral grey).
    std::vector<int> rod_group;
  };

  /**
   * The PictureGroups of the groups @p listed for rods in the groups
   * @p rod_groups (rod r in rod_groups[r] and in "all"): each rod shows the
   * first group of @p listed it is in, so that the list's order settles a
   * rod in several. Throws std::invalid_argument naming the entry
   * "Output/Picture groups" where @p listed is empty, names a group twice
   * or a group no rod is in (with the nearest names), or holds more groups
   * than the palette tells apart (max_picture_groups).
   */
  PictureGroups
  picture_groups(const std::vector<std::string>              &listed,
                 const std::vector<std::vector<std::string>> &rod_groups);

  /// The most groups a picture tells apart: the colours of its palette.
  constexpr unsigned int max_picture_groups = 7;

  /**
   * The fields of a network that do not depend on a state, per segment:
   * "rod" (the index of the segment's rod) and, where @p groups names any,
   * "group" (the index of the group the segment's rod shows, NaN for
   * none). A picture (io/network_picture.h) offers them beside those of
   * the model (Model::output_fields()); a field of the network added here,
   * or of a model added to its output_fields(), can colour a picture
   * without a change to the picture.
   */
  std::vector<OutputFields::Field>
  network_fields(const RodNetwork &network, const PictureGroups &groups = {});

  /// A scalar field that colours a picture: one value per segment (active
  /// cell) or per vertex of the network.
  struct PictureField
  {
    /// As named in a scene ("curvature", "curvature[1]", "rod").
    std::string name;
    std::string unit;
    /// As a colour bar names it, readable, with the unit: "|u| (m)",
    /// "u_z (m)", "kappa_1 (1/m)", "axial strain" (picture_label()).
    std::string         label;
    bool                per_segment = true;
    std::vector<double> values;
    /// OutputFields::Field::interior_vertices_only.
    bool interior_vertices_only = false;
    /// Where not empty, the field names categories: value k is
    /// categories[k], NaN none; drawn in distinct colours with a legend
    /// instead of a colour bar ("group").
    std::vector<std::string> categories;
  };

  /**
   * The colour bar's label of the field @p name ("displacement",
   * "curvature[1]", "axial_strain") of @p components components and unit
   * @p unit: its symbol where it has one (u, kappa), blanks for
   * underscores, a vector's length as |.| and its component k as _x, _y,
   * _z (global components: displacement, directors) or _k (the material
   * frame's: curvature), then the unit in parentheses unless it is "-" or
   * empty.
   */
  std::string
  picture_label(const std::string &name,
                const std::string &unit,
                unsigned int       components);

  /**
   * The fields a picture of a state can be coloured by: "displacement"
   * (per vertex, @p deformed minus the undeformed positions of
   * @p network), network_fields() (with "group" of @p groups), and the
   * vertex and segment fields of @p fields. A field of three components
   * gives its length under its own name and component k (1 to 3) as
   * "name[k]". @p fields must outlive the catalogue, which reads them where
   * they are.
   */
  class PictureFieldCatalogue
  {
  public:
    /// Throws std::invalid_argument if a field does not fit @p network.
    PictureFieldCatalogue(const RodNetwork           &network,
                          const std::vector<Vector3> &deformed,
                          const OutputFields         &fields,
                          const PictureGroups        &groups = {});

    /// Every name select() accepts, in the order of the fields.
    std::vector<std::string>
    names() const;

    /// The field @p name; throws std::invalid_argument if there is none.
    PictureField
    select(const std::string &name) const;

  private:
    struct Source
    {
      const OutputFields::Field *field;
      bool                       per_segment;
    };

    OutputFields::Field              displacement;
    std::vector<OutputFields::Field> network_field_list;
    std::vector<Source>              sources;
    /// The categories of the field "group".
    std::vector<std::string> group_names;
  };
} // namespace rodnet

#endif
