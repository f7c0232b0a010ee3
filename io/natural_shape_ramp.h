#ifndef RODNET_IO_NATURAL_SHAPE_RAMP_H
#define RODNET_IO_NATURAL_SHAPE_RAMP_H

#include <materials/rod_material.h>

#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /// The entry "Loads/Ramped natural shape": which parts of the natural
  /// shape of which rods the load factor scales (RodModel::
  /// ramp_natural_shape()).
  struct NaturalShapeRamp
  {
    NaturalShapeParts parts;
    /// The rods; empty for every rod.
    std::vector<unsigned int> rods;
  };

  /**
   * Parses "<parts>[: <rods>]": parts a ','-separated list of "curvature",
   * "twist" and "eigenstrain", rods a ','-separated list of rod numbers
   * (every rod if none). Empty text: no ramp. Throws std::invalid_argument
   * naming the entry "Loads/Ramped natural shape" and the word it cannot
   * read.
   */
  std::optional<NaturalShapeRamp>
  parse_natural_shape_ramp(const std::string &text);

  /// The entry's name, for messages.
  inline const std::string natural_shape_ramp_entry =
    "Loads/Ramped natural shape";
} // namespace rodnet

#endif
