// The fields of a RodModel state for output (VtuOutput): displacement and
// twist on the model's DoFHandler, strains, directors, curvatures,
// activation fields and internal variables.
#include <core/rod_model.h>
#include <elements/stretch_kernel.h>

#include <algorithm>
#include <array>
#include <map>

namespace rodnet
{
  namespace
  {
    /// Output field name of an internal variable labelled "name (unit)":
    /// the name with underscores for blanks.
    std::string
    field_name(const std::string &label)
    {
      std::string name = label.substr(0, label.find(" ("));
      std::replace(name.begin(), name.end(), ' ', '_');
      return name;
    }

    /// The unit of an internal variable labelled "name (unit)"; "-" where
    /// the label gives none.
    std::string
    field_unit(const std::string &label)
    {
      const std::size_t open = label.find(" (");
      if (open == std::string::npos || label.back() != ')')
        return "-";
      return label.substr(open + 2, label.size() - open - 3);
    }

    /// Appends the fields of @p named (name -> (unit, values)) to
    /// @p fields, defined at the hinges only where @p at_hinges.
    void
    append_scalar_fields(
      const std::map<std::string, std::pair<std::string, std::vector<double>>>
                                       &named,
      std::vector<OutputFields::Field> &fields,
      const bool                        at_hinges = false)
    {
      for (const auto &[name, values] : named)
        fields.push_back({name, 1, values.second, values.first, at_hinges});
    }

    /// Appends to @p fields the activation fields' densities per segment
    /// (Configuration::segment_activation()), if any.
    void
    append_activation_fields(const std::vector<Eigen::Vector4d> &densities,
                             std::vector<OutputFields::Field>   &fields)
    {
      if (densities.empty())
        return;
      const std::array<std::pair<const char *, const char *>, 4> names{
        {{"activation_curvature_1", "1/m"},
         {"activation_curvature_2", "1/m"},
         {"activation_twist", "rad/m"},
         {"activation_eigenstrain", "-"}}};
      for (unsigned int k = 0; k < 4; ++k)
        {
          OutputFields::Field field{names[k].first, 1, {}, names[k].second};
          for (const Eigen::Vector4d &density : densities)
            field.values.push_back(density[k]);
          fields.push_back(field);
        }
    }

    /// The values of the field of the internal variable labelled @p label
    /// in @p named, made with @p n zeros and the label's unit if new.
    std::vector<double> &
    internal_variable_field(
      std::map<std::string, std::pair<std::string, std::vector<double>>> &named,
      const std::string                                                  &label,
      const std::size_t                                                   n)
    {
      return named
        .try_emplace(field_name(label),
                     field_unit(label),
                     std::vector<double>(n))
        .first->second.second;
    }
  } // namespace

  dealii::Vector<double>
  RodModel::field_values(const VectorType &u) const
  {
    const global_dof_index n = layout_->n_field_dofs();
    dealii::Vector<double> values(n);
    for (global_dof_index i = 0; i < n; ++i)
      values[i] = u[i];
    layout_->junction_constraints().distribute(values);
    return values;
  }


  OutputFields::Field
  RodModel::axial_forces(const VectorType &u) const
  {
    // Inextensible segments: the multipliers; the others: the material's
    // stress at its committed internal variables, over no time step.
    using Owner = InternalVariables::Owner;
    OutputFields::Field force{"axial_force",
                              1,
                              std::vector<double>(
                                network_->triangulation().n_active_cells()),
                              "N"};
    StretchStrain       stretch;
    unsigned int        stencil = 0;
    for (const SegmentStencil &segment : layout_->segments())
      {
        if (network_->rods()[segment.rod].inextensible)
          {
            force.values[segment.cell] = constraint_force(segment.cell, u);
            continue;
          }
        const double l0 = configuration_->rest_length(segment.cell);
        evaluate_stretch(configuration_->segment_dofs(u, segment),
                         l0,
                         stretch,
                         false);
        const double *committed =
          history.empty() ? nullptr : history.block(Owner::segment, stencil);
        force.values[segment.cell] =
          materials[segment.rod]
            ->segment_increment(stretch.strain, l0, committed, 0.0, nullptr)
            .stress[0] /
          l0;
        ++stencil;
      }
    return force;
  }


  std::vector<OutputFields::Field>
  RodModel::segment_strain_fields(const VectorType &u) const
  {
    const unsigned int  n_cells = network_->triangulation().n_active_cells();
    OutputFields::Field strain{"axial_strain",
                               1,
                               std::vector<double>(n_cells),
                               "-"};
    OutputFields::Field d1{"d1", 3, std::vector<double>(3 * n_cells), "-"};
    OutputFields::Field d2{"d2", 3, std::vector<double>(3 * n_cells), "-"};
    StretchStrain       stretch;
    for (const SegmentStencil &segment : layout_->segments())
      {
        evaluate_stretch(configuration_->segment_dofs(u, segment),
                         configuration_->rest_length(segment.cell),
                         stretch,
                         false);
        strain.values[segment.cell] = stretch.strain;
        const Matrix3 frame =
          configuration_->director_frame(u, segment.cell).toRotationMatrix();
        for (unsigned int c = 0; c < 3; ++c)
          {
            d1.values[3 * segment.cell + c] = frame(c, 0);
            d2.values[3 * segment.cell + c] = frame(c, 1);
          }
      }
    return {strain, d1, d2};
  }


