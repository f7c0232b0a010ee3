#ifndef RODNET_CORE_OUTPUT_FIELDS_H
#define RODNET_CORE_OUTPUT_FIELDS_H

#include <core/rod_network.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * What a model shows of a state for output (VtuOutput): the displacement
   * of every network vertex, which moves the drawn polyline, and named
   * fields per vertex and per segment (active cell of the network's
   * triangulation).
   */
  struct OutputFields
  {
    /// A scalar (1 component) or vector (3 components) field; values
    /// component by component, entity by entity: values[3 i + c].
    struct Field
    {
      std::string         name;
      unsigned int        components;
      std::vector<double> values;
    };

    /// Per network vertex: current minus undeformed position.
    std::vector<Vector3> displacement;
    std::vector<Field>   vertex_fields;
    std::vector<Field>   segment_fields;
  };
} // namespace rodnet

#endif
