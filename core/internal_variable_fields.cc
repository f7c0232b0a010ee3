#include <core/internal_variable_fields.h>

#include <algorithm>

namespace rodnet
{
  namespace
  {
    /// Output field name of an internal variable labelled "name (unit)":
    /// the name with underscores for blanks.
    std::string
    internal_variable_field_name(const std::string &label)
    {
      std::string name = label.substr(0, label.find(" ("));
      std::replace(name.begin(), name.end(), ' ', '_');
      return name;
    }

    /// The unit of an internal variable labelled "name (unit)"; "-" where
    /// the label gives none.
    std::string
    internal_variable_unit(const std::string &label)
    {
      const std::size_t open = label.find(" (");
      if (open == std::string::npos || label.back() != ')')
        return "-";
      return label.substr(open + 2, label.size() - open - 3);
    }
  } // namespace

  InternalVariableFields::InternalVariableFields(const std::size_t n_vertices,
                                                 const std::size_t n_cells)
      : n_vertices(n_vertices)
      , n_cells(n_cells)
  {
  }

  std::vector<double> &
  InternalVariableFields::values_of(Named             &named,
                                    const std::string &label,
                                    const std::size_t  n)
  {
    return named
      .try_emplace(internal_variable_field_name(label),
                   internal_variable_unit(label),
                   std::vector<double>(n))
      .first->second.second;
  }

  std::vector<double> &
  InternalVariableFields::at_vertices(const std::string &label)
  {
    return values_of(vertex_fields, label, n_vertices);
  }

  std::vector<double> &
  InternalVariableFields::at_cells(const std::string &label)
  {
    return values_of(cell_fields, label, n_cells);
  }

  void
  InternalVariableFields::append_to(
    std::vector<OutputFields::Field> &vertex_output,
    std::vector<OutputFields::Field> &segment_output) const
  {
    for (const auto &[name, values] : vertex_fields)
      vertex_output.push_back({name, 1, values.second, values.first, true});
    for (const auto &[name, values] : cell_fields)
      segment_output.push_back({name, 1, values.second, values.first, false});
  }
} // namespace rodnet