  std::vector<OutputFields::Field>
  RodModel::hinge_strain_fields(const VectorType &u) const
  {
    // Integrated strains divided by the Voronoi length are the curvatures
    // and twist rate of the smooth rod (Korner et al. eq. 4.2). Vertices
    // without a hinge (rod ends) keep zero.
    const unsigned int  n_vertices = network_->n_vertices();
    OutputFields::Field curvature{"curvature",
                                  3,
                                  std::vector<double>(3 * n_vertices),
                                  "1/m",
                                  true};
    OutputFields::Field twist_rate{"twist_rate",
                                   1,
                                   std::vector<double>(n_vertices),
                                   "rad/m",
                                   true};
    const auto         &hinges = layout_->hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      {
        const Vector3 kappa =
          kernels[hinges[h].rod]->strains(configuration_->hinge_dofs(u,
                                                                     hinges[h]),
                                          configuration_->hinge_reference(h)) /
          configuration_->voronoi_length(h);
        const unsigned int vertex        = hinges[h].vertices[1];
        curvature.values[3 * vertex + 0] = kappa[0];
        curvature.values[3 * vertex + 1] = kappa[1];
        twist_rate.values[vertex]        = kappa[2];
      }
    return {curvature, twist_rate};
  }


  void
  RodModel::append_internal_variable_fields(OutputFields &output) const
  {
    // Hinge variables at the hinge's vertex, segment ones per cell, zero
    // where a rod's material has no such variable. (Junction elements
    // share their vertex with several rods and are not drawn.)
    if (history.empty())
      return;
    using Owner = InternalVariables::Owner;
    std::map<std::string, std::pair<std::string, std::vector<double>>>
                vertex_history, cell_history;
    const auto &hinges = layout_->hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      {
        const auto names =
          materials[hinges[h].rod]->hinge_internal_variable_names();
        for (unsigned int m = 0; m < names.size(); ++m)
          internal_variable_field(
            vertex_history,
            names[m],
            network_->n_vertices())[hinges[h].vertices[1]] =
            history.block(Owner::hinge, h)[m];
      }
    // The segment stencils skip the segments of inextensible rods.
    const auto  &segments = layout_->segments();
    unsigned int stencil  = 0;
    for (const SegmentStencil &segment : segments)
      {
        if (network_->rods()[segment.rod].inextensible)
          continue;
        const auto names =
          materials[segment.rod]->segment_internal_variable_names();
        for (unsigned int m = 0; m < names.size(); ++m)
          internal_variable_field(
            cell_history,
            names[m],
            network_->triangulation().n_active_cells())[segment.cell] =
            history.block(Owner::segment, stencil)[m];
        ++stencil;
      }
    append_scalar_fields(vertex_history, output.vertex_fields, true);
    append_scalar_fields(cell_history, output.segment_fields);
  }


  OutputFields
  RodModel::output_fields(const VectorType &u) const
  {
    // The displacement and the twist are the model's finite element field.
    OutputFields output;
    using dealii::DataComponentInterpretation::component_is_part_of_vector;
    using dealii::DataComponentInterpretation::component_is_scalar;
    output.solution = OutputFields::FiniteElementField{
      &layout_->dof_handler(),
      field_values(u),
      {"displacement", "displacement", "displacement", "twist"},
      {component_is_part_of_vector,
       component_is_part_of_vector,
       component_is_part_of_vector,
       component_is_scalar}};
    output.segment_fields = segment_strain_fields(u);
    // The axial force of an inextensible rod is its constraint's.
    const auto &rods = network_->rods();
    if (std::any_of(rods.begin(), rods.end(), [](const Rod &rod) {
          return rod.inextensible;
        }))
      output.segment_fields.push_back(axial_forces(u));
    append_activation_fields(configuration_->segment_activation(),
                             output.segment_fields);
    output.vertex_fields = hinge_strain_fields(u);
    append_declared_dof_fields(u, output.vertex_fields);
    append_internal_variable_fields(output);
    return output;
  }


  void
  RodModel::append_declared_dof_fields(
    const VectorType                 &u,
    std::vector<OutputFields::Field> &fields) const
  {
    const std::size_t first_new  = fields.size();
    const unsigned    n_vertices = network_->n_vertices();
    for (const DofBlock &block : layout_->declared_blocks())
      for (unsigned int i = 0; i < block.dofs.size(); ++i)
        {
          const DeclaredDofOutput &out = block.dofs[i].output;
          if (out.field.empty())
            continue;
          auto field =
            std::find_if(fields.begin() + first_new,
                         fields.end(),
                         [&](const auto &f) { return f.name == out.field; });
          if (field == fields.end())
            field =
              fields.insert(fields.end(),
                            {out.field,
                             out.components,
                             std::vector<double>(out.components * n_vertices),
                             out.unit});
          field
            ->values[out.components * block.dofs[i].vertex + out.component] +=
            out.factor * u[block.first + i];
        }
  }
} // namespace rodnet
