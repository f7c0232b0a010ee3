#ifndef RODNET_CORE_ELEMENT_FAMILY_H
#define RODNET_CORE_ELEMENT_FAMILY_H

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <core/configuration.h>
#include <core/dof_layout.h>
#include <core/internal_variable_fields.h>
#include <core/internal_variables.h>

#include <Eigen/Dense>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  /// The state a stencil is evaluated at: the DoFs, the reference data, the
  /// committed internal variables, the time step and the load factor.
  struct StencilState
  {
    /// The DoF vector, read through its storage where it allows it.
    DofValues                u;
    const Configuration     &configuration;
    const InternalVariables &history;
    /// Time step of the materials' incremental update (0: stored energy).
    double time_step;
    /// Factor on the applied loads of the assembly (load-like families
    /// scale with it): the load factor, or 1 where the loads are fixed
    /// (RodModel::applied_load_factor()).
    double load_factor;
  };

  /// What one stencil contributes to the global energy, gradient and
  /// Hessian; the local vectors in the order of its DoFs.
  struct LocalContribution
  {
    dealii::FullMatrix<double>    matrix;
    dealii::Vector<double>        vector;
    std::vector<global_dof_index> dofs;
    double                        energy = 0;
    /// Which stencil this is: its family's index in the model and its
    /// index in the family (set by the assembly, for the scatter).
    unsigned int family  = 0;
    unsigned int stencil = 0;

    /// Copies an Eigen gradient (and Hessian, if not null) of any size.
    template <class Gradient, class Hessian>
    void
    store(const Gradient &gradient, const Hessian *hessian);
  };

  /// The derivatives an assembly asks for.
  enum class Derivatives
  {
    energy,
    gradient,
    hessian
  };

  /**
   * A family of stencils of the total potential energy: the extension point
   * of the assembly (doc/architecture.md). Stretch, hinge and junction
   * elements, applied moments and the elastic foundation are families; each
   * says which global DoFs its stencils couple (any number, including DoF
   * blocks of its own) and evaluates a stencil's energy, gradient and
   * Hessian at a state. The assembly runs one loop over all families
   * (RodModel::assemble()); the sparsity pattern comes from the same DoF
   * lists, so a new family needs no change outside its own file pair.
   *
   * Implementations are thread-safe: evaluate() is const and keeps its
   * scratch data per thread.
   */
  class ElementFamily
  {
  public:
    virtual ~ElementFamily() = default;

    /// Name in messages and output ("hinges", "elastic foundation", ...).
    virtual std::string
    name() const = 0;

    /// Number of stencils.
    virtual unsigned int
    n_stencils() const = 0;

    /// Global DoFs of stencil @p s, in the order of its local vectors.
    virtual void
    get_dofs(unsigned int s, std::vector<global_dof_index> &dofs) const = 0;

    /// The cost of evaluating one stencil with its Hessian relative to a
    /// hinge's (the simple kernel's): the weight by which the stencils are
    /// shared among processes (balanced_share()). Measured by
    /// bench/family_costs (doc/performance.md); 1 unless a family says.
    virtual double
    relative_cost() const
    {
      return 1.0;
    }

    /**
     * Energy of stencil @p s at @p state into @p local.energy and, as
     * @p derivatives asks, its gradient into @p local.vector and Hessian
     * into @p local.matrix, sized to the stencil's DoFs (local.dofs is set
     * by the caller). May throw where the state is outside the kernel's
     * domain (e.g. a flipped tangent); the assembly rethrows it.
     */
    virtual void
    evaluate(unsigned int        s,
             const StencilState &state,
             Derivatives         derivatives,
             LocalContribution  &local) const = 0;

    /// Whether the family's energy depends on StencilState::load_factor
    /// (a load it ramps, a gap it closes): the model's potential then
    /// follows the load factor (RodModel::potential_follows_load_factor()).
    virtual bool
    follows_load_factor() const
    {
      return false;
    }

    /**
     * @name What the family shows of a state (RodModel::output_fields())
     * The defaults show nothing.
     */
    /// @{
    /**
     * The axial force (N, tension positive) that the family carries in the
     * segment on cell @p cell at @p state (with its committed internal
     * variables, over no time step), if its stencils price that segment's
     * length: the stretching of an extensible segment, the constraint of an
     * inextensible one. The output takes the first family's answer.
     */
    virtual std::optional<double>
    segment_axial_force(const unsigned int  cell,
                        const StencilState &state) const
    {
      (void)cell;
      (void)state;
      return std::nullopt;
    }

    /// Writes the committed internal variables of the stencils it draws
    /// (@p history) into @p fields, by name, at their vertex or cell.
    virtual void
    write_internal_variables(const InternalVariables &history,
                             InternalVariableFields  &fields) const
    {
      (void)history;
      (void)fields;
    }
    /// @}

    /**
     * @name DoFs of the family's own (a multiplier, a shape variable)
     *
     * A family may declare a block of DoFs that no other family has:
     * own_dofs() says how many, the role of each, the vertex it belongs to,
     * how messages name it and how it is written to output. When the family
     * is added, the model numbers the block after all other DoFs
     * (DofLayout::add_block()) and passes its first index to
     * number_own_dofs(); get_dofs() then lists them like any other DoF.
     * DofRoles, the residual check, the KKT solvers (a multiplier is one of
     * RodModel::multiplier_dofs()) and the output read the declaration, so
     * nothing outside the family's files knows it. A multiplier whose
     * stencils couple it to held DoFs only would leave the tangent singular:
     * finalize() holds it at zero or refuses it, naming its label, as the
     * declaration says. The defaults are a family without DoFs of its own.
     */
    /// @{
    /// The DoFs the family declares for itself.
    virtual std::vector<DeclaredDof>
    own_dofs() const
    {
      return {};
    }

    /// The first global index of the declared block (called once, when the
    /// family is added to a model, and only if own_dofs() is not empty).
    virtual void
    number_own_dofs(const global_dof_index first)
    {
      (void)first;
    }

    /// Which of the declared DoFs the model holds at zero (called once by
    /// finalize(), one flag per DoF of own_dofs(); see
    /// DeclaredDof::held_where_supports_hold): a family may leave out the
    /// stencils that then carry nothing.
    virtual void
    hold_own_dofs(const std::vector<bool> &held)
    {
      (void)held;
    }
    /// @}

    /**
     * @name History (for families whose energy depends on committed values)
     *
     * The model keeps, per stencil, n_internal_variables() committed values
     * (InternalVariables), which evaluate() reads from
     * state.history.block(*this, s): e.g. the viscous strains of a
     * history-dependent material, over whose time step the energy is
     * condensed. After a converged step RodModel::commit_internal_variables()
     * asks every stencil with values for its update and commits it. The
     * defaults are a family without history.
     */
    /// @{
    /// Number of internal variables of stencil @p s.
    virtual unsigned int
    n_internal_variables(const unsigned int s) const
    {
      (void)s;
      return 0;
    }

    /**
     * The internal variables of stencil @p s updated from the committed
     * ones over state.time_step at the converged state.u, into @p updated
     * (n_internal_variables(s) values, apart from the committed block).
     * The commit knows no load factor: state.load_factor is 0. Called only
     * for a stencil with internal variables, so the default, for a family
     * without, throws std::logic_error.
     */
    virtual void
    update_internal_variables(const unsigned int  s,
                              const StencilState &state,
                              double             *updated) const
    {
      (void)s;
      (void)state;
      (void)updated;
      throw std::logic_error("element family \"" + name() +
                             "\" has internal variables but no update");
    }
    /// @}
  };


  template <class Gradient, class Hessian>
  void
  LocalContribution::store(const Gradient &gradient, const Hessian *hessian)
  {
    const unsigned int n = gradient.size();
    vector.reinit(n, /*omit_zeroing_entries=*/true);
    for (unsigned int i = 0; i < n; ++i)
      vector[i] = gradient[i];
    if (hessian == nullptr)
      return;
    matrix.reinit(n, n, /*omit_default_initialization=*/true);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        matrix(i, j) = (*hessian)(i, j);
  }
} // namespace rodnet

#endif
