#ifndef RODNET_IO_SCENE_ENTRIES_H
#define RODNET_IO_SCENE_ENTRIES_H

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <elements/quaternion.h>

#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * Readers of the entry kinds that several owners of scene entries share
   * (generators, loads, materials): vectors, directions, the axes of a
   * plane and file names. Each reads an entry of the current subsection of a
   * ParameterHandler and throws std::invalid_argument naming the entry
   * ("Geometry/...") where its value is inadmissible.
   */
  namespace scene_entries
  {
    /// The pattern of a vector entry "x, y, z".
    const dealii::Patterns::List &
    vector_pattern();

    /// The value of the vector entry @p entry (declared with
    /// vector_pattern()).
    Vector3
    get_vector(const dealii::ParameterHandler &prm, const std::string &entry);

    /// The vector entry @p name of subsection Geometry, which gives a
    /// direction: refused if zero.
    Vector3
    get_direction(const dealii::ParameterHandler &prm, const std::string &name);

    /// "Plane axis 1" and "Plane axis 2" of subsection Geometry as unit
    /// vectors; refused unless they are orthogonal (to 1e-6 in the cosine of
    /// their angle).
    std::pair<Vector3, Vector3>
    get_plane_axes(const dealii::ParameterHandler &prm);

    /// The file that entry @p entry of subsection Geometry names, relative
    /// to @p scene_directory unless absolute; refused if empty or a
    /// directory.
    std::string
    get_file(const dealii::ParameterHandler &prm,
             const std::string              &entry,
             const std::string              &scene_directory);

    /// Declares "Mesh file", which the Gmsh generators of rods and of
    /// networks read.
    void
    declare_mesh_file(dealii::ParameterHandler &prm);

    /// @p names joined by @p separator ("a|b|c" for a Selection).
    std::string
    join(const std::vector<std::string> &names, const std::string &separator);

    /// Where the time-stepping entries live, for messages.
    inline const std::string time_stepping_section = "Solver/Time stepping";

    /// "<value>" of a double for messages.
    std::string
    number(double value);
  } // namespace scene_entries
} // namespace rodnet

#endif
