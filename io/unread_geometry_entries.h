#ifndef RODNET_IO_UNREAD_GEOMETRY_ENTRIES_H
#define RODNET_IO_UNREAD_GEOMETRY_ENTRIES_H

#include <io/entry_tree.h>

#include <string>

namespace rodnet
{
  /**
   * Refuses an entry of subsection Geometry that the generator @p generator
   * does not read yet the scene sets off its default (an entry that is
   * not used must not look as if it were): the shared entries it names in
   * GeometryGenerator::unread_shared_entries(), and the entries that only
   * other generators declare. @p geometry is subsection Geometry of the
   * scene's entry_tree(). Throws std::invalid_argument naming the entry,
   * the generator and why.
   */
  void
  refuse_unread_geometry_entries(const EntryNode   &geometry,
                                 const std::string &generator);
} // namespace rodnet

#endif
