#ifndef RODNET_IO_VTU_OUTPUT_H
#define RODNET_IO_VTU_OUTPUT_H

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <core/rod_model.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * Writes converged states of a RodModel as a ParaView time series: one
   * file `<directory>/<basename>-NNNNN.vtu` per step and the collection
   * `<directory>/<basename>.pvd` listing every step written so far, with the
   * load factor (static runs) or the time (time stepping) as its "time".
   * Cells are drawn in the deformed
   * configuration. The fields are
   * - "displacement" (vector) and "twist" (per segment, the twist DoF),
   *   straight from the DoF vector;
   * - per segment: "axial_strain" (engineering strain) and the current
   *   directors "d1" and "d2" (vectors);
   * - per vertex, from the hinge at that vertex and zero at rod ends:
   *   "curvature" = (kappa_1, kappa_2, 0) / l, the bending curvatures about
   *   d1 and d2 in material components, and "twist_rate" = kappa_3 / l,
   *   with l the hinge's undeformed Voronoi length;
   * - for history-dependent materials, their committed internal variables,
   *   one field per name ("viscous_curvature_1", ...): hinge variables per
   *   vertex (zero at rod ends), segment variables per segment.
   *
   * deal.II's VTU writer stores every value as a 32-bit float, which is
   * enough to look at but not to restart from. The model must outlive this
   * object.
   */
  class VtuOutput
  {
  public:
    /**
     * Creates @p directory (and its parents) if needed; throws
     * std::runtime_error naming the path if it cannot.
     */
    VtuOutput(const RodModel    &model,
              const std::string &directory,
              const std::string &basename = "solution");

    /**
     * Writes the state @p u of step @p step at load factor (or time)
     * @p load_factor
     * and rewrites the .pvd record, both before returning, so that a later
     * failure loses no converged step. Writing the same step again replaces
     * its entry. In a parallel run only rank 0 of @p u's communicator
     * writes; @p u must hold every entry on it. Throws std::runtime_error
     * naming the file if a file cannot be written.
     */
    void
    write(unsigned int step, double load_factor, const VectorType &u);

    /// Path of the .vtu file of step @p step.
    std::string
    vtu_path(unsigned int step) const;

    /// Path of the .pvd collection.
    std::string
    pvd_path() const;

  private:
    const RodModel &model;
    std::string     directory;
    std::string     basename;

    /// Vertex vector fields: the displacement that drives the Eulerian
    /// mapping (which wants exactly spacedim components) and "curvature".
    dealii::FESystem<1, 3>   vertex_vector_fe;
    dealii::DoFHandler<1, 3> vertex_vector_dofs;
    /// Vertex scalar field "twist_rate".
    dealii::FE_Q<1, 3>       vertex_scalar_fe;
    dealii::DoFHandler<1, 3> vertex_scalar_dofs;
    /// Segment vector fields "d1" and "d2": deal.II's cell data are
    /// scalars only, so vectors per cell need a DG0 system.
    dealii::FESystem<1, 3>   segment_vector_fe;
    dealii::DoFHandler<1, 3> segment_vector_dofs;

    /// Triangulation vertex -> DoFs of its three components.
    std::vector<std::array<global_dof_index, 3>> vertex_vector_index;
    /// Triangulation vertex -> DoF.
    std::vector<global_dof_index> vertex_scalar_index;
    /// Active cell -> DoFs of its three components.
    std::vector<std::array<global_dof_index, 3>> segment_vector_index;

    /// Step -> (load factor, .vtu file name relative to the .pvd).
    std::map<unsigned int, std::pair<double, std::string>> records;
  };
} // namespace rodnet

#endif
