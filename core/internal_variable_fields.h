#ifndef RODNET_CORE_INTERNAL_VARIABLE_FIELDS_H
#define RODNET_CORE_INTERNAL_VARIABLE_FIELDS_H

#include <core/output_fields.h>

#include <map>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * The committed internal variables drawn as scalar fields, one per
   * variable name, with one value per vertex or per cell of the network
   * (zero where no stencil writes one): what each family with history
   * writes its stencils' values into
   * (ElementFamily::write_internal_variables()), and the output then appends,
   * in the order of the names.
   */
  class InternalVariableFields
  {
  public:
    InternalVariableFields(std::size_t n_vertices, std::size_t n_cells);

    /// The per-vertex values of the variable labelled @p label ("name
    /// (unit)", RodMaterial::hinge_internal_variable_names()).
    std::vector<double> &
    at_vertices(const std::string &label);

    /// The per-cell values of the variable labelled @p label.
    std::vector<double> &
    at_cells(const std::string &label);

    /// Appends the vertex fields (defined at the hinges) to
    /// @p vertex_fields and the cell fields to @p segment_fields.
    void
    append_to(std::vector<OutputFields::Field> &vertex_fields,
              std::vector<OutputFields::Field> &segment_fields) const;

  private:
    /// Field name -> (unit, values).
    using Named =
      std::map<std::string, std::pair<std::string, std::vector<double>>>;

    std::size_t n_vertices, n_cells;
    Named       vertex_fields, cell_fields;

    /// The values of the field of @p label in @p named, made with @p n
    /// zeros and the label's unit if new.
    static std::vector<double> &
    values_of(Named &named, const std::string &label, std::size_t n);
  };
} // namespace rodnet

#endif
