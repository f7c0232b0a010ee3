#ifndef RODNET_IO_PICTURE_FIELDS_H
#define RODNET_IO_PICTURE_FIELDS_H

#include <core/output_fields.h>
#include <core/rod_network.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * The fields of a network that do not depend on a state, per segment:
   * "rod" (the index of the segment's rod). A picture (io/network_picture.h)
   * offers them beside those of the model (Model::output_fields()); a
   * field of the network added here, or of a model added to its
   * output_fields(), can colour a picture without a change to the picture.
   */
  std::vector<OutputFields::Field>
  network_fields(const RodNetwork &network);

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
   * @p network), network_fields(), and the vertex and segment fields of
   * @p fields. A field of three components gives its length under its own
   * name and component k (1 to 3) as "name[k]". @p fields must outlive the
   * catalogue, which reads them where they are.
   */
  class PictureFieldCatalogue
  {
  public:
    /// Throws std::invalid_argument if a field does not fit @p network.
    PictureFieldCatalogue(const RodNetwork           &network,
                          const std::vector<Vector3> &deformed,
                          const OutputFields         &fields);

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
  };
} // namespace rodnet

#endif
