#ifndef RODNET_IO_SCENE_HELP_H
#define RODNET_IO_SCENE_HELP_H

#include <ostream>
#include <string>

namespace rodnet
{
  /**
   * Writes every scene entry once, compactly: per subsection (in
   * declaration order) each entry as "Name = default", what it takes (the
   * values of a selection, the range of a number, the length of a list)
   * and its help, wrapped to 79 columns. A subsection that repeats an
   * earlier sibling (the material of a group repeats "Material") lists
   * only what it adds. This is the scene part of `rodnet-run --help` and
   * of doc/scene_reference.txt.
   */
  void
  print_scene_entries(std::ostream &out);

  /**
   * What an entry of deal.II's machine-readable pattern @p pattern takes,
   * in words: "[Integer range 1...2147483647 (inclusive)]" is
   * "integer >= 1", "[Selection a|b ]" is "one of: a | b", a list of three
   * numbers is "3 numbers separated by ','". Unknown patterns come back as
   * they are.
   */
  std::string
  describe_pattern(const std::string &pattern);

  /**
   * The unit of the scene entry @p path ("Geometry/Radius", subsections
   * separated by '/') as its help states it: "m" where the help ends in
   * "[m]" (the convention of most entries), otherwise its first unit in
   * parentheses, such as "(Pa)" or "(N m^2)" (material entries); "" where
   * there is no such entry or its help names no unit.
   */
  std::string
  entry_unit(const std::string &path);
} // namespace rodnet

#endif
