#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/mapping_q1_eulerian.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <io/vtu_output.h>

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

    /// Closes @p out; throws naming @p path if any write failed.
    void
    close_checked(std::ofstream &out, const std::string &path)
    {
      out.close();
      if (!out)
        throw std::runtime_error("VtuOutput: writing \"" + path + "\" failed");
    }
  } // namespace

  VtuOutput::VtuOutput(const RodNetwork  &network_,
                       const std::string &directory_,
                       const std::string &basename_)
      : network(network_)
      , directory(directory_)
      , basename(basename_)
      , vertex_vector_fe(dealii::FE_Q<1, 3>(1), 3)
      , vertex_vector_dofs(network_.triangulation())
      , vertex_scalar_fe(1)
      , vertex_scalar_dofs(network_.triangulation())
      , segment_vector_fe(dealii::FE_DGQ<1, 3>(0), 3)
      , segment_vector_dofs(network_.triangulation())
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

    const auto &tria = network.triangulation();
    vertex_vector_index.resize(tria.n_vertices());
    vertex_scalar_index.resize(tria.n_vertices());
    segment_vector_index.resize(tria.n_active_cells());
    std::vector<dealii::types::global_dof_index> dofs;
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

  dealii::Vector<double>
  VtuOutput::field_vector(const OutputFields::Field &field,
                          const bool                 per_segment) const
  {
    const unsigned int n =
      per_segment ? segment_vector_index.size() : vertex_vector_index.size();
    if (!(field.components == 1 || field.components == 3) ||
        field.values.size() != field.components * n)
      throw std::invalid_argument(
        "VtuOutput: the field \"" + field.name + "\" has " +
        std::to_string(field.values.size()) + " values for " +
        std::to_string(n) + (per_segment ? " segments" : " vertices"));
    if (field.components == 1 && per_segment)
      return dealii::Vector<double>(field.values.begin(), field.values.end());
    const auto &index =
      per_segment ? segment_vector_index : vertex_vector_index;
    dealii::Vector<double> values(field.components == 1 ?
                                    vertex_scalar_dofs.n_dofs() :
                                  per_segment ? segment_vector_dofs.n_dofs() :
                                                vertex_vector_dofs.n_dofs());
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < field.components; ++c)
        values[field.components == 1 ? vertex_scalar_index[k] : index[k][c]] =
          field.values[field.components * k + c];
    return values;
  }

  void
  VtuOutput::write(const unsigned int  step,
                   const double        time,
                   const OutputFields &fields)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const auto        &tria       = network.triangulation();
    const unsigned int n_vertices = vertex_vector_index.size();
    if (fields.displacement.size() != n_vertices)
      throw std::invalid_argument("VtuOutput: a displacement of " +
                                  std::to_string(fields.displacement.size()) +
                                  " vertices for a network of " +
                                  std::to_string(n_vertices));

    dealii::Vector<double> displacement(vertex_vector_dofs.n_dofs());
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int c = 0; c < 3; ++c)
        displacement[vertex_vector_index[v][c]] = fields.displacement[v][c];

    // The fields as finite element vectors of the handlers above (vector
    // fields and vertex scalars) or as cell data (segment scalars); kept
    // alive until the patches are built.
    dealii::DataOut<1, 3> data_out;
    data_out.attach_triangulation(tria);
    std::vector<dealii::Vector<double>> values;
    values.reserve(1 + fields.vertex_fields.size() +
                   fields.segment_fields.size());
    const auto add_vector = [&](const dealii::DoFHandler<1, 3> &dofs,
                                const std::string              &name) {
      data_out.add_data_vector(
        dofs,
        values.back(),
        std::vector<std::string>(3, name),
        std::vector<Interpretation>(3, component_is_part_of_vector));
    };
    values.push_back(displacement);
    add_vector(vertex_vector_dofs, "displacement");
    for (const auto &[list, per_segment] :
         {std::make_pair(&fields.vertex_fields, false),
          std::make_pair(&fields.segment_fields, true)})
      for (const OutputFields::Field &field : *list)
        {
          values.push_back(field_vector(field, per_segment));
          if (field.components == 3)
            add_vector(per_segment ? segment_vector_dofs : vertex_vector_dofs,
                       field.name);
          else if (per_segment)
            data_out.add_data_vector(values.back(),
                                     field.name,
                                     dealii::DataOut<1, 3>::type_cell_data);
          else
            data_out.add_data_vector(vertex_scalar_dofs,
                                     values.back(),
                                     field.name);
        }

    // A degree-1 Eulerian mapping moves each vertex by its displacement, so
    // the patches are the deformed polyline.
    const dealii::MappingQ1Eulerian<1, dealii::Vector<double>, 3> mapping(
      vertex_vector_dofs,
      displacement);
    data_out.build_patches(mapping, 1);
    data_out.set_flags(dealii::DataOutBase::VtkFlags(
      time,
      step,
      false,
      dealii::DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed));

    const std::string vtu  = vtu_path(step);
    std::ofstream     file = open_for_writing(vtu);
    data_out.write_vtu(file);
    close_checked(file, vtu);
    records[step] = {time, std::filesystem::path(vtu).filename().string()};
    write_pvd_record();
  }

  void
  VtuOutput::write_pvd_record() const
  {
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
