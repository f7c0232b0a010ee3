// Pieces of scene text that validation tests assemble their scenes from,
// and the probe they read back.
#ifndef RODNET_TESTS_COMMON_SCENE_TEXT_H
#define RODNET_TESTS_COMMON_SCENE_TEXT_H

#include "run_scene_text.h"
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rodnet::testing
{
  /// "x, y, z" of @p v to full precision.
  inline std::string
  vector_text(const Vector3 &v)
  {
    std::ostringstream text;
    text.precision(17);
    text << v[0] << ", " << v[1] << ", " << v[2];
    return text.str();
  }

  /// Subsection Material: linear elastic with the rigidities given.
  inline std::string
  direct_material(const double EA,
                  const double EI1,
                  const double EI2,
                  const double GJ)
  {
    std::ostringstream text;
    text.precision(17);
    text << "subsection Material\n"
            "  subsection linear elastic\n"
            "    set Stiffness input = direct\n"
         << "    set EA = " << EA << "\n    set EI1 = " << EI1
         << "\n    set EI2 = " << EI2 << "\n    set GJ = " << GJ
         << "\n  end\nend\n";
    return text.str();
  }

  /// The same with the axial rigidity @p EA as scene text (bad-input tests
  /// pass values such as "nan") and unit bending and torsional rigidities.
  inline std::string
  direct_material(const std::string &EA = "1e4")
  {
    return "subsection Material\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = direct\n"
           "    set EA = " +
           EA +
           "\n"
           "    set EI1 = 1\n"
           "    set EI2 = 1\n"
           "    set GJ = 1\n"
           "  end\n"
           "end\n";
  }

  /// The subsection Output of a scene that writes probes.csv alone, with
  /// the probes @p probes.
  inline std::string
  probes_only(const std::string &probes)
  {
    return "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = " +
           probes +
           "\n"
           "end\n";
  }

  /// Writes the open chain @p points as an ASCII Gmsh 2.2 line mesh of one
  /// physical line to @p path; returns @p path.
  inline std::string
  write_gmsh_chain(const std::string &path, const std::vector<Vector3> &points)
  {
    std::ofstream mesh(path);
    mesh.precision(17);
    mesh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
         << points.size() << "\n";
    for (std::size_t i = 0; i < points.size(); ++i)
      mesh << i + 1 << " " << points[i][0] << " " << points[i][1] << " "
           << points[i][2] << "\n";
    mesh << "$EndNodes\n$Elements\n" << points.size() - 1 << "\n";
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      mesh << i + 1 << " 1 2 1 1 " << i + 1 << " " << i + 2 << "\n";
    mesh << "$EndElements\n";
    return path;
  }

  /// Subsection Output: no VTU, no plot, the probes "x", "y", "z" of the
  /// position of the vertex "end" (read by end_position()).
  inline std::string
  end_position_output()
  {
    return "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = x: position end x; y: position end y; z: position "
           "end z\n"
           "end\n";
  }

  /**
   * A cantilever: the Geometry entries @p geometry with d1 = e_z, the
   * material text @p material, the start clamped, the force @p tip_force at
   * the vertex "end" in one load step, end_position_output().
   */
  inline std::string
  cantilever_scene(const std::string &geometry,
                   const std::string &material,
                   const Vector3     &tip_force)
  {
    return "subsection Geometry\n" + geometry +
           "  set Director d1 = 0, 0, 1\n"
           "end\n" +
           material +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Loads\n"
           "  set Steps = 1\n"
           "  set Point forces = end: " +
           vector_text(tip_force) + "\nend\n" + end_position_output();
  }

  /// The position of the vertex "end" in row @p row of a run of a scene
  /// with end_position_output().
  inline Vector3
  end_position(const RunSummary &run, const std::size_t row)
  {
    const std::vector<double> &values = run.rows.at(row);
    return Vector3(values[probe_column(run, "x")],
                   values[probe_column(run, "y")],
                   values[probe_column(run, "z")]);
  }
} // namespace rodnet::testing

#endif
