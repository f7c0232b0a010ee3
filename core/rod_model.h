#ifndef RODNET_CORE_ROD_MODEL_H
#define RODNET_CORE_ROD_MODEL_H

#include <deal.II/base/index_set.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <core/configuration.h>
#include <core/dead_loads.h>
#include <core/direct_scatter.h>
#include <core/dof_layout.h>
#include <core/dof_values.h>
#include <core/element_family.h>
#include <core/internal_variables.h>
#include <core/model.h>
#include <core/model_state.h>
#include <core/rigid_body.h>
#include <core/rod_network.h>
#include <core/scatter_positions.h>
#include <core/solvable_model.h>
#include <core/stencil_coloring.h>
#include <core/stencil_ownership.h>
#include <core/system_block.h>
#include <elements/hinge_kernel.h>
#include <materials/rod_material.h>

#include <Epetra_Import.h>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * A rod network with materials, supports and dead loads: the object a
   * driver or a user's deal.II program works with. It owns the DoF layout,
   * the configuration (undeformed and reference data) and the current DoF
   * vector, and evaluates the total potential energy
   *   Phi(u) = sum_hinges W + sum_segments W + sum_junction_elements W
   *            - lambda f . x - lambda sum_moments M theta_u(q)
   * with its gradient (the residual) and Hessian (the tangent).
   *
   * Junctions of the network bring their supports with them: a clamped
   * junction fixes its position and rotation, a welded-and-pinned one its
   * position; each is a Support named after the junction. The scale of
   * every junction quaternion is a gauge freedom (the kernels see q/|q|):
   * its real part is held at 1, so increments are q = (1, v), which
   * covers every rotation below 180 degrees per step (see
   * doc/junctions.md).
   *
   * Usage: construct, add supports and loads, call finalize(), then
   * assemble / solve (see StaticSolver) and reset_reference() after each
   * converged step.
   *
   * History-dependent materials (RodMaterial with internal variables) make
   * the energy the condensed incremental potential of one time step: set
   * the step with set_time_step() before assembling, and after the step has
   * converged call commit_internal_variables() (see TimeIntegrator, which
   * does both). Static load stepping refuses such models.
   *
   * RodModel implements the Model interface, through which probes, output
   * and the scene runner see it, and the SolvableModel interface, through
   * which the solvers do.
   */
  class AxisMomentFamily;

  class RodModel final : public SolvableModel
  {
  public:
    /**
     * @p materials holds one material per rod of @p network (shared
     * pointers: rods may share one). Hinge kernels are created from the
     * rods' kernel names. The model's vectors and matrices live on
     * @p communicator (finalize() says which DoFs this process owns).
     */
    RodModel(std::unique_ptr<RodNetwork>                     network,
             std::vector<std::shared_ptr<const RodMaterial>> materials,
             GhostSpin      ghost_spin   = GhostSpin::exact,
             const MPI_Comm communicator = MPI_COMM_WORLD);

    /**
     * @name Supports (before finalize())
     *
     * A support holds DoFs at values that are ramped with the load factor.
     * The same DoF may be held by several supports only at the same value:
     * finalize() refuses two different values, naming both supports. A
     * clamp (clamp_end(), a clamped junction, clamp_junction()) moves
     * rigidly: the displacement that fix_components() prescribes at its
     * end vertex translates it, a prescribed rotation turns it about that
     * vertex (doc/junctions.md, "Supports").
     */
    /// @{
    /**
     * Clamps the first (or last) end of rod @p rod by holding its end
     * segment: both its vertices and its twist (Korner et al. section 5a).
     * The clamp moves rigidly with its end vertex (see above and
     * rotate_clamp()). A rod of a single segment is refused: the clamp
     * would hold it whole, and every load on it would vanish into the
     * support.
     */
    void
    clamp_end(const std::string &name,
              unsigned int       rod,
              bool               at_start) override;

    /// Turns the clamp called @p name (clamp_end()), and every other clamp
    /// of the same rod end, rigidly about its end vertex by @p angle (rad)
    /// about the unit @p axis at load factor 1, ramped with the load factor
    /// (or @p angle times the function of time @p in_time).
    void
    rotate_clamp(const std::string  &name,
                 const Vector3      &axis,
                 double              angle,
                 const TimeFunction &in_time = {});

    /**
     * Holds junction @p junction as a clamped junction: its position
     * (moved by fix_components() at its vertex) and its rotation (the
     * identity, or prescribe_rotation()); a support called @p name. A
     * pinned junction has no rotation of its own and is refused.
     */
    void
    clamp_junction(const std::string &name, unsigned int junction) override;

    /// Fixes the masked position components of @p vertex; their value
    /// moves with the load factor to @p displacement (at load factor 1).
    /// At the end vertex of a clamp or the vertex of a junction that holds
    /// its position this moves the clamp or junction.
    void
    fix_components(const std::string         &name,
                   unsigned int               vertex,
                   const std::array<bool, 3> &mask,
                   const Vector3 &displacement = Vector3::Zero()) override;

    /// As fix_components(), the value @p displacement times the function
    /// of time @p in_time (RodModel::set_time(), time stepping) instead of
    /// the load factor: a support moving in time.
    void
    move_components(const std::string         &name,
                    unsigned int               vertex,
                    const std::array<bool, 3> &mask,
                    const Vector3             &displacement,
                    const TimeFunction        &in_time) override;

    /**
     * Lowers prescribed rotations and moments: at the end vertex of a clamp
     * (clamp_end()) a rotation turns the clamp (rotate_clamp()) and a moment
     * is refused (the clamp would take it up whole); elsewhere they act on
     * the junction there (prescribe_rotation(), add_moment()).
     */
    void
    add_rotational_loads(
      const std::vector<SupportsAndLoads::AxisLoad> &rotations,
      const std::vector<SupportsAndLoads::AxisLoad> &moments) override;
    /// @}

    /**
     * Ramps the parts @p parts of the natural shape of the rods @p rods
     * with the load factor, as the loads are: at load factor lambda their
     * materials' natural curvatures, twist or axial eigenstrain are lambda
     * times the given ones (RodMaterial::with_natural_shape_scaled()), so
     * that load stepping and continuation follow a structure as its
     * natural shape grows (before finalize()). Throws
     * std::invalid_argument naming the rod where its material has no
     * natural shape, or a rod that does not exist.
     */
    void
    ramp_natural_shape(const NaturalShapeParts         &parts,
                       const std::vector<unsigned int> &rods);

    /**
     * Adds the activation field @p field to rod @p rod
     * (Configuration::add_activation(): natural curvatures, twist and axial
     * eigenstrain along the rod), ramped with the load factor as the
     * natural shape of ramp_natural_shape() is, held fixed, or scaled by
     * its own function of time (set_time(); before finalize()). Fields
     * add. Throws std::invalid_argument naming the rod for an eigenstrain
     * of an inextensible rod or any field of a developable ribbon.
     */
    void
    add_activation(unsigned int           rod,
                   const ActivationField &field,
                   const ActivationDrive &drive);

    /**
     * The time (s) of the assemblies that follow, at which the activation
     * fields driven by functions of time are evaluated (TimeIntegrator sets
     * it), and of apply_boundary_values() for supports moving in time;
     * those fields are zero until it is set. Throws
     * std::invalid_argument where such a function has no finite value.
     */
    void
    set_time(double time) override;

    /// The factors of the activation fields driven by functions of time,
    /// one per function, at the last set_time() (empty if none).
    std::vector<double>
    activation_time_factors() const override;

    /**
     * Whether the potential Pi(u, lambda) at a given state u changes with
     * the load factor lambda: nonzero dead loads or applied moments ramped
     * by it (not fix_loads()), a ramped natural shape or activation field.
     * Supports ramped by it move the held values of u, not Pi. The model
     * must be finalized.
     */
    bool
    potential_follows_load_factor() const override;

    /// Whether the potential at a given state changes with the time of
    /// set_time(): activation fields driven by functions of time.
    bool
    potential_follows_time() const override;

    /**
     * Holds the dead loads and the applied moments at their full value at
     * every load factor, which then ramps only the prescribed displacements
     * and rotations and the ramped natural shape: a natural shape that grows
     * (or a support that moves) under a load that is there all along
     * (before finalize()).
     */
    void
    fix_loads();

    /// The factor on the dead loads and applied moments at @p load_factor:
    /// @p load_factor, or 1 where the loads are fixed (fix_loads()).
    double
    applied_load_factor(double load_factor) const override
    {
      return loads_fixed ? 1.0 : load_factor;
    }

    /// @name Dead loads at load factor 1 (before finalize())
    /// @{
    void
    add_point_force(unsigned int vertex, const Vector3 &force) override;

    /// A point force at its full value at every load factor, ramped
    /// neither by the load factor nor with the other loads (an
    /// imperfection, LoadRamp::held).
    void
    add_held_point_force(unsigned int vertex, const Vector3 &force) override;

    /// Force per unit undeformed length on rod @p rod, lumped to the
    /// vertices by their Voronoi lengths (DeadLoads::vertex_forces()).
    void
    add_distributed_force(unsigned int   rod,
                          const Vector3 &force_per_length) override;

    /**
     * Moment @p moment about the fixed unit @p axis at junction
     * @p junction (Lestringant & Kochmann appendix C): the load potential
     * -lambda M theta_u(q), q the junction's rotation since the undeformed
     * state (AxisMomentFamily). The junction must have a free rotation:
     * finalize() refuses one whose rotation is held. A moment at a rod end
     * or inside a rod acts on a rotation handle there
     * (RodNetwork::add_rotation_handle()). A moment with @p ramp
     * LoadRamp::held keeps its full value at every load factor (-M
     * theta_u(q), an imperfection).
     */
    void
    add_moment(unsigned int   junction,
               const Vector3 &axis,
               double         moment,
               LoadRamp       ramp = LoadRamp::ramped);

    /**
     * Turns junction @p junction about the unit @p axis by @p angle (rad)
     * at load factor 1, ramped with the load factor, and holds its
     * rotation there. The junction must carry a rotation; its position
     * stays as its kind says (free for a welded junction, e.g. a rotation
     * handle at a free rod end). Prescribing a junction twice is refused
     * unless both rotations are the same. With @p in_time the angle is
     * @p angle times that function of time instead of the load factor.
     */
    void
    prescribe_rotation(unsigned int        junction,
                       const Vector3      &axis,
                       double              angle,
                       const TimeFunction &in_time = {});

    /// As above, the rotation at load factor 1 given as a unit quaternion
    /// (a non-unit one is refused: it is not a rotation).
    void
    prescribe_rotation(unsigned int junction, const Quaternion &rotation);
    /// @}

    /**
     * Attaches the rigid body @p body (before finalize()): its inertia
     * enters the mass matrix (assemble_mass_matrix(), add_rigid_body_mass());
     * its weight is a load like any other (rigid_body_weight()). Throws
     * std::invalid_argument naming the body for what check_rigid_body()
     * refuses.
     */
    void
    add_rigid_body(const RigidBody &body);

    /// The rigid bodies attached (add_rigid_body()).
    const std::vector<RigidBody> &
    rigid_bodies() const override
    {
      return bodies;
    }

    /**
     * Adds @p family to the energy (before finalize()): an elastic
     * foundation, or any other ElementFamily. The hinges, segments and
     * junction elements of the rods and the applied moments are families
     * the model makes itself.
     */
    void
    add_element_family(std::unique_ptr<ElementFamily> family);

    /// The families of the energy, in the order they are assembled.
    const std::vector<std::unique_ptr<ElementFamily>> &
    element_families() const override
    {
      return families;
    }

    /// Builds constraints, sparsity pattern, matrices and vectors. On one
    /// process it owns every DoF; on a communicator of P processes each
    /// owns a contiguous range of the DoFs, the ranges cut so that each
    /// process evaluates about as many stencils (balanced_share()).
    void
    finalize() override;

    /**
     * As finalize(), with the DoFs this process owns given by the caller:
     * a contiguous range of 0 .. layout().n_dofs() - 1, the ranges of the
     * communicator's processes a partition of all DoFs in rank order (as
     * Trilinos' maps and MUMPS's distributed input take them); otherwise
     * std::invalid_argument on every process. Every process holds the whole
     * network; on several, assemble() and elastic_energy() evaluate only
     * the stencils that couple the process's DoFs (doc/architecture.md,
     * "Several processes").
     */
    void
    finalize(const dealii::IndexSet &locally_owned_dofs);

    /**
     * Energy at DoF vector @p u and load factor @p load_factor; adds the
     * gradient into @p residual and the Hessian into @p tangent where they
     * are not null (both are zeroed first). With @p apply_constraints the
     * rows and columns of fixed DoFs are eliminated (Newton increments are
     * zero there); without, the residual holds the reaction forces there.
     * A non-null @p extra_force is a further dead force, not scaled by the
     * load factor (solvers use it to push a state off an unstable branch).
     * Thread-parallel over stencils.
     */
    double
    assemble(const VectorType &u,
             double            load_factor,
             VectorType       *residual,
             MatrixType       *tangent,
             bool              apply_constraints = true,
             const VectorType *extra_force       = nullptr) const override;

    /**
     * As assemble(), into the rows and columns @p block of a caller's
     * system (a block of a coupled problem): adds the gradient into
     * @p residual and the Hessian into @p tangent where they are not null,
     * without zeroing them first (the caller's own terms stay), and returns
     * the energy. @p tangent must have the entries of
     * add_sparsity_pattern() for @p block. With @p apply_constraints the
     * rows of the DoFs that the model fixes (and the junction copies) get
     * a diagonal entry and no other, and their residual is zero. Throws
     * std::invalid_argument if @p block does not place every DoF.
     */
    double
    assemble_into(const VectorType  &u,
                  double             load_factor,
                  const SystemBlock &block,
                  VectorType        *residual,
                  MatrixType        *tangent,
                  bool               apply_constraints = true) const;

    /// Adds every pair of DoFs that a stencil couples, and the diagonal,
    /// at the rows and columns @p block into @p pattern.
    void
    add_sparsity_pattern(dealii::DynamicSparsityPattern &pattern,
                         const SystemBlock              &block) const;

    /**
     * The values of @p u on the DoFHandler (positions and twists, without
     * the quaternion block), with the junction constraints distributed: a
     * finite element vector on layout().dof_handler() for deal.II's
     * FEValues and DataOut.
     */
    dealii::Vector<double>
    field_values(const VectorType &u) const;

    /// Elastic energy alone at @p u: no potential of the dead loads and
    /// applied moments (fixed or not), the ramped rods' natural shape at
    /// @p load_factor.
    double
    elastic_energy(const VectorType &u, double load_factor) const override;

    /// Sets the fixed DoFs of @p u to their values at @p load_factor (and,
    /// for supports moving in time, at the time of the last set_time()).
    void
    apply_boundary_values(VectorType &u, double load_factor) const override;

    /**
     * Sets the fixed DoFs of @p u to their values at @p load_factor and at
     * @p time (supports moving in time; doc/dynamics.md, "Moving
     * supports"). Throws std::runtime_error where a prescribed rotation
     * (of a junction or a clamp) would turn by 180 degrees or more from
     * @p u: the increments of one step cannot (doc/junctions.md, "Gauge").
     */
    void
    apply_boundary_values(VectorType &u,
                          double      load_factor,
                          double      time) const override;

    /**
     * Throws std::runtime_error naming the support where a prescribed
     * rotation (of a junction or a clamp) turns by half a turn or more
     * from (@p load_factor_0, @p time_0) to (@p load_factor_1, @p time_1):
     * the increment of one step, which a quaternion increment (1, v) cannot
     * reach and an orientation alone cannot tell from the opposite turn
     * (doc/junctions.md, "Gauge").
     */
    void
    check_rotation_step(double load_factor_0,
                        double time_0,
                        double load_factor_1,
                        double time_1) const override;

    /**
     * The same for a load step from @p load_factor_0 to @p load_factor_1
     * (static load stepping, where no time passes: a support moving in
     * time stays). Without it a step of 360 degrees would leave the
     * support where it was, and one of 240 would turn it by -120.
     */
    void
    check_rotation_step(double load_factor_0,
                        double load_factor_1) const override;

    /// Whether a support moves by its own function of time.
    bool
    moves_supports_in_time() const override;

    /// The factors of the supports moving in time at @p time, one per
    /// support (empty if none moves in time).
    std::vector<double>
    support_time_factors(double time) const;

    /// Current position of vertex @p vertex at @p u.
    Vector3
    position(const VectorType &u, unsigned int vertex) const override
    {
      return configuration_->position(u, vertex);
    }

    /// Rotation of junction @p junction at @p u from the undeformed state.
    Quaternion
    junction_rotation(const VectorType &u, unsigned int junction) const override
    {
      return configuration_->junction_rotation(u, junction);
    }

    bool
    has_junction_rotations() const override
    {
      return true;
    }

    bool
    has_rotation(unsigned int junction) const override
    {
      return layout_->has_rotation_dofs(junction);
    }

    bool
    has_tangent() const override
    {
      return true;
    }

    /**
     * The displacement and, per segment, "twist" (the twist DoF),
     * "axial_strain" (engineering strain) and the current directors "d1"
     * and "d2"; per vertex, from the hinge at that vertex and zero at rod
     * ends, "curvature" = (kappa_1, kappa_2, 0) / l, the bending curvatures
     * about d1 and d2 in material components, and "twist_rate" =
     * kappa_3 / l, with l the hinge's undeformed Voronoi length; for
     * history-dependent materials their committed internal variables, one
     * field per name ("viscous_curvature_1", ...): hinge variables per
     * vertex (zero at rod ends), segment variables per segment.
     */
    OutputFields
    output_fields(const VectorType &u) const override;

    /// Makes @p u the reference configuration; its quaternion DoFs return
    /// to the identity (their rotation moves into the reference).
    void
    reset_reference(VectorType &u) override;

    /// Reaction force of support @p s at the converged @p u.
    Vector3
    reaction(const Support    &s,
             const VectorType &u,
             double            load_factor) const override;

    /**
     * Reaction moment of support @p s at the converged @p u about its
     * first vertex (a clamp's end vertex): the moment of the reaction
     * forces, and for a clamp the torque conjugate to its twist,
     * M = sum_k (x_k - x_0) x F_k + r_phi t, the moment conjugate to a
     * rigid rotation of the support.
     */
    Vector3
    reaction_moment(const Support    &s,
                    const VectorType &u,
                    double            load_factor) const override;

    /**
     * Moment vector that junction @p junction's rotation DoFs transmit at
     * @p u: for a clamped junction the reaction moment of the clamp (the
     * moment conjugate to a prescribed rotation, L&K appendix C), for a
     * free one the residual moment (zero at equilibrium).
     */
    Vector3
    reaction_moment(unsigned int      junction,
                    const VectorType &u,
                    double            load_factor) const override;

    /// @name Inextensible rods (Rod::inextensible)
    /// @{
    /**
     * The free Lagrange multiplier DoFs that families declared (after
     * finalize(); ElementFamily::own_dofs()): of the inextensible rods'
     * segments, the developable ribbons' hinges, the bonding constraints.
     * They are the constraint rows of the tangent, which is then
     * the KKT matrix of the constrained minimization
     * (families/inextensibility_family.h). The stability counts and the
     * eigen-solvers work on the constraint manifold with them
     * (ConstrainedFactorization). Empty for a model without.
     */
    const std::vector<global_dof_index> &
    multiplier_dofs() const override
    {
      return free_multipliers;
    }

    /**
     * Axial force (N, tension positive) of the segment on cell @p cell at
     * @p u: the first family's ElementFamily::segment_axial_force() (the
     * material's, at the committed internal variables, of an extensible
     * segment; the multiplier times the constraint's scale of an
     * inextensible one, 0 where both its ends are held); 0 where no family
     * prices the segment's length.
     */
    double
    axial_force(unsigned int cell, const VectorType &u) const;
    /// @}

    /// @name History-dependent materials
    /// @{
    /// Whether any element family stores internal variables (a rod's
    /// history-dependent material, or a family of its own).
    bool
    has_internal_variables() const override
    {
      return !history.empty();
    }

    /**
     * Time step of the next assemblies, which the materials' incremental
     * updates need; 0 (the default) evaluates the stored energy at the
     * committed internal variables, the state at the end of a converged
     * step. Throws std::invalid_argument for a negative or non-finite value
     * when the model has internal variables (any value is accepted, and
     * ignored, otherwise).
     */
    void
    set_time_step(double time_step) override;

    double
    time_step() const override
    {
      return step_length;
    }

    /**
     * Asks every element family for the updated internal variables of its
     * stencils at the converged state @p u over the current time step
     * (ElementFamily::update_internal_variables()) and makes them the
     * committed ones. Call once per converged step, before
     * reset_reference().
     */
    void
    commit_internal_variables(const VectorType &u) override;

    /// The committed internal variables.
    const InternalVariables &
    internal_variables() const override
    {
      return history;
    }

    /// A copy of the reference configuration, the committed internal
    /// variables and the time step (see ModelState).
    ModelState
    state() const override;

    /// Installs @p state, taken from this model by state(), as it was.
    void
    set_state(const ModelState &state) override;
    /// @}

    /// A zero vector with the model's layout.
    VectorType
    create_vector() const override;

    /// A matrix with the model's sparsity pattern.
    void
    initialize_matrix(MatrixType &matrix) const override;

    /// The communicator of the model's vectors and matrices.
    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }

    /// The DoFs this process owns (finalize()).
    const dealii::IndexSet &
    locally_owned_dofs() const
    {
      return owned_dofs;
    }

    const RodNetwork &
    network() const override
    {
      return *network_;
    }
    const DofLayout &
    layout() const override
    {
      return *layout_;
    }
    const Configuration &
    configuration() const override
    {
      return *configuration_;
    }
    Configuration &
    configuration()
    {
      return *configuration_;
    }
    const dealii::AffineConstraints<double> &
    constraints() const override
    {
      return homogeneous_constraints;
    }
    const std::vector<Support> &
    supports() const override
    {
      return support_list;
    }
    const HingeKernel &
    hinge_kernel(unsigned int rod) const override
    {
      return *kernels[rod];
    }
    const JunctionKernel &
    junction_kernel(unsigned int rod) const
    {
      return *junction_kernels[rod];
    }
    const RodMaterial &
    material(unsigned int rod) const
    {
      return *materials[rod];
    }
    /// External force vector at load factor 1: the ramped dead forces
    /// (not the held ones, add_held_point_force()).
    const VectorType &
    external_force() const override
    {
      return f_ext;
    }

  private:
    /// A support's hold on a position DoF at load factor 1. Holds that
    /// yield (the position of a clamp's end or a junction) take the value
    /// of any other hold there, or zero.
    struct Hold
    {
      unsigned int support;
      unsigned int vertex;
      unsigned int component;
      double       value;
      bool         yields;
      TimeFunction in_time = {};
    };

    /// A clamp of a rod end and its rigid motion at load factor 1: the
    /// translation of its end vertex (from the holds there, set by
    /// finalize()) and a rotation about it.
    struct Clamp
    {
      unsigned int                support;
      std::array<unsigned int, 2> vertices; ///< end vertex, inner vertex
      unsigned int                segment;  ///< cell
      Quaternion                  undeformed_frame;
      Vector3                     translation = Vector3::Zero();
      Vector3                     axis        = Vector3::UnitZ();
      double                      angle       = 0;
      /// What scales each component of the translation and the angle.
      std::array<TimeFunction, 3> translation_in_time = {};
      TimeFunction                rotation_in_time    = {};
    };

    /// The hinge kernel and the junction kernel of each rod, after the
    /// rods' kernel names (constructor).
    void
    create_kernels(GhostSpin ghost_spin);

    /// The supports that the junctions imply (constructor): the position
    /// of a clamped or welded-and-pinned junction, the rotation of a
    /// clamped one.
    void
    add_junction_supports();

    /// A support called @p name of the masked components of @p vertex,
    /// held at @p displacement (at load factor 1) or, if it @p yields, at
    /// the value of any other support there.
    void
    add_position_support(const std::string         &name,
                         unsigned int               vertex,
                         const std::array<bool, 3> &mask,
                         const Vector3             &displacement,
                         bool                       yields,
                         const TimeFunction        &in_time = {});

    /// Resolves the holds, clamps and held rotations into fixed_dofs;
    /// throws naming the supports that hold a DoF at different values and
    /// moments on held rotations.
    void
    resolve_supports();

    /// Position holds and clamps into fixed_dofs (see resolve_supports()).
    void
    resolve_position_holds();

    /// Each held position DoF into fixed_dofs (and timed_dofs): the value
    /// of its holds that do not yield; throws naming two that disagree.
    void
    resolve_held_components();

    /// The clamps' translations from their end vertices' holds, their inner
    /// vertices and segment twists into fixed_dofs; throws naming two clamps
    /// that turn one rod end differently.
    void
    resolve_clamps();

    /// The force that support @p s exerts at its @p k-th vertex, from the
    /// unconstrained residual @p r.
    Vector3
    support_force(const Support &s, unsigned int k, const VectorType &r) const;

    /// Puts the materials of the ramped rods at @p load_factor
    /// (ramp_natural_shape()); nothing if none is ramped or they are there.
    void
    follow_natural_shape(double load_factor) const;

    /// The energy of every family at @p u, with each stencil's derivatives
    /// handed to @p copier: serially, or, where @p copier may run on
    /// several threads at once for stencils that share no DoF
    /// (@p concurrent_copier) and deal.II has more than one thread, color
    /// by color in parallel (stencil_blocks).
    double
    assemble_families(
      const VectorType                                     &u,
      double                                                load_factor,
      Derivatives                                           derivatives,
      const std::function<void(const LocalContribution &)> &copier,
      bool concurrent_copier = false) const;

    /// Adds the dead load terms at @p load_factor (their factor
    /// applied_load_factor(); the held forces at full value; and
    /// @p extra_force, if not null) to @p energy
    /// and, at the rows @p block (null: the model's own numbering), to @p
    /// residual (if not null).
    void
    add_dead_loads(const VectorType  &u,
                   double             load_factor,
                   const VectorType  *extra_force,
                   const SystemBlock *block,
                   double            &energy,
                   VectorType        *residual) const;

    /// assemble() into a @p tangent of another sparsity pattern than the
    /// model's, through assemble_mapped(); refused on several processes.
    double
    assemble_foreign_tangent(const VectorType &u,
                             double            load_factor,
                             VectorType       *residual,
                             MatrixType       *tangent,
                             bool              apply_constraints,
                             const VectorType *extra_force) const;

    /// Adds to @p tangent, at @p block's rows, the mean magnitude of the
    /// free DoFs' @p diagonal on each constrained DoF that no stencil sees.
    void
    add_unseen_diagonal(const std::vector<double> &diagonal,
                        const SystemBlock         &block,
                        MatrixType                &tangent) const;

    /// assemble_into() with an @p extra_force (see assemble()), through
    /// AffineConstraints::distribute_local_to_global: the path for a
    /// caller's system and for every layout the direct scatter does not
    /// handle.
    double
    assemble_mapped(const VectorType  &u,
                    double             load_factor,
                    const SystemBlock &block,
                    VectorType        *residual,
                    MatrixType        *tangent,
                    bool               apply_constraints,
                    const VectorType  *extra_force) const;

    /// Assembles the stencils of family @p f at @p state, handing each
    /// stencil's contribution to @p copier: serially, or, if @p blocks is
    /// given, color by color, the blocks of a color in parallel, each in
    /// stencil order on one thread; rethrows the first exception of a
    /// stencil after the loop. Adds the family's energy to @p energy in
    /// the stencils' order, whatever the threads.
    void
    assemble_family(
      unsigned int                                          f,
      const StencilState                                   &state,
      Derivatives                                           derivatives,
      const std::function<void(const LocalContribution &)> &copier,
      const StencilBlocks                                  *blocks,
      double                                               &energy) const;

    /// Throws std::invalid_argument unless @p locally_owned_dofs can be the
    /// DoFs of this process (see finalize()); collective.
    void
    check_ownership(const dealii::IndexSet &locally_owned_dofs) const;

    /// What assemble() computes where @p residual and @p tangent are
    /// (not) null.
    static Derivatives
    derivatives_for(const VectorType *residual, const MatrixType *tangent);

    /// apply_boundary_values() on a vector that holds every entry (the
    /// model's on one process, a replica() on several).
    void
    set_support_values(VectorType &u, double load_factor, double time) const;

    /// Runs @p assemble_here (this process's stencils) on every process and
    /// returns the sum of their energies; a failure on one process throws
    /// the same std::runtime_error on all (first_problem()).
    double
    energy_over_processes(const std::function<double()> &assemble_here) const;

    /// The numbering of the DoFs and matrix columns the direct scatter
    /// adds into: this process's share, and on several processes the
    /// column map of the model's sparsity pattern (local_columns).
    DirectScatter::Numbering
    scatter_numbering() const;

    /// The work f . u of the dead force @p force on the state @p u, which
    /// may hold every entry where @p force is distributed (a replica).
    /// Collective.
    static double
    work(const VectorType &force, const VectorType &u);

    /// The unconstrained residual at (@p u, @p load_factor), every entry
    /// on this process: the reactions at the fixed DoFs. Collective.
    VectorType
    reactions_at(const VectorType &u, double load_factor) const;

    /// Every entry of the distributed @p u, in a vector of one process
    /// (MPI_COMM_SELF): for what reads and writes DoFs anywhere, such as
    /// the supports. Collective; O(n_dofs) per process.
    VectorType
    replica(const VectorType &u) const;

    /// @p u with the ghost entries this process's stencils read, in
    /// ghosted_state (on several processes).
    const VectorType &
    with_ghosts(const VectorType &u) const;

    /// The reader of @p u's entries that the stencils get: with the places
    /// of ghosted_state's entries where @p u is ghosted_state.
    DofValues
    values_of(const VectorType &u) const;

    /// The homogeneous constraints of the fixed DoFs and the junction
    /// copies, and the mask of the DoFs they constrain.
    void
    make_constraints();

    /// The model's own sparsity pattern (add_sparsity_pattern() in its own
    /// numbering) on the DoFs this process owns.
    void
    make_sparsity_pattern();

    /// The factor of a support's value (TimeFunction::factor() at a load
    /// factor and time, or a sample of it).
    using SupportFactor = std::function<double(const TimeFunction &)>;

    /// The displacement of vertex @p v of clamp @p c at the factors
    /// @p factor of its translation and rotation.
    Vector3
    clamp_displacement(const Clamp         &c,
                       unsigned int         v,
                       const SupportFactor &factor) const;

    /// Throws std::runtime_error naming the first prescribed rotation that
    /// turns by half a turn or more where its factor changes by
    /// @p change over the step described by @p step ("from t = 0 to 1 s");
    /// the message ends with the @p remedy.
    void
    require_rotation_step_below_half_turn(const SupportFactor &change,
                                          const std::string   &step,
                                          const std::string   &remedy) const;

    /// "0 m and 0.1 m at load factor 1", or each value with what scales
    /// it where a function of time scales one: for messages.
    static std::string
    held_values(const Hold &a, const Hold &b);

    /// Throws std::invalid_argument where another support holds the inner
    /// vertex of a clamp where the clamp does not move it.
    void
    check_clamp_inner_holds(const Clamp &clamp) const;

    /// Sets the twist of every turned clamp's end segment in @p u, whose
    /// positions are set, to reach its frame at @p factor; @p twists: the
    /// twists before.
    void
    turn_clamp_twists(VectorType                &u,
                      const std::vector<double> &twists,
                      const SupportFactor       &factor) const;

    MPI_Comm                    mpi_communicator;
    dealii::IndexSet            owned_dofs;
    std::unique_ptr<RodNetwork> network_;
    /// Per rod; the entries of ramped rods are replaced at each load factor
    /// (follow_natural_shape()); the families hold a reference to it.
    mutable std::vector<std::shared_ptr<const RodMaterial>> materials;
    /// The materials as given, of the rods whose natural shape is ramped
    /// (ramp_natural_shape()), null for the others; empty if none is.
    std::vector<std::shared_ptr<const RodMaterial>> given_materials;
    NaturalShapeParts                               ramped_parts;
    /// The load factor the ramped materials are at (NaN: not yet set).
    mutable double ramped_at = std::nan("");
    /// Whether the loads stay at their full value (fix_loads()).
    bool                                         loads_fixed = false;
    std::vector<std::unique_ptr<HingeKernel>>    kernels;
    std::vector<std::unique_ptr<JunctionKernel>> junction_kernels;
    std::unique_ptr<DofLayout>                   layout_;
    std::unique_ptr<Configuration>               configuration_;
    std::vector<std::unique_ptr<ElementFamily>>  families;
    /// Per family, its stencils in blocks, in colors of blocks that share no
    /// DoF (color_stencil_blocks(), finalize()): the scatter of several
    /// threads.
    std::vector<StencilBlocks> stencil_blocks;
    /// On several processes, per family, the stencils this process
    /// evaluates (stencils_anchored()); empty on one process, where every
    /// stencil is evaluated.
    std::vector<OwnedStencils> own_stencils;
    /// On several processes, the first DoF of every process's share in
    /// rank order, then the number of DoFs (DirectScatter::Numbering).
    std::vector<global_dof_index> share_starts;
    /// The state with the ghost entries own_stencils read (with_ghosts()).
    mutable VectorType ghosted_state;
    /// Per global DoF, its place in ghosted_state's storage, -1 where it
    /// holds none (DofValues): 4 bytes a DoF on each process.
    std::vector<int> ghost_places;
    /// The import of the ghost entries into ghosted_state from a vector
    /// of the model's partition, made once at finalize() (deal.II's
    /// assignment makes one per call).
    std::unique_ptr<Epetra_Import> ghost_import;
    /// On several processes, per DoF, its column in the column map of the
    /// model's sparsity pattern (-1: no row of this process couples it).
    std::vector<int> local_columns;
    /// Where the stencils' entries land in the rows of the tangent last
    /// assembled (the direct scatter's; found again for a new pattern).
    std::unique_ptr<ScatterPositionsCache> scatter_positions =
      std::make_unique<ScatterPositionsCache>();
    std::vector<Support>                  support_list;
    std::multimap<global_dof_index, Hold> holds;
    std::vector<Clamp>                    clamps;
    /// Per junction: whether its rotation is held (clamped, prescribed).
    std::vector<bool> rotation_held;
    /// Fixed DoF -> prescribed value at load factor 1 (finalize()).
    std::map<global_dof_index, double> fixed_dofs;
    /// The fixed DoFs whose value a function of time scales.
    std::map<global_dof_index, TimeFunction> timed_dofs;
    /// The time of the last set_time() (NaN: none), at which
    /// apply_boundary_values() puts the supports moving in time.
    double                            support_time = std::nan("");
    dealii::AffineConstraints<double> homogeneous_constraints;
    /// Per DoF: fixed by a support (the same DoFs as the constraints).
    std::vector<bool>                 fixed_dof_mask;
    dealii::AffineConstraints<double> no_constraints;
    DeadLoads                         loads;
    std::vector<RigidBody>            bodies;
    struct AxisLoad
    {
      unsigned int junction;
      Vector3      axis;
      double       value; ///< moment (N m) or angle (rad) at load factor 1
      LoadRamp     ramp    = LoadRamp::ramped; ///< moments only
      TimeFunction in_time = {};               ///< rotations only
    };
    std::vector<AxisLoad> moments;
    std::vector<AxisLoad> prescribed_rotations;
    VectorType            f_ext;
    /// The held point forces (add_held_point_force()) and their vector.
    DeadLoads                                 held_loads;
    VectorType                                f_held;
    InternalVariables                         history;
    double                                    step_length = 0;
    dealii::TrilinosWrappers::SparsityPattern sparsity;
    /// DoFs that no stencil of any family sees (make_sparsity_pattern()).
    std::vector<global_dof_index> unseen_dofs;
    /// The applied moments about fixed axes, once one is added
    /// (add_moment()).
    AxisMomentFamily             *axis_moment_family = nullptr;
    std::vector<global_dof_index> free_multipliers;
    /// The family that declared each of the layout's blocks
    /// (DofLayout::declared_blocks()), in their order.
    std::vector<ElementFamily *> block_owners;

    /// The axial force of every segment at @p u (output_fields()).
    OutputFields::Field
    axial_forces(const VectorType &u) const;

    /// The axial strain and the directors d1, d2 of every segment at @p u
    /// (output_fields()).
    std::vector<OutputFields::Field>
    segment_strain_fields(const VectorType &u) const;

    /// The curvature and twist rate at every hinge's vertex at @p u
    /// (output_fields()).
    std::vector<OutputFields::Field>
    hinge_strain_fields(const VectorType &u) const;

    /// Appends the committed internal variables of history-dependent
    /// materials to @p output, one field per name (output_fields()).
    void
    append_internal_variable_fields(OutputFields &output) const;

    /// Appends the vertex fields that the families' declared DoFs are
    /// written to (DeclaredDofOutput), at @p u.
    void
    append_declared_dof_fields(const VectorType                 &u,
                               std::vector<OutputFields::Field> &fields) const;

    /// The force vector of @p dead_loads at load factor 1 (finalize()).
    VectorType
    force_vector(const DeadLoads &dead_loads) const;

    /// The families of every rod model (bending, junctions, stretching)
    /// and those the network's rods ask for (inextensibility, developable
    /// ribbons), each added like a user's (add_element_family()).
    void
    add_built_in_families();

    /// Adds the free multipliers of the families' declared blocks
    /// (ElementFamily::own_dofs()) to multiplier_dofs(). One whose stencils
    /// see held DoFs only is held at zero (and its family told,
    /// ElementFamily::hold_own_dofs()) where its declaration allows it;
    /// else throws std::invalid_argument naming it.
    void
    collect_declared_multipliers();

    /// Holds at zero, or refuses, the declared multipliers that see no
    /// free DoF (@p sees_free, per declared multiplier), adds the others to
    /// multiplier_dofs() (collect_declared_multipliers()).
    void
    hold_or_free_declared_multipliers(
      const std::map<global_dof_index, bool> &sees_free);
  };
} // namespace rodnet

#endif
