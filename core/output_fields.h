#ifndef RODNET_CORE_OUTPUT_FIELDS_H
#define RODNET_CORE_OUTPUT_FIELDS_H

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <core/rod_network.h>

#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * What a model shows of a state for output (VtuOutput): its solution as a
   * finite element field on its own DoFHandler where it has one, or else
   * the displacement of every network vertex; and named fields per vertex
   * and per segment (active cell of the network's triangulation) that are
   * not finite element fields (curvatures at hinges, directors, ...).
   */
  struct OutputFields
  {
    /// A scalar (1 component) or vector (3 components) field; values
    /// component by component, entity by entity: values[3 i + c]; its unit
    /// as a picture's colour bar states it ("1/m", "-").
    struct Field
    {
      std::string         name;
      unsigned int        components;
      std::vector<double> values;
      std::string         unit = "";
      /// A vertex field defined at the interior vertices of each open rod
      /// only (at its hinges: curvature, twist rate), whose value at a rod's
      /// end (0) is no value: a picture colours the end's half segment by
      /// the vertex next to it.
      bool interior_vertices_only = false;
    };

    /**
     * A model's solution on its own DoFHandler (over the network's
     * triangulation), with its constraints distributed: deal.II's DataOut
     * draws it as it is. The first three components are the displacement,
     * which moves the drawn polyline (MappingQEulerian).
     */
    struct FiniteElementField
    {
      const dealii::DoFHandler<1, 3> *dof_handler = nullptr;
      dealii::Vector<double>          values;
      /// One name per component ("displacement" three times, ...).
      std::vector<std::string> names;
      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>
        interpretation;
    };

    /// The solution on the model's DoFHandler (RodModel), if it has one.
    std::optional<FiniteElementField> solution;
    /// Otherwise per network vertex: current minus undeformed position.
    std::vector<Vector3> displacement;
    std::vector<Field>   vertex_fields;
    std::vector<Field>   segment_fields;
  };
} // namespace rodnet

#endif
