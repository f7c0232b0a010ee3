#ifndef RODNET_IO_SCENE_H
#define RODNET_IO_SCENE_H

#include <deal.II/base/parameter_handler.h>

#include <core/dr_model.h>
#include <core/rod_graph.h>
#include <core/rod_model.h>
#include <io/probes.h>
#include <solvers/dynamic_relaxation.h>
#include <solvers/static_solver.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /// A scene built for dynamic relaxation: the model and the network it
  /// refers to.
  struct DrScene
  {
    std::unique_ptr<RodNetwork> network;
    std::unique_ptr<DrModel>    model;
  };

  /// How a scene is solved.
  enum class SolutionMethod
  {
    newton,             ///< discrete rods and junctions, StaticSolver
    dynamic_relaxation, ///< bending-active element, DynamicRelaxation
  };

  /**
   * A scene file: geometry, material, supports, loads, solver and output
   * settings, as a deal.II ParameterHandler input (.prm or .json). Every
   * entry carries a pattern, a unit and a help text; `rodnet-run --help`
   * prints them all.
   *
   * Usage: declare_parameters(prm); prm.parse_input(file); then
   * Scene scene(prm); auto model = scene.build_model(); ...
   */
  class Scene
  {
  public:
    /// Declares every entry of a scene, with defaults.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Reads and checks the entries; throws std::invalid_argument naming
    /// the entry for inadmissible values. @p scene_directory resolves
    /// relative mesh file names.
    Scene(dealii::ParameterHandler &prm,
          const std::string        &scene_directory = ".");

    /// Builds the rods, material, supports and loads.
    std::unique_ptr<RodModel>
    build_model() const;

    /**
     * The same rods, supports and loads for the bending-active element of
     * dynamic relaxation. Throws std::invalid_argument for what that element
     * cannot represent: materials other than linear elastic without natural
     * shape, junction moments and prescribed rotations.
     */
    DrScene
    build_dr_model() const;

    /// The probes of the scene, resolved on @p model.
    std::vector<Probe>
    probes(const RodModel &model) const;
    std::vector<Probe>
    probes(const DrModel &model) const;

    SolutionMethod                method = SolutionMethod::newton;
    StaticSolver::Parameters      solver;
    DynamicRelaxation::Parameters relaxation;
    std::string                   output_directory;
    bool                          write_vtu    = true;
    unsigned int                  vtu_interval = 1;
    bool                          plot         = true;

  private:
    /// The rods (or the network's rods) and the material of each.
    std::pair<std::unique_ptr<RodNetwork>,
              std::vector<std::shared_ptr<const RodMaterial>>>
    build_network() const;

    /// Supports and loads of the scene, onto a RodModel or a DrModel.
    template <class Model>
    void
    apply_supports_and_loads(Model &model) const;

    std::vector<std::vector<Vector3>> rod_points;
    std::vector<bool>                 rod_closed;
    Vector3                           director_hint;
    std::string                       hinge_kernel;
    /// Networks: the beams and junctions, built into rods by build_model().
    std::optional<RodGraph> graph;
    unsigned int            segments_per_beam = 1;
    GhostSpin               ghost_spin        = GhostSpin::exact;
    /// Material of each material group (group 0: every plain rod).
    std::vector<std::shared_ptr<const RodMaterial>> group_materials;
    std::string clamped_ends, pinned_vertices, fixed_components,
      prescribed_displacements, prescribed_rotations, point_forces, moments,
      probe_text;
    Vector3 distributed_force, gravity;
    double  mass_per_length;
  };
} // namespace rodnet

#endif
