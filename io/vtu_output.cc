#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1_eulerian.h>
#include <deal.II/fe/mapping_q_eulerian.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <base/first_problem.h>
#include <base/mpi_session.h>
#include <io/vtu_output.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
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

    /// Writes the file @p path by @p write; throws naming it where it
    /// cannot be opened or written.
    void
    write_file(const std::string                         &path,
               const std::function<void(std::ostream &)> &write)
    {
      std::ofstream out = open_for_writing(path);
      write(out);
      close_checked(out, path);
    }

    /// The name of the file @p path, without its directory.
    std::string
    file_name(const std::string &path)
    {
      return std::filesystem::path(path).filename().string();
    }

    /// Adds the 3-vector field @p name, @p values on @p dofs, to
    /// @p data_out.
    void
    add_vector_field(dealii::DataOut<1, 3>          &data_out,
                     const dealii::DoFHandler<1, 3> &dofs,
                     const dealii::Vector<double>   &values,
                     const std::string              &name)
    {
      data_out.add_data_vector(
        dofs,
        values,
        std::vector<std::string>(3, name),
        std::vector<Interpretation>(3, component_is_part_of_vector));
    }
  } // namespace

  VtuOutput::VtuOutput(const RodNetwork  &network_,
                       const std::string &directory_,
                       const std::string &basename_)
      : network(network_)
      , directory(directory_)
      , basename(basename_)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory))
      throw std::runtime_error("VtuOutput: cannot create the output "
                               "directory \"" +
                               directory + "\"" +
                               (error ? ": " + error.message() : ""));
  }


  VtuOutput::FieldSpace::FieldSpace(const RodNetwork  &network,
                                    const bool         per_segment,
                                    const unsigned int components)
      : dofs(network.triangulation())
  {
    if (per_segment)
      fe = std::make_unique<dealii::FESystem<1, 3>>(dealii::FE_DGQ<1, 3>(0),
                                                    components);
    else
      fe = std::make_unique<dealii::FESystem<1, 3>>(dealii::FE_Q<1, 3>(1),
                                                    components);
    dofs.distribute_dofs(*fe);
    index.resize(per_segment ? network.n_segments() : network.n_vertices());
    std::vector<dealii::types::global_dof_index> cell_dofs(
      fe->n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if (!RodNetwork::is_segment(*cell))
          continue;
        cell->get_dof_indices(cell_dofs);
        for (unsigned int i = 0; i < cell_dofs.size(); ++i)
          {
            const unsigned int entity =
              per_segment ? cell->active_cell_index() :
                            cell->vertex_index(i / fe->n_dofs_per_vertex());
            index[entity][fe->system_to_component_index(i).first] =
              cell_dofs[i];
          }
      }
  }


  const VtuOutput::FieldSpace &
  VtuOutput::space(const bool per_segment, const unsigned int components)
  {
    auto &made = spaces[{per_segment, components}];
    if (!made)
      made = std::make_unique<FieldSpace>(network, per_segment, components);
    return *made;
  }

  std::string
  VtuOutput::vtu_path(const unsigned int step) const
  {
    const bool pieces =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    return directory + "/" + basename + "-" +
           dealii::Utilities::int_to_string(step, 5) +
           (pieces ? ".pvtu" : ".vtu");
  }

  std::string
  VtuOutput::piece_path(const unsigned int step, const unsigned int rank) const
  {
    return directory + "/" + basename + "-" +
           dealii::Utilities::int_to_string(step, 5) + "." +
           std::to_string(rank) + ".vtu";
  }

  std::string
  VtuOutput::pvd_path() const
  {
    return directory + "/" + basename + ".pvd";
  }

  dealii::Vector<double>
  VtuOutput::displacement_vector(const std::vector<Vector3> &displacement)
  {
    const unsigned int n_vertices = network.triangulation().n_vertices();
    if (displacement.size() != n_vertices)
      throw std::invalid_argument(
        "VtuOutput: a displacement of " + std::to_string(displacement.size()) +
        " vertices for a network of " + std::to_string(n_vertices));
    const FieldSpace      &target = space(false, 3);
    dealii::Vector<double> values(target.dofs.n_dofs());
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int c = 0; c < 3; ++c)
        values[target.index[v][c]] = displacement[v][c];
    return values;
  }

  dealii::Vector<double>
  VtuOutput::field_vector(const OutputFields::Field &field,
                          const bool                 per_segment)
  {
    const unsigned int n =
      per_segment ? network.n_segments() : network.n_vertices();
    if (!(field.components == 1 || field.components == 3) ||
        field.values.size() != field.components * n)
      throw std::invalid_argument(
        "VtuOutput: the field \"" + field.name + "\" has " +
        std::to_string(field.values.size()) + " values for " +
        std::to_string(n) + (per_segment ? " segments" : " vertices"));
    if (field.components == 1 && per_segment)
      {
        // Cell data has a value per cell, also for the links that follow
        // the segments (they are not drawn).
        dealii::Vector<double> values(network.triangulation().n_active_cells());
        std::copy(field.values.begin(), field.values.end(), values.begin());
        return values;
      }
    const FieldSpace      &target = space(per_segment, field.components);
    dealii::Vector<double> values(target.dofs.n_dofs());
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < field.components; ++c)
        values[target.index[k][c]] = field.values[field.components * k + c];
    return values;
  }

  void
  VtuOutput::write(const unsigned int  step,
                   const double        time,
                   const OutputFields &fields)
  {
    // The fields as finite element vectors (the model's solution, other
    // vector fields and vertex scalars) or as cell data (segment scalars);
    // kept alive until the patches are built, at the addresses DataOut
    // holds (reserved: no reallocation).
    dealii::DataOut<1, 3> data_out;
    data_out.attach_triangulation(network.triangulation());
    // The segments, not the links that tie the rods into one mesh; on
    // several processes, this process's piece of them.
    const Piece piece = this_piece();
    data_out.set_cell_selection(
      [piece](const dealii::Triangulation<1, 3>::cell_iterator &cell) {
        return cell->is_active() && RodNetwork::is_segment(*cell) &&
               piece.holds(cell->active_cell_index());
      });
    std::vector<dealii::Vector<double>> values;
    values.reserve(1 + fields.vertex_fields.size() +
                   fields.segment_fields.size());
    const std::unique_ptr<dealii::Mapping<1, 3>> mapping =
      add_displacement(data_out, values, fields);
    add_fields(data_out, values, fields);
    data_out.build_patches(*mapping, 1);
    data_out.set_flags(dealii::DataOutBase::VtkFlags(
      time,
      step,
      false,
      dealii::DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed));
    write_patches(data_out, step, time);
  }

  VtuOutput::Piece
  VtuOutput::this_piece() const
  {
    const unsigned int n_pieces =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const std::uint64_t n_cells = network.triangulation().n_active_cells();
    return Piece{rank,
                 n_pieces,
                 static_cast<unsigned int>(n_cells * rank / n_pieces),
                 static_cast<unsigned int>(n_cells * (rank + 1) / n_pieces)};
  }

  std::unique_ptr<dealii::Mapping<1, 3>>
  VtuOutput::add_displacement(dealii::DataOut<1, 3>               &data_out,
                              std::vector<dealii::Vector<double>> &values,
                              const OutputFields                  &fields)
  {
    // A degree-1 Eulerian mapping moves each vertex by its displacement
    // (the first three components of the solution), so the patches are the
    // deformed polyline.
    if (const auto &solution = fields.solution)
      {
        data_out.add_data_vector(*solution->dof_handler,
                                 solution->values,
                                 solution->names,
                                 solution->interpretation);
        return std::make_unique<
          dealii::MappingQEulerian<1, dealii::Vector<double>, 3>>(
          1,
          *solution->dof_handler,
          solution->values);
      }
    values.push_back(displacement_vector(fields.displacement));
    add_vector_field(data_out,
                     space(false, 3).dofs,
                     values.back(),
                     "displacement");
    return std::make_unique<
      dealii::MappingQ1Eulerian<1, dealii::Vector<double>, 3>>(
      space(false, 3).dofs,
      values.back());
  }

  void
  VtuOutput::add_fields(dealii::DataOut<1, 3>               &data_out,
                        std::vector<dealii::Vector<double>> &values,
                        const OutputFields                  &fields)
  {
    for (const auto &[list, per_segment] :
         {std::make_pair(&fields.vertex_fields, false),
          std::make_pair(&fields.segment_fields, true)})
      for (const OutputFields::Field &field : *list)
        {
          values.push_back(field_vector(field, per_segment));
          if (field.components == 3)
            add_vector_field(data_out,
                             space(per_segment, 3).dofs,
                             values.back(),
                             field.name);
          else if (per_segment)
            data_out.add_data_vector(values.back(),
                                     field.name,
                                     dealii::DataOut<1, 3>::type_cell_data);
          else
            data_out.add_data_vector(space(false, 1).dofs,
                                     values.back(),
                                     field.name);
        }
  }

  void
  VtuOutput::write_patches(const dealii::DataOut<1, 3> &data_out,
                           const unsigned int           step,
                           const double                 time)
  {
    const Piece piece = this_piece();
    if (piece.n_pieces == 1)
      {
        write_file(vtu_path(step),
                   [&](std::ostream &out) { data_out.write_vtu(out); });
        records[step] = {time, file_name(vtu_path(step))};
        write_pvd_record();
        return;
      }
    // Each process writes its piece; one that cannot fails the step on all
    // (first_problem()), so that none waits in a later collective call.
    std::string problem;
    try
      {
        write_file(piece_path(step, piece.rank),
                   [&](std::ostream &out) { data_out.write_vtu(out); });
      }
    catch (const std::exception &e)
      {
        problem = e.what();
      }
    problem = first_problem(problem, MPI_COMM_WORLD);
    if (!problem.empty())
      throw std::runtime_error(problem);
    records[step] = {time, file_name(vtu_path(step))};
    if (!writes_outputs())
      return;
    std::vector<std::string> pieces;
    for (unsigned int rank = 0; rank < piece.n_pieces; ++rank)
      pieces.push_back(file_name(piece_path(step, rank)));
    write_file(vtu_path(step), [&](std::ostream &out) {
      data_out.write_pvtu_record(out, pieces);
    });
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
