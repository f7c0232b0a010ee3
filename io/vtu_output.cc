#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/mapping_q1_eulerian.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <elements/stretch_kernel.h>
#include <io/vtu_output.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace rodnet
{
  namespace
  {
    using dealii::DataComponentInterpretation::component_is_part_of_vector;
    using dealii::DataComponentInterpretation::component_is_scalar;
    using Interpretation =
      dealii::DataComponentInterpretation::DataComponentInterpretation;

    /// Opens @p path for writing; throws naming it if that fails.
    std::ofstream
    open_for_writing(const std::string &path)
    {
      std::ofstream out(path);
      if (!out)
        throw std::runtime_error("VtuOutput: cannot open \"" + path +
                                 "\" for writing");
      return out;
    }

    /// VTU field name of an internal variable labelled "name (unit)":
    /// the name with underscores for blanks.
    std::string
    field_name(const std::string &label)
    {
      std::string name = label.substr(0, label.find(" ("));
      std::replace(name.begin(), name.end(), ' ', '_');
      return name;
    }

    /// Closes @p out; throws naming @p path if any write failed.
    void
    close_checked(std::ofstream &out, const std::string &path)
    {
      out.close();
      if (!out)
        throw std::runtime_error("VtuOutput: writing \"" + path + "\" failed");
    }
  } // namespace

  VtuOutput::VtuOutput(const RodModel    &model_,
                       const std::string &directory_,
                       const std::string &basename_)
      : model(model_)
      , directory(directory_)
      , basename(basename_)
      , vertex_vector_fe(dealii::FE_Q<1, 3>(1), 3)
      , vertex_vector_dofs(model_.network().triangulation())
      , vertex_scalar_fe(1)
      , vertex_scalar_dofs(model_.network().triangulation())
      , segment_vector_fe(dealii::FE_DGQ<1, 3>(0), 3)
      , segment_vector_dofs(model_.network().triangulation())
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory))
      throw std::runtime_error("VtuOutput: cannot create the output "
                               "directory \"" +
                               directory + "\"" +
                               (error ? ": " + error.message() : ""));

    vertex_vector_dofs.distribute_dofs(vertex_vector_fe);
    vertex_scalar_dofs.distribute_dofs(vertex_scalar_fe);
    segment_vector_dofs.distribute_dofs(segment_vector_fe);

    const auto &tria = model.network().triangulation();
    vertex_vector_index.resize(tria.n_vertices());
    vertex_scalar_index.resize(tria.n_vertices());
    segment_vector_index.resize(tria.n_active_cells());
    std::vector<global_dof_index> dofs;
    for (const auto &cell : vertex_vector_dofs.active_cell_iterators())
      {
        dofs.resize(vertex_vector_fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          vertex_vector_index
            [cell->vertex_index(i / vertex_vector_fe.n_dofs_per_vertex())]
            [vertex_vector_fe.system_to_component_index(i).first] = dofs[i];
      }
    for (const auto &cell : vertex_scalar_dofs.active_cell_iterators())
      {
        dofs.resize(vertex_scalar_fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          vertex_scalar_index[cell->vertex_index(i)] = dofs[i];
      }
    for (const auto &cell : segment_vector_dofs.active_cell_iterators())
      {
        dofs.resize(segment_vector_fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          segment_vector_index[cell->active_cell_index()]
                              [segment_vector_fe.system_to_component_index(i)
                                 .first] = dofs[i];
      }
  }

  std::string
  VtuOutput::vtu_path(const unsigned int step) const
  {
    return directory + "/" + basename + "-" +
           dealii::Utilities::int_to_string(step, 5) + ".vtu";
  }

  std::string
  VtuOutput::pvd_path() const
  {
    return directory + "/" + basename + ".pvd";
  }

  void
  VtuOutput::write(const unsigned int step,
                   const double       load_factor,
                   const VectorType  &u)
  {
    if (dealii::Utilities::MPI::this_mpi_process(u.get_mpi_communicator()) != 0)
      return;

    const Configuration &configuration = model.configuration();
    const auto          &tria          = model.network().triangulation();

    dealii::Vector<double> displacement(vertex_vector_dofs.n_dofs());
    for (unsigned int v = 0; v < vertex_vector_index.size(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        displacement[vertex_vector_index[v][c]] =
          u[model.layout().vertex_dof(v, c)];

    dealii::Vector<double> axial_strain(tria.n_active_cells());
    dealii::Vector<double> d1(segment_vector_dofs.n_dofs());
    dealii::Vector<double> d2(segment_vector_dofs.n_dofs());
    StretchStrain          stretch;
    for (const SegmentStencil &segment : model.layout().segments())
      {
        evaluate_stretch(configuration.segment_dofs(u, segment),
                         configuration.rest_length(segment.cell),
                         stretch,
                         false);
        axial_strain[segment.cell] = stretch.strain;
        const Matrix3 frame =
          configuration.director_frame(u, segment.cell).toRotationMatrix();
        for (unsigned int c = 0; c < 3; ++c)
          {
            d1[segment_vector_index[segment.cell][c]] = frame(c, 0);
            d2[segment_vector_index[segment.cell][c]] = frame(c, 1);
          }
      }

    // Integrated strains divided by the Voronoi length are the curvatures
    // and twist rate of the smooth rod (Korner et al. eq. 4.2). Vertices
    // without a hinge (rod ends) keep zero.
    dealii::Vector<double> curvature(vertex_vector_dofs.n_dofs());
    dealii::Vector<double> twist_rate(vertex_scalar_dofs.n_dofs());
    const auto            &hinges = model.layout().hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      {
        const HingeStencil &hinge = hinges[h];
        const Vector3       kappa = model.hinge_kernel(hinge.rod).strains(
                                configuration.hinge_dofs(u, hinge),
                                configuration.hinge_reference(h)) /
                              configuration.voronoi_length(h);
        const unsigned int vertex                 = hinge.vertices[1];
        curvature[vertex_vector_index[vertex][0]] = kappa[0];
        curvature[vertex_vector_index[vertex][1]] = kappa[1];
        twist_rate[vertex_scalar_index[vertex]]   = kappa[2];
      }

    // Internal variables of history-dependent materials, one field per
    // name: hinge variables at the hinge's vertex, segment ones per cell,
    // zero where a rod's material has no such variable. (Junction elements
    // share their vertex with several rods and are not drawn.)
    using Owner                      = InternalVariables::Owner;
    const InternalVariables &history = model.internal_variables();
    std::map<std::string, dealii::Vector<double>> vertex_history, cell_history;
    for (unsigned int h = 0; !history.empty() && h < hinges.size(); ++h)
      {
        const auto names =
          model.material(hinges[h].rod).hinge_internal_variable_names();
        for (unsigned int m = 0; m < names.size(); ++m)
          vertex_history
            .try_emplace(field_name(names[m]), vertex_scalar_dofs.n_dofs())
            .first->second[vertex_scalar_index[hinges[h].vertices[1]]] =
            history.block(Owner::hinge, h)[m];
      }
    const auto &segments = model.layout().segments();
    for (unsigned int c = 0; !history.empty() && c < segments.size(); ++c)
      {
        const auto names =
          model.material(segments[c].rod).segment_internal_variable_names();
        for (unsigned int m = 0; m < names.size(); ++m)
          cell_history.try_emplace(field_name(names[m]), tria.n_active_cells())
            .first->second[segments[c].cell] =
            history.block(Owner::segment, c)[m];
      }

    // The DoFHandler's part of u, with the position of every rod end at a
    // junction filled in from the DoFs it shares.
    const DofLayout       &layout = model.layout();
    dealii::Vector<double> fields(layout.n_field_dofs());
    for (unsigned int i = 0; i < fields.size(); ++i)
      fields[i] = u[i];
    for (const auto &[copy, source] : layout.shared_copies())
      fields[copy] = u[source];

    dealii::DataOut<1, 3> data_out;
    data_out.attach_triangulation(tria);
    data_out.add_data_vector(
      layout.dof_handler(),
      fields,
      {"displacement", "displacement", "displacement", "twist"},
      {component_is_part_of_vector,
       component_is_part_of_vector,
       component_is_part_of_vector,
       component_is_scalar});
    const auto add_vector_field =
      [&data_out](const dealii::DoFHandler<1, 3> &dofs,
                  const dealii::Vector<double>   &values,
                  const std::string              &name) {
        data_out.add_data_vector(
          dofs,
          values,
          std::vector<std::string>(3, name),
          std::vector<Interpretation>(3, component_is_part_of_vector));
      };
    add_vector_field(vertex_vector_dofs, curvature, "curvature");
    data_out.add_data_vector(vertex_scalar_dofs, twist_rate, "twist_rate");
    add_vector_field(segment_vector_dofs, d1, "d1");
    add_vector_field(segment_vector_dofs, d2, "d2");
    data_out.add_data_vector(axial_strain,
                             "axial_strain",
                             dealii::DataOut<1, 3>::type_cell_data);
    for (const auto &[name, values] : vertex_history)
      data_out.add_data_vector(vertex_scalar_dofs, values, name);
    for (const auto &[name, values] : cell_history)
      data_out.add_data_vector(values,
                               name,
                               dealii::DataOut<1, 3>::type_cell_data);

    // A degree-1 Eulerian mapping moves each vertex by its displacement, so
    // the patches are the deformed polyline.
    const dealii::MappingQ1Eulerian<1, dealii::Vector<double>, 3> mapping(
      vertex_vector_dofs,
      displacement);
    data_out.build_patches(mapping, 1);

    dealii::DataOutBase::VtkFlags flags(
      load_factor,
      step,
      false,
      dealii::DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed);
    data_out.set_flags(flags);

    const std::string vtu  = vtu_path(step);
    std::ofstream     file = open_for_writing(vtu);
    data_out.write_vtu(file);
    close_checked(file, vtu);

    records[step] = {load_factor,
                     std::filesystem::path(vtu).filename().string()};
    std::vector<std::pair<double, std::string>> times_and_names;
    for (const auto &record : records)
      times_and_names.push_back(record.second);

    // Replace the record atomically: a crash while writing it must not
    // leave a truncated .pvd behind in place of the previous one.
    const std::string pvd       = pvd_path();
    const std::string temporary = pvd + ".tmp";
    std::ofstream     record    = open_for_writing(temporary);
    dealii::DataOutBase::write_pvd_record(record, times_and_names);
    close_checked(record, temporary);
    std::error_code error;
    std::filesystem::rename(temporary, pvd, error);
    if (error)
      throw std::runtime_error("VtuOutput: cannot replace \"" + pvd +
                               "\": " + error.message());
  }
} // namespace rodnet
