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
    const unsigned int  n_cells = network_->n_segments();
    OutputFields::Field force{"axial_force",
                              1,
                              std::vector<double>(n_cells),
                              "N"};
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      force.values[cell] = axial_force(cell, u);
    return force;
  }


  std::vector<OutputFields::Field>
  RodModel::segment_strain_fields(const VectorType &u) const
  {
    const unsigned int  n_cells = network_->n_segments();
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
    // Each family draws its stencils' variables, zero where a rod's
    // material has no such variable.
    if (history.empty())
      return;
    InternalVariableFields fields(network_->n_vertices(),
                                  network_->n_segments());
    for (const auto &family : families)
      family->write_internal_variables(history, fields);
    fields.append_to(output.vertex_fields, output.segment_fields);
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
