#ifndef RODNET_IO_GMSH_LINE_MESH_H
#define RODNET_IO_GMSH_LINE_MESH_H

#include <elements/quaternion.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /// A line element (Gmsh type 1) and its physical group (0: none).
  struct GmshLineElement
  {
    long tag;
    int  physical;
    long nodes[2];
  };

  /// What the rod and network readers need of a .msh file.
  struct GmshLineMesh
  {
    std::map<long, Vector3>      nodes;
    std::vector<GmshLineElement> lines;
    /// Physical point groups (tags) on each node.
    std::map<long, std::set<int>> node_points;
    /// Names of the physical groups, by (dimension, tag).
    std::map<std::pair<int, int>, std::string> physical_names;
  };

  /**
   * Reads the nodes, line and point elements and physical names of an ASCII
   * Gmsh mesh (.msh format 2.2 or 4.1), with the checks that
   * read_gmsh_network() documents for the file's syntax: it throws
   * std::invalid_argument naming the file and line for an unreadable or
   * binary file, another version, a malformed or truncated section, and
   * element types other than lines and points, for a line element whose
   * nodes are not defined or are one node twice, and for a mesh without
   * line elements.
   */
  GmshLineMesh
  read_gmsh_line_mesh(const std::string &path);
} // namespace rodnet

#endif
