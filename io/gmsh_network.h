#ifndef RODNET_IO_GMSH_NETWORK_H
#define RODNET_IO_GMSH_NETWORK_H

#include <geometry/rod_graph.h>
#include <io/read_notes.h>

#include <string>

namespace rodnet
{
  /**
   * Reads a beam network from an ASCII Gmsh line mesh (.msh format 2.2 or
   * 4.1) with a parser of its own: deal.II's GridIn refuses the vertices
   * where more than two line elements meet, which are exactly the junctions.
   *
   * Only the sections $MeshFormat, $PhysicalNames, $Entities (4.1), $Nodes
   * and $Elements are read; element types other than lines (type 1) and
   * points (type 15) are an error, so that second-order lines or surfaces
   * are not silently dropped.
   *
   * - Branch nodes are the mesh nodes where the number of line elements is
   *   not 2, where the two line elements belong to different physical
   *   groups, or that carry a physical point. They are the graph's nodes,
   *   in increasing node tag order.
   * - A beam is a maximal chain of line elements between two branch nodes;
   *   its other mesh nodes become RodGraph::Beam::interior (a chain of one
   *   element has none: build_rod_network() splits it). Beams are
   *   ordered by the lowest element tag of each chain and run in the node
   *   order of that element (the direction of all of them when the chain is
   *   oriented consistently). A corner between two lines of the same
   *   physical group that no third line touches stays inside one (bent)
   *   beam: mark it with a physical point to make it a junction.
   * - The physical line groups become material groups 0, 1, ... in
   *   increasing physical tag order (lines without a physical group: tag 0).
   * - A physical point named as a junction kind ("clamped", "pinned",
   *   "welded", "welded and pinned") sets the kind of its nodes; any other
   *   name names its node (it must hold a single node), so that scenes can
   *   refer to it. Other branch nodes are called "node<tag>".
   *
   * - Coincident nodes are merged first (read_gmsh_line_mesh()): a joint
   *   written as two node tags at one point is one node.
   *
   * Where @p notes is given, it receives the line naming the merged nodes
   * (info) and the warning about beams that are chains of two line
   * elements (one_hinge_warning()).
   *
   * Throws std::invalid_argument naming the file and the line, node or
   * element for an unreadable or binary file, another format version, a
   * malformed line, an unknown node, another element type, a line element
   * between two coincident nodes, and for a chain of elements that closes
   * on itself ("closed beam loops are not supported in networks").
   */
  RodGraph
  read_gmsh_network(const std::string &path, ReadNotes *notes = nullptr);
} // namespace rodnet

#endif
