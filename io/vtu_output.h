#ifndef RODNET_IO_VTU_OUTPUT_H
#define RODNET_IO_VTU_OUTPUT_H

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <core/model.h>
#include <core/output_fields.h>
#include <core/rod_network.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * Writes states of a model as a ParaView time series: one file
   * `<directory>/<basename>-NNNNN.vtu` per step and the collection
   * `<directory>/<basename>.pvd` listing every step written so far, with the
   * load factor (static runs) or the time (time stepping) as its "time".
   * Cells are drawn in the deformed configuration: the rods of the network
   * moved by the model's displacement. The fields are those the model gives
   * (Model::output_fields(): RodModel::output_fields(),
   * DrModel::output_fields()), "displacement" first: a model's solution on
   * its own DoFHandler as it is (deal.II's DataOut and MappingQEulerian on
   * it), other fields per vertex or segment on a DoFHandler of this writer
   * made for the first field that needs it.
   *
   * On P > 1 MPI processes each process writes a piece of every step,
   * `<basename>-NNNNN.<rank>.vtu`, the segments of a P-th of the cells
   * (every process holds the whole network and state), and rank 0 writes
   * the step's `<basename>-NNNNN.pvtu`, which lists the pieces, and the .pvd
   * record of the .pvtu files. ParaView opens either collection alike.
   *
   * deal.II's VTU writer stores every value as a 32-bit float, which is
   * enough to look at but not to restart from. The network must outlive
   * this object.
   */
  class VtuOutput
  {
  public:
    /**
     * Output of models of @p network. Creates @p directory (and its
     * parents) if needed; throws std::runtime_error naming the path if it
     * cannot.
     */
    VtuOutput(const RodNetwork  &network,
              const std::string &directory,
              const std::string &basename = "solution");

    /**
     * Writes @p fields of step @p step at load factor (or time) @p time
     * and rewrites the .pvd record, both before returning, so that a later
     * failure loses no converged step. Writing the same step again replaces
     * its entry. Collective on several processes: every process writes its
     * piece (see above) and rank 0 the .pvtu and .pvd files. Throws
     * std::runtime_error naming the file if a file cannot be written, and
     * std::invalid_argument if a field does not fit the network.
     */
    void
    write(unsigned int step, double time, const OutputFields &fields);

    /// Writes the state @p u of @p model (see above).
    template <class State>
    void
    write(const unsigned int  step,
          const double        time,
          const Model<State> &model,
          const State        &u)
    {
      write(step, time, model.output_fields(u));
    }

    /// Path of the file of step @p step that the .pvd lists: its .vtu on
    /// one process, its .pvtu on several.
    std::string
    vtu_path(unsigned int step) const;

    /// Path of the piece of step @p step that process @p rank writes on
    /// several processes.
    std::string
    piece_path(unsigned int step, unsigned int rank) const;

    /// Path of the .pvd collection.
    std::string
    pvd_path() const;

  private:
    /// The cells a process writes: active cells first .. end - 1 of the
    /// triangulation, the rank-th of n_pieces even ranges.
    struct Piece
    {
      unsigned int rank;
      unsigned int n_pieces;
      unsigned int first;
      unsigned int end;

      bool
      holds(const unsigned int cell) const
      {
        return cell >= first && cell < end;
      }
    };

    /// This process's piece.
    Piece
    this_piece() const;

    /// A DoFHandler on the network's triangulation that draws values per
    /// vertex (FE_Q 1) or per segment (FE_DGQ 0) with 1 or 3 components,
    /// for fields that are not on a model's own DoFHandler.
    struct FieldSpace
    {
      FieldSpace(const RodNetwork &network,
                 bool              per_segment,
                 unsigned int      components);

      std::unique_ptr<dealii::FiniteElement<1, 3>> fe;
      dealii::DoFHandler<1, 3>                     dofs;
      /// Vertex (or active cell) -> DoF of each component.
      std::vector<std::array<dealii::types::global_dof_index, 3>> index;
    };

    /// The space of fields per segment (or vertex) with @p components
    /// components, made when first asked for.
    const FieldSpace &
    space(bool per_segment, unsigned int components);

    /// The displacement of every vertex as a vector of its FieldSpace;
    /// throws std::invalid_argument if it does not fit the network.
    dealii::Vector<double>
    displacement_vector(const std::vector<Vector3> &displacement);

    /// The values of a vertex (or, @p per_segment, segment) field as a
    /// vector of its FieldSpace, or as cell data for a segment scalar.
    /// Throws std::invalid_argument for a field that does not fit the
    /// network.
    dealii::Vector<double>
    field_vector(const OutputFields::Field &field, bool per_segment);

    /// Adds the displacement of @p fields to @p data_out: the model's
    /// solution, or the vertex displacements (their vector kept in
    /// @p values); returns the mapping that moves the patches by it.
    std::unique_ptr<dealii::Mapping<1, 3>>
    add_displacement(dealii::DataOut<1, 3>               &data_out,
                     std::vector<dealii::Vector<double>> &values,
                     const OutputFields                  &fields);

    /// Adds the vertex and segment fields of @p fields to @p data_out,
    /// their vectors kept in @p values.
    void
    add_fields(dealii::DataOut<1, 3>               &data_out,
               std::vector<dealii::Vector<double>> &values,
               const OutputFields                  &fields);

    /// Writes the patches of @p data_out as the .vtu file (or this
    /// process's piece and the .pvtu) of @p step at @p time and adds it to
    /// the .pvd record.
    void
    write_patches(const dealii::DataOut<1, 3> &data_out,
                  unsigned int                 step,
                  double                       time);

    /// Rewrites the .pvd record with every step written.
    void
    write_pvd_record() const;

    const RodNetwork &network;
    std::string       directory;
    std::string       basename;

    /// (per segment, components) -> its space.
    std::map<std::pair<bool, unsigned int>, std::unique_ptr<FieldSpace>> spaces;

    /// Step -> (load factor, .vtu file name relative to the .pvd).
    std::map<unsigned int, std::pair<double, std::string>> records;
  };
} // namespace rodnet

#endif
