#ifndef RODNET_IO_ENTRY_NUMBERS_H
#define RODNET_IO_ENTRY_NUMBERS_H

#include <io/entry_tree.h>

#include <set>
#include <string>

namespace rodnet
{
  /**
   * Refuses non-finite and absurd numbers wherever they are written: every
   * number in the value of every entry below @p tree (numbers, vectors,
   * lists, loads, points, expressions) must be finite and at most
   * max_input_magnitude in magnitude, and no value may contain the words
   * "nan" or "inf". Throws std::invalid_argument naming the first entry
   * ("entry \"Loads/Point forces\": ...") where that fails. Entries in
   * @p exempt (paths such as "Geometry/Mesh file") hold file names, whose
   * digits are no numbers, and are skipped.
   */
  void
  check_entry_numbers(const EntryNode             &tree,
                      const std::set<std::string> &exempt);
} // namespace rodnet

#endif
