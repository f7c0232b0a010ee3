#ifndef RODNET_IO_SCENE_H
#define RODNET_IO_SCENE_H

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <core/dr_model.h>
#include <core/mass_matrix.h>
#include <core/rod_model.h>
#include <geometry/rod_graph.h>
#include <io/entry_tree.h>
#include <io/natural_shape_ramp.h>
#include <io/network_picture.h>
#include <io/probes.h>
#include <io/problem_size.h>
#include <io/read_notes.h>
#include <io/rigid_body_entries.h>
#include <io/rod_groups.h>
#include <io/scene_families.h>
#include <io/solution_methods.h>
#include <io/substrate.h>
#include <materials/cross_section.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/relaxation/dynamic_relaxation.h>
#include <solvers/statics/static_solver.h>
#include <solvers/time/time_integrator.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * What a user needs of an input error @p e: for deal.II's exceptions
   * (ExcMessage, a pattern mismatch of ParameterHandler, ...) their
   * explanation without the source location and stack trace that what()
   * adds, otherwise what(); on one line.
   */
  std::string
  error_message(const std::exception &e);

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

    /**
     * Declares the subsections a scene names itself, among the titles
     * @p titles of its top-level subsections: "Material <name>", a
     * material with the entries of subsection Material, and "Group
     * <name>", what the rods of a group take (io/rod_groups.h). Other
     * titles are left to the parser. Throws std::invalid_argument for the
     * numbered "Material of group <n>" of earlier scenes, saying what to
     * write instead.
     */
    static void
    declare_named_subsections(dealii::ParameterHandler       &prm,
                              const std::vector<std::string> &titles);

    /// Reads and checks the entries; throws std::invalid_argument naming
    /// the entry for inadmissible values: numbers that are not finite or
    /// beyond max_input_magnitude (in any entry), models that would not fit
    /// in the available memory (before generating them), runs longer than
    /// run_limits allow. @p scene_directory resolves relative mesh file
    /// names.
    Scene(dealii::ParameterHandler &prm,
          const std::string        &scene_directory = ".");

    /// The size of the model that build_model() makes, and the memory a
    /// run of it takes (estimated), known before it is built.
    const ProblemSize &
    size() const;

    /// How many VTU files the run writes if no step is cut: the
    /// recorded steps (step 0 included) divided by the VTU interval.
    double
    planned_vtu_files() const;

    /// Builds the rods, material, supports and loads.
    std::unique_ptr<RodModel>
    build_model() const;

    /**
     * The same rods, supports and loads for the bending-active element of
     * dynamic relaxation. Throws std::invalid_argument for what that element
     * cannot represent: materials other than linear elastic without natural
     * shape, junction moments and prescribed rotations.
     */
    std::unique_ptr<DrModel>
    build_dr_model() const;

    /// The probes of the scene, resolved on @p model.
    ProbeList
    probes(const ModelBase &model) const;

    /**
     * The inertia of every rod of build_model(), rod by rod, from its
     * material group (the groups of build_model()): the group's "Mass per
     * length" and "Twist inertia per length" where given, else rho A and
     * rho (I1 + I2) of its "Density" and cross-section; the mass per length
     * falls back on Loads/Mass per length. The rotary inertia is the
     * group's "Rotary inertia per length", by default half the twist
     * inertia. Throws std::invalid_argument
     * naming the entry where a group in use has neither (e.g. a density
     * with rigidities given directly: no section to take A and I from), or
     * where two of them differ.
     */
    std::vector<RodInertia>
    inertia() const;

    /**
     * Per rod of build_model(): the fiber distances (c1, c2) of its section
     * for the bending about d1 and about d2, 2 sqrt(I1 / A) and
     * 2 sqrt(I2 / A) (the radius of a circle; 1.15 times the half depth of
     * a rectangle in that direction, on the safe side), for the bending
     * strain check (StrainLimits); NaN where the rigidities are given
     * directly and there is no section.
     */
    std::vector<std::array<double, 2>>
    fiber_distances() const;

    /**
     * The start of a time-stepping run on @p model (built by
     * build_model()): @p u and @p v take "Initial displacement" and
     * "Initial velocity" at the undeformed position of every vertex; twists
     * and junction rotations start at zero, and so does the velocity of the
     * supported DoFs. Throws std::invalid_argument naming the entry where a
     * value is not finite.
     */
    void
    initial_state(const RodModel &model, VectorType &u, VectorType &v) const;

    SolutionMethod                method = SolutionMethod::newton;
    StaticSolver::Parameters      solver;
    DynamicRelaxation::Parameters relaxation;
    /// Method = continuation: the path following's settings (the
    /// tolerance and linear solver are those of the Newton entries).
    ArclengthContinuation::Parameters continuation;
    /// Method = time stepping: the integrator's settings; its load_factor
    /// evaluates the scene's "Load factor" expression (and throws
    /// std::invalid_argument naming that entry where it is not finite).
    TimeIntegrator::Parameters time_stepping;
    std::string                output_directory;
    bool                       write_vtu    = true;
    unsigned int               vtu_interval = 1;
    bool                       plot         = true;
    /// picture.png and picture-NNNNN.png (io/network_picture.h).
    PictureOptions picture;
    /// How many of the lowest eigenpairs of the last equilibrium's
    /// tangent to write (io/mode_shapes.h); Newton and continuation.
    unsigned int mode_shapes = 0;
    /// The element families the scene asks for beyond the rods' own
    /// (an elastic foundation, ...).
    std::vector<RequestedFamily> family_requests;
    /// What the generator's reader said of its input: merged coincident
    /// nodes, coarse mesh chains (run_scene() prints it).
    ReadNotes geometry_notes;

  private:
    /// What a material subsection defines.
    struct SceneMaterial
    {
      std::shared_ptr<const RodMaterial> material;
      /// The subsection, for messages ("Material", "Material soft").
      std::string subsection;
      /// The subsection of the material model within it.
      std::string model;
      /// kg/m^3; 0 when not given.
      double density = 0;
      /// "Mass per length" rho A (kg/m); 0 when not given.
      double mass_per_length = 0;
      /// "Twist inertia per length" (kg m); 0 when not given.
      double twist_inertia_per_length = 0;
      /// "Rotary inertia per length" (kg m); empty for "auto" (half the
      /// twist inertia per length).
      std::optional<double> rotary_inertia_per_length;
      /// Whether the rods keep their segments' lengths (Rod::inextensible).
      bool inextensible = false;
      /// Empty where the rigidities are given directly.
      std::optional<CrossSection> section;
    };

    /// Checks the size of what will be built (ProblemSize) against the
    /// memory, naming the entry; returns it with its bytes per DoF.
    using SizeCheck =
      std::function<ProblemSize(ProblemSize, const std::string &)>;

    /// Subsection Geometry: the entries every generator shares, then those
    /// of each registered generator (GeneratorRegistry).
    static void
    declare_geometry(dealii::ParameterHandler &prm);
    /// Subsection Material with the entries of every registered material.
    static void
    declare_materials(dealii::ParameterHandler &prm);
    static void
    declare_supports(dealii::ParameterHandler &prm);
    static void
    declare_loads(dealii::ParameterHandler &prm);
    /// Subsection Solver: "Method" and the entries of every solution
    /// method (solution_methods()), then the initial state.
    static void
    declare_solver(dealii::ParameterHandler &prm);
    /// "Initial displacement" and "Initial velocity" of subsection
    /// Time stepping (current: Solver).
    static void
    declare_initial_state(dealii::ParameterHandler &prm);
    static void
    declare_output(dealii::ParameterHandler &prm);

    /// Makes the rods or the network of the generator that subsection
    /// Geometry names, refusing with @p check_size what cannot fit.
    void
    parse_geometry(dealii::ParameterHandler &prm,
                   const std::string        &scene_directory,
                   const SizeCheck          &check_size);
    /// Reads subsection Material and every "Material <name>"; @p entries
    /// (entry_tree() of @p prm) shows which entries a material subsection
    /// sets.
    void
    parse_materials(dealii::ParameterHandler &prm, const EntryNode &entries);

    /**
     * Reads every "Group <name>" subsection of @p entries and gives each
     * rod its material (rod_material), and each beam of a network its
     * director and segments. Throws std::invalid_argument naming the
     * subsection for what io/rod_groups.h refuses, an unknown material, a
     * named material no rod takes, a director or segments given to rods
     * that are not a network's beams, segments given to a mesh's chain,
     * and a director parallel to a beam.
     */
    void
    parse_rod_groups(dealii::ParameterHandler &prm, const EntryNode &entries);

    /// Gives beam @p b of the network the director @p d1 of group
    /// @p group; refused where there is no network or d1 is parallel to
    /// the beam (@p describe names it).
    void
    orient_beam(unsigned int                                    b,
                const Vector3                                  &d1,
                const std::string                              &group,
                const std::function<std::string(unsigned int)> &describe);

    /// Gives beam @p b of the network @p segments segments, of group
    /// @p group; refused where there is no network or the beam is a mesh's
    /// chain.
    void
    split_beam(unsigned int                                    b,
               unsigned int                                    segments,
               const std::string                              &group,
               const std::function<std::string(unsigned int)> &describe);

    /// "beam 3 (n1 to n2)" of a network, "rod 3" otherwise, for messages.
    std::string
    rod_name(unsigned int r) const;

    /// The groups of every rod (RodGraph::Beam::groups: beam b is rod b);
    /// none for rods that are not a network's beams.
    std::vector<std::vector<std::string>>
    groups_of_rods() const;

    /**
     * Adds the activation fields of the groups (rod_activation) to
     * @p model, each rod's arc length from its start (after the half
     * segment behind it under a midpoint clamp). Throws
     * std::invalid_argument naming the entry and the rod for a region past
     * the rod's length, values not finite on the rod, an eigenstrain of an
     * inextensible rod and a field on a developable ribbon.
     */
    void
    add_activation_fields(RodModel &model) const;

    /// Whether a group gives a rod a ramped activation field (or, with
    /// @p in_time_too, one driven by a function of time).
    bool
    ramps_activation(bool in_time_too = false) const;

    /// Throws naming the entry and the item for an activation field driven
    /// by a function of time outside time stepping, or one not finite at
    /// a time a step ends on.
    void
    check_activation_drives() const;

    /// Throws @p what (which names the entry and item) " in time stepping
    /// only; set Solver/Method = time stepping, or " @p instead outside
    /// time stepping; evaluates @p f at the times the steps end on, where
    /// it throws if not finite.
    void
    check_time_function(const std::function<double(double)> &f,
                        const std::string                   &what,
                        const std::string                   &instead) const;

    /// The value of the item "<name>: <value>" of the support entry
    /// @p entry without its "in time <f(t)>" into @p rest, and that function
    /// (empty if none), checked by check_time_function().
    TimeFunction
    support_in_time(const std::string &entry,
                    const std::string &name,
                    const std::string &value,
                    std::string       &rest) const;

    /// The index in scene_materials of the material @p rod takes.
    unsigned int
    material_index(const RodSettings &rod) const;
    void
    parse_supports(dealii::ParameterHandler &prm);
    /// Subsection Loads, and "Steps" into solver.n_steps.
    void
    parse_loads(dealii::ParameterHandler &prm);
    /// Whether the load factor ramps a natural shape, an activation field,
    /// the substrate or a prescribed displacement or rotation (an item
    /// without "in time"); with @p in_time_too, also whether an activation
    /// field or a prescribed displacement or rotation follows a function of
    /// time.
    bool
    moves_shape_or_support(bool in_time_too) const;
    /// Throws naming Loads/Imperfections/Magnitude where the imperfections
    /// cannot follow it: ramped while Loads/Fixed loads holds every load,
    /// held while nothing else moves (no load, natural shape, activation
    /// field, substrate strain, prescribed displacement or rotation).
    void
    check_imperfection_ramp() const;
    /// Subsection Solver: the method and the parameters of every method.
    void
    parse_solver(dealii::ParameterHandler &prm);
    void
    parse_output(dealii::ParameterHandler &prm);

    /// Reads Solver/Time stepping (and the Newton entries of Solver).
    void
    parse_time_stepping(dealii::ParameterHandler &prm);

    /// The material of subsection @p title (current).
    static SceneMaterial
    parse_material(dealii::ParameterHandler &prm,
                   const EntryNode          &entries,
                   const std::string        &title);

    /// Throws std::invalid_argument naming the entry unless the scene can
    /// be time stepped: a positive step, an end after the start, densities
    /// and sections for inertia, no midpoint rule with a history material.
    void
    check_time_stepping() const;

    /// Throws std::invalid_argument naming the entry for a negative
    /// damping coefficient, or damping in a quasi-static run.
    void
    check_damping() const;

    /// The steps a run takes if none is cut: load steps, or time steps
    /// with the preload steps.
    double
    planned_steps() const;

    /// Throws std::invalid_argument naming the entry if the run would
    /// exceed run_limits: load steps, time steps, VTU files.
    void
    check_run_length() const;

    /// The material (index in scene_materials) of every rod of
    /// build_network(), rod by rod.
    std::vector<unsigned int> rod_material;

    /// The activation items of every rod of build_network(), rod by rod.
    std::vector<std::vector<ActivationItem>> rod_activation;

    /// Segments of every rod of build_network(), rod by rod.
    std::vector<double>
    rod_segments() const;

    /// The size of the rods and junctions that build_network() makes.
    ProblemSize
    geometry_size() const;

    /// The DoFs of the constraints of the rods' materials
    /// (ProblemSize::constraint_dofs).
    double
    constraint_dofs() const;

    /// The rods (or the network's rods) and the material of each.
    std::pair<std::unique_ptr<RodNetwork>,
              std::vector<std::shared_ptr<const RodMaterial>>>
    build_network() const;

    /// Throws naming the entry for what the bending-active element of
    /// dynamic relaxation cannot model: a clamp at a segment's midpoint,
    /// element families, natural shapes, constraints, a rigid body's
    /// centre off its vertex.
    void
    refuse_for_dr_element() const;

    /// Throws naming the entry for loads that dynamic relaxation, which
    /// ramps every load, cannot apply: fixed or held ones.
    void
    refuse_for_dr_loading() const;

    /// Throws naming the entry unless the start of every rod is clamped
    /// (the rods begin half a segment behind it, see
    /// "Clamp at first segment midpoint").
    void
    check_midpoint_clamps(const RodModel &model) const;

    /// Ramps the natural shape of @p model as Loads/Ramped natural shape
    /// says, naming the entry in errors.
    void
    ramp_natural_shape(RodModel &model) const;
    /// Rotation handles (RodNetwork::add_rotation_handle()) at the free
    /// vertices that moments and prescribed rotations name, and where a
    /// rigid body's rotary inertia needs one (rigid_body_handle_vertex()).
    void
    add_rotation_handles(RodNetwork &network) const;

    /// The supports and loads of the scene on @p network, which every
    /// model lowers (Model::apply()).
    SupportsAndLoads
    supports_and_loads(const RodNetwork &network) const;

    /// The clamped ends and junctions into @p spec.
    void
    add_clamps(const RodNetwork &network, SupportsAndLoads &spec) const;

    /// Prescribed rotations and moments into @p spec.
    void
    add_rotational_loads(const RodNetwork &network,
                         SupportsAndLoads &spec) const;

    /// Pinned vertices, fixed components and prescribed displacements into
    /// @p spec.
    void
    add_position_supports(const RodNetwork &network,
                          SupportsAndLoads &spec) const;

    /// Point forces, distributed forces and the weight (of the rods and
    /// the rigid bodies) into @p spec.
    void
    add_forces(const RodNetwork &network, SupportsAndLoads &spec) const;

    /**
     * The mass per length that gravity weighs of the rods of material
     * group @p group (rod_mass_per_length()). Throws
     * std::invalid_argument naming the entries where two are given and
     * differ (by more than 1e-6 relative) and where none is.
     */
    double
    mass_per_length_of(const SceneMaterial &group) const;

    /**
     * The mass per length of the rods of @p group, for gravity and time
     * stepping alike: the group's "Mass per length", else Density times the
     * section's area, else Loads/Mass per length; empty where none is
     * given. Throws std::invalid_argument naming the entry where two that
     * are given differ by more than 1e-6 relative.
     */
    std::optional<double>
    rod_mass_per_length(const SceneMaterial &group) const;

    /// The inertia of the rods of @p group for time stepping (inertia()).
    RodInertia
    inertia_of(const SceneMaterial &group) const;

    /// mass_per_length_of() the group of every rod of build_network(),
    /// rod by rod.
    std::vector<double>
    masses_per_length() const;

    std::vector<std::vector<Vector3>> rod_points;
    std::vector<bool>                 rod_closed;
    Vector3                           director_hint;
    std::string                       hinge_kernel;
    /// Geometry/Frame half turns, of the closed rods.
    unsigned int frame_half_turns = 0;
    NaturalShape natural_shape    = NaturalShape::initial_geometry;
    /// Every rod begins half a segment behind its start (midpoint clamp).
    bool midpoint_clamp = false;
    /// Networks: the beams and junctions, built into rods by build_model().
    std::optional<RodGraph> graph;
    unsigned int            segments_per_beam = 1;
    GhostSpin               ghost_spin        = GhostSpin::exact;
    /// Subsection Material (first) and every "Material <name>".
    std::vector<SceneMaterial> scene_materials;
    /// Time stepping: displacement and velocity fields of the undeformed
    /// position x, y, z (three components each).
    std::shared_ptr<const dealii::Function<3>> initial_displacement,
      initial_velocity;
    std::string clamped_ends, pinned_vertices, fixed_components,
      prescribed_displacements, prescribed_rotations, point_forces, moments,
      probe_text;
    Vector3 distributed_force, gravity;
    /// Loads/Mass per length; 0 when not given.
    double mass_per_length;
    /// Loads/Rigid bodies, as written (placed on a network by
    /// place_rigid_body()).
    std::vector<RigidBodyItem> rigid_body_items;
    /// Under gravity: the mass per length of every rod (masses_per_length());
    /// empty without gravity.
    std::vector<double> rod_masses;
    /// Loads/Ramped natural shape, if set.
    std::optional<NaturalShapeRamp> natural_shape_ramp;
    /// Loads/Fixed loads.
    bool fixed_loads = false;
    /// Subsection Substrate: bonding sites that follow a substrate.
    Substrate substrate;
    /// Loads/Imperfections: point forces and moments (the syntax of
    /// Loads/Point forces and Loads/Moments) and how they follow the load
    /// factor.
    std::string imperfection_forces, imperfection_moments;
    LoadRamp    imperfection_ramp = LoadRamp::held;
    ProblemSize model_size;
    /// The entry a message about the model's size names
    /// (GeometryGenerator::size_entry()).
    std::string model_size_entry;
  };
} // namespace rodnet

#endif
