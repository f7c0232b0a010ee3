#ifndef RODNET_CORE_SOLVABLE_MODEL_H
#define RODNET_CORE_SOLVABLE_MODEL_H

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <core/configuration.h>
#include <core/dof_layout.h>
#include <core/element_family.h>
#include <core/internal_variables.h>
#include <core/model.h>
#include <core/model_state.h>
#include <core/rigid_body.h>
#include <elements/hinge_kernel.h>

#include <memory>
#include <vector>

namespace rodnet
{
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

  /**
   * What the solvers of solvers/ see of a model: a potential with its
   * residual and tangent on a Trilinos DoF vector, the supports as values
   * and homogeneous constraints, the state a solver advances (reference
   * configuration, internal variables, time step) and the queries their
   * checks make (DoF layout, configuration, element families). RodModel
   * implements it; the static solver, path following, time integration
   * and the checks take a SolvableModel, so a second model that offers
   * the same operations runs under them unchanged.
   *
   * The functions can be virtual since they are called once per assembly,
   * step or check, never per stencil; the loops over stencils stay inside
   * the model (RodModel is final, so its own calls are not dispatched at
   * all). RodModel documents each operation in full.
   */
  class SolvableModel : public Model<VectorType>
  {
  public:
    /// @name Potential, residual and tangent
    /// @{
    /**
     * Energy at @p u and @p load_factor; the gradient into @p residual and
     * the Hessian into @p tangent where they are not null (zeroed first),
     * the fixed DoFs eliminated with @p apply_constraints; @p extra_force a
     * further dead force not scaled by the load factor
     * (RodModel::assemble()).
     */
    virtual double
    assemble(const VectorType &u,
             double            load_factor,
             VectorType       *residual,
             MatrixType       *tangent,
             bool              apply_constraints = true,
             const VectorType *extra_force       = nullptr) const = 0;

    /// A matrix with the model's sparsity pattern.
    virtual void
    initialize_matrix(MatrixType &matrix) const = 0;

    /// The homogeneous constraints of the fixed DoFs (and the DoFs the
    /// model ties to others).
    virtual const dealii::AffineConstraints<double> &
    constraints() const = 0;

    /// The free Lagrange multiplier DoFs: the constraint rows of a KKT
    /// tangent (empty for a model without).
    virtual const std::vector<global_dof_index> &
    multiplier_dofs() const = 0;

    /// The ramped dead forces at load factor 1.
    virtual const VectorType &
    external_force() const = 0;

    /// The factor on the dead loads and applied moments at
    /// @p load_factor (1 where the loads are fixed).
    virtual double
    applied_load_factor(double load_factor) const = 0;

    /// Whether the potential at a given state changes with the load factor.
    virtual bool
    potential_follows_load_factor() const = 0;
    /// @}

    /// @name Supports in time and load
    /// @{
    using Model<VectorType>::apply_boundary_values;

    /// The fixed DoFs of @p u at @p load_factor and @p time (supports
    /// moving in time); throws std::runtime_error where a prescribed
    /// rotation would turn by half a turn or more from @p u.
    virtual void
    apply_boundary_values(VectorType &u,
                          double      load_factor,
                          double      time) const = 0;

    /// Throws std::runtime_error where a prescribed rotation turns by half
    /// a turn or more over the step from (@p load_factor_0, @p time_0) to
    /// (@p load_factor_1, @p time_1).
    virtual void
    check_rotation_step(double load_factor_0,
                        double time_0,
                        double load_factor_1,
                        double time_1) const = 0;

    /// The same over a load step, in which no time passes.
    virtual void
    check_rotation_step(double load_factor_0, double load_factor_1) const = 0;

    /// Whether a support moves by its own function of time.
    virtual bool
    moves_supports_in_time() const = 0;
    /// @}

    /// @name Time
    /// @{
    /// The time of the assemblies that follow.
    virtual void
    set_time(double time) = 0;

    /// The factors of the activation fields driven by functions of time
    /// at the last set_time(), one per function.
    virtual std::vector<double>
    activation_time_factors() const = 0;

    /// Whether the potential at a given state changes with the time.
    virtual bool
    potential_follows_time() const = 0;
    /// @}

    /// @name The state a solver advances
    /// @{
    /// Makes @p u the reference configuration (its rotations move into
    /// the reference).
    virtual void
    reset_reference(VectorType &u) = 0;

    /// A copy of the reference configuration, the committed internal
    /// variables and the time step.
    virtual ModelState
    state() const = 0;

    /// Installs @p state, taken from this model by state().
    virtual void
    set_state(const ModelState &state) = 0;

    /// Whether any element family stores internal variables.
    virtual bool
    has_internal_variables() const = 0;

    /// The time step of the next assemblies (0: the stored energy).
    virtual void
    set_time_step(double time_step) = 0;

    /// The time step of set_time_step().
    virtual double
    time_step() const = 0;

    /// Makes the internal variables updated at the converged @p u the
    /// committed ones (once per converged step, before reset_reference()).
    virtual void
    commit_internal_variables(const VectorType &u) = 0;

    /// The committed internal variables.
    virtual const InternalVariables &
    internal_variables() const = 0;
    /// @}

    /// @name What the solvers' checks read
    /// @{
    /// The numbering of the DoFs: positions, twists, quaternions and the
    /// families' own blocks.
    virtual const DofLayout &
    layout() const = 0;

    /// The undeformed and reference data, and positions at a DoF vector.
    virtual const Configuration &
    configuration() const = 0;

    /// The families of the energy, in the order they are assembled.
    virtual const std::vector<std::unique_ptr<ElementFamily>> &
    element_families() const = 0;

    /// The hinge kernel of rod @p rod.
    virtual const HingeKernel &
    hinge_kernel(unsigned int rod) const = 0;

    /// The rigid bodies attached to the model.
    virtual const std::vector<RigidBody> &
    rigid_bodies() const = 0;
    /// @}
  };
} // namespace rodnet

#endif
