#include <deal.II/base/utilities.h>

#include <io/scene_entries.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace scene_entries
  {
    const dealii::Patterns::List &
    vector_pattern()
    {
      static const dealii::Patterns::List pattern(dealii::Patterns::Double(),
                                                  3,
                                                  3,
                                                  ",");
      return pattern;
    }

    Vector3
    get_vector(const dealii::ParameterHandler &prm, const std::string &entry)
    {
      const std::vector<double> v = dealii::Utilities::string_to_double(
        dealii::Utilities::split_string_list(prm.get(entry), ','));
      return Vector3(v[0], v[1], v[2]);
    }

    std::string
    join(const std::vector<std::string> &names, const std::string &separator)
    {
      std::string out;
      for (const std::string &n : names)
        out += (out.empty() ? "" : separator) + n;
      return out;
    }

    std::string
    number(const double value)
    {
      std::ostringstream s;
      s << value;
      return s.str();
    }

    Vector3
    get_direction(const dealii::ParameterHandler &prm, const std::string &name)
    {
      const Vector3 v = get_vector(prm, name);
      if (!(v.norm() > 0))
        throw std::invalid_argument(
          "entry \"Geometry/" + name + "\": \"" + prm.get(name) +
          "\" has no direction; give a non-zero vector, e.g. 0, 0, 1");
      return v;
    }

    std::pair<Vector3, Vector3>
    get_plane_axes(const dealii::ParameterHandler &prm)
    {
      const Vector3 e1     = get_direction(prm, "Plane axis 1").normalized();
      const Vector3 e2     = get_direction(prm, "Plane axis 2").normalized();
      const double  cosine = e1.dot(e2);
      if (std::abs(cosine) > 1e-6)
        throw std::invalid_argument(
          "entry \"Geometry/Plane axis 2\": \"" + prm.get("Plane axis 2") +
          "\" makes " +
          number(std::acos(std::clamp(cosine, -1., 1.)) * 180 / M_PI) +
          " deg with \"Plane axis 1\" = \"" + prm.get("Plane axis 1") +
          "\"; the axes of the circle's plane must be orthogonal, e.g. 1, 0, "
          "0 and 0, 1, 0");
      return {e1, e2};
    }

    std::string
    get_file(const dealii::ParameterHandler &prm,
             const std::string              &entry,
             const std::string              &scene_directory)
    {
      const std::string file = prm.get(entry);
      if (file.empty())
        throw std::invalid_argument("entry \"Geometry/" + entry +
                                    "\" is empty but the generator needs it");
      const std::string path =
        file[0] == '/' ? file : scene_directory + "/" + file;
      if (std::filesystem::is_directory(path))
        throw std::invalid_argument("entry \"Geometry/" + entry + "\": \"" +
                                    path + "\" is a directory, not a file");
      return path;
    }

    void
    declare_mesh_file(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Mesh file",
                        "",
                        dealii::Patterns::Anything(),
                        "Gmsh: path of the .msh line mesh, relative to the "
                        "scene file. [-]");
    }
  } // namespace scene_entries
} // namespace rodnet
