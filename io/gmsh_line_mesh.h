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
    /// The nodes read_gmsh_line_mesh() merged: the tags of each set of
    /// coincident nodes, the one kept (the lowest) first.
    std::vector<std::vector<long>> merged_nodes;
    /// The distance within which nodes were merged.
    double merge_tolerance = 0;
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
   *
   * Coincident nodes are merged, as Gmsh's "Coherence Mesh" merges them:
   * nodes of the elements closer than coincident_node_tolerance times the
   * diagonal of the mesh's bounding box become the one of lowest tag, which
   * takes the others' elements and physical points (merged_nodes lists
   * them). A mesh written without that step (two node tags at one point
   * where the drawing shows a joint) would otherwise be rods that only
   * touch. A line element whose two nodes coincide is refused, naming them.
   */
  GmshLineMesh
  read_gmsh_line_mesh(const std::string &path);

  /**
   * Merges the coincident nodes of @p mesh as read_gmsh_line_mesh()
   * documents; @p path names the file in the message about a line element
   * between two coincident nodes.
   */
  void
  merge_coincident_nodes(GmshLineMesh &mesh, const std::string &path);

  /**
   * The line that tells which nodes of @p mesh (read from @p path) were
   * merged, "mesh "...": merged coincident nodes (within ... m): node 26
   * into node 13; ...", the first five sets and the number of others;
   * empty if none were.
   */
  std::string
  merged_nodes_note(const GmshLineMesh &mesh, const std::string &path);

  /**
   * The warning about the rods of mesh @p path that are chains of two line
   * elements (@p chains: a description of each, e.g. "beam 0 (its hinge at
   * node 2)"): the mesh decides their segments, and their one hinge gives a
   * first-order answer. The first five are named, with the number of
   * others and @p advice (what to do) at the end; empty if there are none.
   */
  std::string
  one_hinge_warning(const std::string              &path,
                    const std::vector<std::string> &chains,
                    const std::string              &advice);
} // namespace rodnet

#endif
