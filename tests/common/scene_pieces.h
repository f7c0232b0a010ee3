#ifndef RODNET_TESTS_SCENE_PIECES_H
#define RODNET_TESTS_SCENE_PIECES_H

#include <string>

namespace rodnet::testing
{
  /// Subsection Material of a scene: a linear elastic rod of axial
  /// rigidity @p EA and unit bending and torsional rigidities.
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
} // namespace rodnet::testing

#endif
