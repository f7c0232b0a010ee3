#ifndef RODNET_IO_GMSH_RODS_H
#define RODNET_IO_GMSH_RODS_H

#include <elements/quaternion.h>
#include <io/read_notes.h>

#include <string>
#include <vector>

namespace rodnet
{
  /// The vertex chain of one rod read from a mesh.
  struct RodChain
  {
    unsigned int         tag;    ///< Gmsh physical tag
    std::vector<Vector3> points; ///< in order along the rod
    bool                 closed = false;
  };

  /**
   * Reads a Gmsh line mesh (.msh, ASCII formats 2.2 and 4.1, through
   * read_gmsh_line_mesh()) and returns one rod per physical tag (lines
   * without a physical group: tag 0): the tag's segments must form a single
   * chain, open or closed; an open rod starts at the end where its line
   * elements begin (their node order). Throws std::invalid_argument naming
   * the file and tag where they do not (branches belong to rod networks
   * with junctions), or naming the file and line where the file cannot be
   * read (see read_gmsh_line_mesh()). Coincident nodes are merged first
   * (read_gmsh_line_mesh()). Where @p notes is given, it receives the line
   * naming the merged nodes (info) and the warning about open rods of two
   * line elements (one_hinge_warning()).
   */
  std::vector<RodChain>
  read_gmsh_rods(const std::string &path, ReadNotes *notes = nullptr);
} // namespace rodnet

#endif
