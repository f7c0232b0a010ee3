#ifndef RODNET_TESTS_SCENE_TEXT_H
#define RODNET_TESTS_SCENE_TEXT_H

#include <string>

namespace rodnet::testing
{
  /// The subsection Material of a scene: a linear elastic rod with the
  /// rigidities given directly.
  inline std::string
  direct_material(const double EA,
                  const double EI1,
                  const double EI2,
                  const double GJ)
  {
    return "subsection Material\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = direct\n"
           "    set EA = " +
           std::to_string(EA) + "\n    set EI1 = " + std::to_string(EI1) +
           "\n    set EI2 = " + std::to_string(EI2) +
           "\n    set GJ = " + std::to_string(GJ) +
           "\n"
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
} // namespace rodnet::testing

#endif
