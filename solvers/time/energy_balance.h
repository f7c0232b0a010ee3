#ifndef RODNET_SOLVERS_TIME_ENERGY_BALANCE_H
#define RODNET_SOLVERS_TIME_ENERGY_BALANCE_H

#include <core/solvable_model.h>
#include <core/tensor_body_spin.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/time/integration_scheme.h>

#include <functional>
#include <string>
#include <vector>

namespace rodnet
{
  /// The two ends of a converged time step, in the step's chart (before
  /// the model's reference reset).
  struct StepEnds
  {
    const VectorType &u0, &u1; ///< u_n, u_{n+1}
    const VectorType &v0, &v1; ///< v_n, v_{n+1}
    double            time, end_time;
    /// Where the step's scheme takes grad Pi
    /// (IntegrationScheme::force_points()).
    std::vector<ForcePoint> force_points;
  };

  /**
   * The energy watch of a dynamic run (doc/dynamics.md, "Failures"): the
   * balance of the total energy E = 1/2 v.Mv + Pi against the work W that
   * the loads, the activation fields and the supports moving in time do
   * on the model,
   *   B = E - E_0 - W,
   * which no stable run makes grow: the midpoint rule keeps it at zero to
   * the Newton tolerance, the others and damping lower it. Growth beyond a
   * fraction of its scale (the largest of |E_0|, the kinetic energy, |E|
   * and |W| so far) marks an unstable integration, stopped before it runs
   * away. The scale has a floor, the residual bound over the fraction: the
   * most that the accepted steps' residuals can have added to B, sum_n
   * |r_F| |d_x| + |r_M| |d_theta| (the force and moment norms of each
   * step's final residual, ResidualCriterion::norms(), times the norms of
   * its motion on the free positions and angles; a quaternion increment a
   * turns by 2 a), since the step's energy error is r . d. A run from rest
   * under loads near the rounding of its residual has energies of the
   * size of that noise, and without the floor Newmark's took it for growth
   * (tests/validation/energy_balance.cc).
   *
   * A step from t_n to t_{n+1} is balanced as its scheme's discrete
   * system is: the scheme takes grad Pi at force points
   * (IntegrationScheme::force_points()) y_k = (1 - s_k) u_n + s_k
   * u_{n+1} with weights w_k, under the loads and fields p_k of the time
   * t_n + s_k h, so that the step adds to B
   *   Delta B = Delta K + sum_k w_k [Pi(u_{n+1}, p_k) - Pi(u_n, p_k)] - W_s,
   * the rest of the change of Pi being the loads' and fields' work (the
   * midpoint rule: its discrete gradient at p_{n+1/2}; Newmark: the
   * trapezoidal rule, whose carried inertial force holds the loads of
   * both ends). W_s is the supports' work on their fixed DoFs, with the
   * reaction there that the step's balance of momentum holds with,
   *   W_s = [M (v_{n+1} - v_n) / h + f + C (v_n + v_{n+1}) / 2]_fixed
   *         . (u_{n+1} - u_n)_fixed,
   * plus the inertial force of bodies with an inertia tensor at held
   * junction rotations beyond M's (tensor_body_reaction()),
   * f = sum_k w_k grad Pi(y_k, p_k) unconstrained: the equation of motion
   * M a + C v + grad Pi = R, with R the reaction, gives dE/dt =
   * R.v_fixed - v.Cv. With the midpoint rule's own point the balance holds
   * to the Newton tolerance; the trapezoidal rule on a midpoint run would
   * miss the work by percents where stiff modes ring. A step where nothing
   * moves costs nothing more; one where the loads, fields or supports move
   * two energy assemblies per force point (one of them with the gradient
   * where a support moves). A load factor or a time that nothing in the
   * model's potential follows moves nothing, and the model is not even put
   * at the step's times then.
   */
  class EnergyBalance
  {
  public:
    /// @p model, its unconstrained mass matrix @p mass and damping matrix
    /// @p damping (empty: none) must outlive this object; the model must be
    /// finalized.
    EnergyBalance(SolvableModel    &model,
                  const MatrixType &mass,
                  const MatrixType &damping);

    /// (Re)starts the watch, on or off, at the state of energies
    /// @p kinetic and @p potential; @p growth_limit is the fraction of the
    /// scale the balance may grow by.
    void
    start(bool on, double growth_limit, double kinetic, double potential);

    /// Whether the watch is on.
    bool
    on() const
    {
      return watching;
    }

    /// Records the work of the converged step @p ends, with the load
    /// factor as a function of time @p load_factor. Leaves the model at
    /// ends.end_time.
    void
    add_step(const StepEnds                      &ends,
             const std::function<double(double)> &load_factor);

    /**
     * Adds the step last recorded, which ended with the energies
     * @p kinetic and @p potential and the final residual's norms
     * @p residual (StepInfo::residual), to the balance, and throws
     * SolverFailure naming @p who at @p time (and appending @p advice)
     * where the balance grew beyond the limit.
     */
    void
    check(const std::string   &who,
          const std::string   &advice,
          double               time,
          double               kinetic,
          double               potential,
          const ResidualParts &residual);

    /// The work W done on the model since start().
    double
    work() const
    {
      return external_work;
    }

  private:
    /// Whether the load factor @p load_factor or a field driven in time
    /// changes over the step @p ends (at its ends and force points).
    bool
    parameters_move(const StepEnds                      &ends,
                    const std::function<double(double)> &load_factor);

    /// The supports' work W_s of @p ends under the step's mean internal
    /// force @p force.
    double
    support_work(const StepEnds &ends, const VectorType &force) const;

    /// The l2 norms of the step's motion from @p u0 to @p u1 (vectors with
    /// every entry) on the free positions (m) and angles (rad: twists, 2 a
    /// of a quaternion increment a).
    ResidualParts
    step_motion(const VectorType &u0, const VectorType &u1) const;

    SolvableModel    &model;
    const MatrixType &mass;
    const MatrixType &damping;
    /// What the model's potential at a given state follows
    /// (SolvableModel::potential_follows_load_factor(),
    /// potential_follows_time()).
    const bool follows_load_factor, follows_time;
    /// The DoFs fixed by supports (no junction copies), as a list and as
    /// a mask.
    std::vector<global_dof_index> fixed;
    std::vector<bool>             is_fixed;
    /// What each DoF is, for the norms of a step's motion.
    DofRoles roles;
    /// The bodies with an inertia tensor (tensor_body_reaction()).
    std::vector<TensorBody> tensor_bodies;

    bool   watching       = false;
    double growth_limit   = 0;
    double start_energy   = 0;
    double scale          = 0;
    double balance        = 0;
    double external_work  = 0;
    double last_kinetic   = 0;
    double last_potential = 0;
    /// The step last recorded: whether its loads, fields or supports
    /// moved, and then Pi(u_{n+1}, p*) - Pi(u_n, p*) and W_s.
    bool   step_moved            = false;
    double step_potential_change = 0;
    double step_support_work     = 0;
    /// The last step's motion (step_motion()), and the residual bound.
    ResidualParts last_motion;
    double        residual_bound = 0;
  };
} // namespace rodnet

#endif
