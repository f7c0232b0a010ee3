#ifndef RODNET_IO_NETWORK_FILE_H
#define RODNET_IO_NETWORK_FILE_H

#include <geometry/rod_graph.h>

#include <string>

namespace rodnet
{
  /**
   * Reads a beam network from a plain text node/edge list:
   * @code
   * # a comment runs from '#' to the end of the line
   * node <name> <x> <y> <z> [<kind>]
   * beam <from> <to> [group <name>]... [d1 <x> <y> <z>]
   * @endcode
   * One statement per line, tokens separated by blanks. Node names are
   * single tokens; beams refer to nodes declared anywhere in the file. The
   * optional kind is one of welded, pinned, clamped, welded-and-pinned
   * (hyphens instead of the blanks of to_string(JunctionKind)); without it a
   * node is welded where beams meet and a free end where one beam ends.
   * A beam's options may come in any order: the groups it belongs to
   * (RodGraph::Beam::groups; "group" repeated for several, a name is one
   * token, "1" as good as "struts") and the director hint d1 (at most once;
   * default: see RodGraph::Beam).
   * The n-th beam line becomes beam n - 1, the n-th node line node n - 1.
   * Beams are straight; build_rod_network() splits them.
   *
   * Throws std::invalid_argument with "file:line:" and the offending token
   * for an unreadable file, an unknown keyword or kind, a bad number, a
   * missing or extra field, a duplicate node name or an unknown node in a
   * beam. The graph's geometry (zero-length beams, supports) is checked by
   * build_rod_network(), whose messages name the nodes.
   */
  RodGraph
  read_network_file(const std::string &path);
} // namespace rodnet

#endif
