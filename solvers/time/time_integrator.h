#ifndef RODNET_SOLVERS_TIME_TIME_INTEGRATOR_H
#define RODNET_SOLVERS_TIME_TIME_INTEGRATOR_H

#include <core/mass_matrix.h>
#include <core/solvable_model.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/checks/strain_range.h>
#include <solvers/newton/newton_solver.h>
#include <solvers/newton/tangent_factorization.h>
#include <solvers/statics/static_solver.h>
#include <solvers/time/energy_balance.h>
#include <solvers/time/integration_scheme.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Implicit time stepping of a SolvableModel (Lestringant & Kochmann sections
   * 2.4-2.5): every step of length h from the state (u_n, v_n) at t_n
   * solves one nonlinear system for u = u_{n+1} by NewtonSolver, the same
   * Newton path as statics, with the model's incremental potential
   * Pi(u, lambda) (energy minus load potential, history materials
   * condensed over h) and the mass matrix M:
   *
   * - quasi-static:   grad Pi(u, lambda_{n+1}) = 0;
   * - backward Euler: M (u - u_n - h v_n) / h^2 + grad Pi(u, lambda_{n+1})
   *                   = 0, v_{n+1} = (u - u_n) / h;
   * - Newmark (beta = 1/4, gamma = 1/2), in trapezoidal form with the
   *   inertial force p = M a carried from step to step:
   *                   4 M (u - u_n - h v_n) / h^2 - p_n
   *                   + grad Pi(u, lambda_{n+1}) = 0,
   *                   p_{n+1} = 4 M (u - u_n - h v_n) / h^2 - p_n;
   * - midpoint:       2 M (u - u_n - h v_n) / h^2
   *                   + gradbar Pi(u_n, u; lambda_{n+1/2}) = 0,
   *   with Gonzalez's discrete gradient
   *     gradbar = grad Pi(m) + (Pi(u) - Pi(u_n) - grad Pi(m).d) M d / d.Md,
   *   m = (u_n + u)/2, d = u - u_n (over the free DoFs), which makes
   *   gradbar . d = Pi(u) - Pi(u_n), so that 1/2 v.Mv + Pi is conserved to
   *   the Newton tolerance whatever the nonlinearity;
   * - Newmark and midpoint: v_{n+1} = 2 (u - u_n) / h - v_n.
   *
   * The first three minimize an incremental potential (the mass term plus
   * Pi), which is what history-dependent materials need; the midpoint
   * rule's discrete gradient needs a stored energy and refuses them.
   * The tangent is c M + K (midpoint: 2 M / h^2 + K(m) / 2 plus the
   * derivative of the discrete-gradient correction, whose dense rank-one
   * part NewtonSolver handles by Sherman-Morrison).
   *
   * Activation fields driven by functions of time are evaluated at the
   * time the loads are taken at (SolvableModel::set_time()), and at the step's
   * end once it has converged.
   *
   * After every converged step the internal variables of history materials
   * are committed, the model's time step set to 0 (so that what the
   * observer evaluates, reactions and energies, is the state at the end of
   * the step: the stored energy at the committed variables), and the
   * reference configuration reset (Korner et al. 2c;
   * the twist inertia neglects the transport of the reference frame, see
   * doc/theory.md); the observer then sees the step. A step whose Newton
   * solve fails is halved, from the same state, down to min_step_fraction
   * of the nominal step; the run then throws SolverFailure naming the time
   * and the reason, after every earlier step has been reported. A state or
   * energy that is not finite is a failure as well, never an output, and
   * so is energy growth beyond the work of the loads and supports
   * (Parameters::energy_growth_limit, EnergyBalance): the signature of an
   * unstable integration.
   *
   * Each integrator is an IntegrationScheme (solvers/<name>_scheme.h),
   * created by its name from integration_scheme_registry(); TimeIntegrator
   * does
   * what is the same for all: the predictor, the tolerance, the Newton
   * solve of one step, step halving, the commit, the checks. A step that
   * fails or throws leaves the model's ModelState as it was (StateGuard).
   */
  class TimeIntegrator
  {
  public:
    struct Parameters
    {
      /// The time discretization: the name of a scheme registered in
      /// integration_scheme_registry() (see the equations above).
      std::string integrator = "newmark";
      double      start_time = 0;
      double      end_time   = 0;
      /// Nominal time step (s); steps land on start_time + k time_step and
      /// on end_time.
      double time_step = 0;
      /// Load factor multiplying every load and prescribed displacement of
      /// the model, as a function of time.
      std::function<double(double)> load_factor = [](double) { return 1.0; };
      /**
       * Quasi-static steps before start_time (the hold of Lestringant &
       * Kochmann's Fig. 5): preload_steps steps of h = preload_time /
       * preload_steps under load_factor(t) at t = start_time -
       * preload_time + (k - 1) h, k = 1..n, all before the start, so that
       * a load released at the start, if(t < 0, 1, 0), holds throughout;
       * the run then starts at rest. No preload when 0.
       */
      double       preload_time  = 0;
      unsigned int preload_steps = 0;
      MassKind     mass          = MassKind::consistent;
      /// Smallest step after halving, as a fraction of time_step.
      double min_step_fraction = 1.0 / 64;
      /// Newton converges when the force and moment parts of R are at
      /// most relative_tolerance times their scales, the loads and
      /// reactions or R at the predictor, or at their round-off floors
      /// (ResidualCriterion, as in statics).
      double relative_tolerance = 1e-9;
      /// As StaticSolver::Parameters::rounding_floor_limit,
      /// rounding_uncertainty_limit and rounding_failure_limit (quasi-static
      /// steps).
      double rounding_floor_limit       = 1e-3;
      double rounding_uncertainty_limit = 1e-6;
      double rounding_failure_limit     = 1e-3;
      /**
       * Dynamic steps solve by modified Newton
       * (NewtonSolver::Problem::reuse_first_jacobian): one tangent
       * assembly and factorization per step, the predictor's; a step that
       * fails so is solved again by full Newton before it is halved.
       */
      bool modified_newton = true;
      /// Strains past these get a warning (StrainMonitor).
      StrainLimits             strain_limits;
      NewtonSolver::Parameters newton;
      /**
       * Dynamic runs stop as unstable (SolverFailure) where the total
       * energy (kinetic plus potential) grows beyond the work of the loads,
       * fields and moving supports by more than this fraction of its scale
       * (the largest of the energy at the start, the kinetic energy, the
       * energy and the work since; EnergyBalance). 0: off.
       */
      double energy_growth_limit = 0.01;
      /// Progress line on the log every this many steps (0: none).
      unsigned int progress_interval = 100;
      /**
       * Rayleigh damping C = rayleigh_mass M + rayleigh_stiffness K_0 (1/s
       * and s), K_0 the tangent at the state the dynamic run starts from,
       * and viscous drag: a force -viscous_drag v (N s/m^2) per undeformed
       * length on the positions, lumped per vertex with its Voronoi length.
       * Each scheme adds C v at its own velocity (IntegrationScheme::
       * damping_velocity(), doc/dynamics.md "Damping"). Not negative; 0:
       * none.
       */
      double rayleigh_mass      = 0;
      double rayleigh_stiffness = 0;
      double viscous_drag       = 0;
      /// The generalized-alpha scheme's spectral radius at omega h ->
      /// infinity, in [0, 1]: 1 keeps every frequency (Newmark), 0
      /// annihilates the highest in one step (GeneralizedAlphaScheme).
      double spectral_radius_at_infinity = 0.8;

      /// Whether any damping coefficient is nonzero.
      bool
      damped() const
      {
        return rayleigh_mass != 0 || rayleigh_stiffness != 0 ||
               viscous_drag != 0;
      }

      /// Declares the entries of these parameters ("Integrator", the times,
      /// "Load factor", the preload, "Mass", "Progress interval", "Energy
      /// growth limit"; parse_parameters() reads all but "Load factor", a
      /// muparser expression the scene reads into load_factor, and the Newton
      /// settings, which are those of StaticSolver::Parameters) in the current
      /// subsection of @p prm, with their defaults and help.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Reads the entries of declare_parameters() from the current
      /// subsection of @p prm.
      void
      parse_parameters(const dealii::ParameterHandler &prm);

      /// Whether the integrator has inertia (its registered trait): all but
      /// "quasi-static", which needs no density.
      bool
      dynamic() const;

      /// The time of the state a run starts from: start_time, or with a
      /// preload the start of its first step, start_time - preload_time -
      /// h (see preload_time).
      double
      initial_time() const
      {
        return preload_time > 0 ?
                 start_time - preload_time - preload_time / preload_steps :
                 start_time;
      }
    };

    struct StepInfo
    {
      unsigned int step      = 0; ///< converged steps so far, preload included
      double       time      = 0;
      double       time_step = 0; ///< length of this step
      double       load_factor = 0;
      unsigned int iterations  = 0;
      /// Force (N) and moment (N m) norms of the final residual.
      ResidualParts residual;
      double        kinetic_energy = 0; ///< 1/2 v.Mv (0 quasi-statically)
      /// Stored energy minus load potential at the end of the step.
      double potential_energy = 0;
      /// The work the loads, fields and moving supports did on the model
      /// since the start of the run (dynamic runs with the energy watch
      /// on; EnergyBalance).
      double external_work = 0;
      double wall_time     = 0; ///< seconds spent on this step
      /// Quasi-static steps: the constrained tangent has no negative
      /// eigenvalue (always true for dynamic steps, which do not check).
      bool        stable = true;
      StrainRange strain;
    };

    using Observer = std::function<
      void(const StepInfo &, const VectorType &u, const VectorType &v)>;

    /**
     * @p inertia holds one RodInertia per rod (may be empty for
     * quasi-static runs). Throws std::invalid_argument for a time step that
     * is not positive and finite, an end time before the start, missing
     * inertia for a dynamic integrator, the midpoint rule with a
     * history-dependent material, or a damping coefficient that is negative
     * or not finite, or not zero in a quasi-static run. The model must be
     * finalized.
     */
    TimeIntegrator(SolvableModel                 &model,
                   const std::vector<RodInertia> &inertia,
                   const Parameters              &parameters,
                   std::ostream                  *log = nullptr);

    /**
     * Runs from the displacement @p u and velocity @p v at start_time
     * (after the preload, if any, which overwrites @p v with zero) to
     * end_time; both hold the last converged state on return or on a
     * throw. Prescribed DoFs of @p u are set to their values at the start
     * and, in dynamic runs, those of @p v to their velocity there.
     * Quasi-static runs and preloads throw std::invalid_argument first if
     * a rigid motion is free (describe_free_motions()): without inertia
     * nothing holds it.
     */
    void
    run(VectorType &u, VectorType &v, const Observer &on_converged);

    /**
     * The state a run starts from, as run() sets it: the prescribed DoFs
     * of @p u at their values at initial_time() and, in a dynamic run
     * without preload, those of @p v at the velocity of the prescribed
     * motion (set_prescribed_velocity()): a support moving at the start
     * moves the DoFs it holds.
     */
    void
    start_state(VectorType &u, VectorType &v) const;

    /// The mass matrix (unconstrained); empty for quasi-static runs.
    const MatrixType &
    mass_matrix() const
    {
      return mass;
    }

  private:
    /// Runs steps of @p scheme from @p from to @p to, nominally @p h long.
    void
    advance(IntegrationScheme &scheme,
            double             from,
            double             to,
            double             h,
            VectorType        &u,
            VectorType        &v,
            const Observer    &on_converged);

    /**
     * One attempt of a step of @p scheme from the state (u, v) at @p time
     * to @p end_time; on success updates them and the model's state and
     * returns true. A failed or throwing attempt leaves the model's state
     * (StateGuard), @p u and @p v as they were.
     */
    bool
    step(IntegrationScheme &scheme,
         double             time,
         double             end_time,
         VectorType        &u,
         VectorType        &v,
         JudgedResult      &result);

    /// The predictor of the step from (@p u, @p v) at @p time to
    /// @p end_time into @p x; false, with a failed @p result, where a
    /// prescribed rotation turns by half a turn or more within the step.
    bool
    predict_step(double            time,
                 double            end_time,
                 const VectorType &u,
                 const VectorType &v,
                 VectorType       &x,
                 JudgedResult     &result) const;

    /// Newton for the step @p start from the predictor @p x: modified
    /// Newton where the scheme is dynamic and modified_newton is on, full
    /// Newton from the same predictor where that fails; a state that is
    /// not finite is a failure.
    void
    solve_newton(IntegrationScheme &scheme,
                 const StepStart   &start,
                 VectorType        &x,
                 JudgedResult      &result);

    /// Commits the converged @p x of the step @p start from @p time to
    /// @p end_time: the internal variables, the velocity (zero on rows
    /// without mass), the work of the step, the reference reset (which
    /// changes the twist DoFs of @p x); then
    /// @p u = @p x.
    void
    commit_step(IntegrationScheme &scheme,
                const StepStart   &start,
                double             time,
                double             end_time,
                VectorType        &x,
                VectorType        &u,
                VectorType        &v);

    /// The predictor of a step of length @p h from (u, v), at the
    /// prescribed values of @p end_time (throws std::runtime_error for a
    /// prescribed rotation of half a turn or more within the step).
    VectorType
    predict(const VectorType &u,
            const VectorType &v,
            double            h,
            double            end_time) const;

    /// Newton for the step @p start of @p scheme from @p x, judged by the
    /// criterion of statics (by modified Newton if @p modified); a throw
    /// becomes a failed @p result.
    void
    solve_step(IntegrationScheme &scheme,
               const StepStart   &start,
               VectorType        &x,
               JudgedResult      &result,
               bool               modified = false);

    /// The mass and drag matrices of the rods' @p inertia (constructor,
    /// dynamic schemes).
    void
    assemble_inertia(const std::vector<RodInertia> &inertia);

    /// The force and moment scales of the step @p start's tolerance, from
    /// the predictor @p x: the loads' and the predictor's out-of-balance
    /// force; @p problem then gives its values at x without evaluating
    /// again.
    ResidualParts
    step_scale(IntegrationScheme     &scheme,
               const StepStart       &start,
               NewtonSolver::Problem &problem,
               const VectorType      &x);

    /// C = alpha M + beta K(@p u) + drag at the start of a dynamic run at
    /// @p load_factor (nothing without damping).
    void
    assemble_damping(const VectorType &u, double load_factor);

    /// After a failed step from @p time of @p length: the halved attempt,
    /// or SolverFailure below min_step_fraction of @p h.
    double
    halve_step(const IntegrationScheme &scheme,
               double                   time,
               double                   length,
               double                   h,
               const JudgedResult      &result) const;

    /// What the observer sees of the step to @p time that @p result
    /// accepted, with its checks (check_state()).
    StepInfo
    describe_step(const IntegrationScheme &scheme,
                  double                   time,
                  double                   length,
                  const VectorType        &u,
                  const VectorType        &v,
                  const JudgedResult      &result);

    /// Starts the energy watch at the start (@p from) of a run of
    /// @p scheme.
    void
    watch_energy(const IntegrationScheme &scheme,
                 double                   from,
                 const VectorType        &u,
                 const VectorType        &v);

    /// Throws SolverFailure for an energy of @p info that is not finite
    /// or whose balance (EnergyBalance) grew beyond the limit.
    void
    check_energy(const IntegrationScheme &scheme, const StepInfo &info);

    /// Stability and rounding (quasi-static steps, check_equilibrium()) and
    /// the strain range of the converged @p u that @p result accepted into
    /// @p info, with warnings on the log.
    void
    check_state(const IntegrationScheme &scheme,
                const VectorType        &u,
                const JudgedResult      &result,
                StepInfo                &info);

    /// Whether the potential is the same under the load factors @p a and
    /// @p b: they are equal, or nothing in the model follows the load
    /// factor (SolvableModel::potential_follows_load_factor()).
    bool
    same_potential_load(double a, double b) const;

    /// Pi at the converged @p x of the step @p start (before the reference
    /// reset) where its scheme assembled it at the load factor of
    /// @p end_time and the fields there (@p load_time_fields those of the
    /// step's load time; the model at @p end_time), else NaN.
    double
    energy_at_end(const IntegrationScheme   &scheme,
                  const StepStart           &start,
                  double                     end_time,
                  const std::vector<double> &load_time_fields,
                  const VectorType          &x) const;

    /// Remembers Pi = @p energy of the converged @p u at @p load_factor
    /// and the model's time factors (describe_step()).
    void
    remember_energy(const VectorType &u, double load_factor, double energy);

    /// The remembered Pi where @p u, @p load_factor and the model's time
    /// factors are those it was assembled at (the same assembly: the same
    /// value to the bit), else NaN.
    double
    known_energy(const VectorType &u, double load_factor) const;

    SolvableModel    &model;
    Parameters        parameters;
    std::ostream     *log;
    ResidualCriterion criterion;
    StrainMonitor     strains;
    /// Rounding noise of the residual, measured every noise_interval steps.
    RoundoffNoise                 noise;
    unsigned int                  steps_since_noise = 0;
    static constexpr unsigned int noise_interval    = 20;
    MatrixType                    mass; ///< unconstrained
    MatrixType constrained_mass;        ///< fixed rows and columns zero
    /// The entries of mass that are not zero, in a pattern of their own:
    /// the products of a step (the schemes', the energies') cost what M's
    /// entries do, not K's pattern.
    MatrixType mass_nonzeros;
    /// The damping matrix C (empty without damping), for the residual and
    /// for the tangent (fixed rows and columns zero but K_0's diagonal);
    /// both condense the clamps' constraints, as the mass matrix does.
    MatrixType damping, constrained_damping;
    /// The drag matrix (lumped, c per length on the positions), kept to
    /// form C at the start of a run; unconstrained and constrained.
    MatrixType drag, constrained_drag;
    MatrixType tangent;
    /// The tangent's factorization, kept across Newton solves.
    TangentFactorizationCache factorizations;
    /// This process's rows with a zero mass diagonal.
    std::vector<global_dof_index> massless_rows;
    StepSystem                    system{model,
                      mass_nonzeros,
                      constrained_mass,
                      massless_rows,
                      damping,
                      constrained_damping,
                      parameters.spectral_radius_at_infinity};
    /// The scheme of Parameters::integrator, and the quasi-static one of
    /// the preload.
    std::unique_ptr<IntegrationScheme> scheme, preload_scheme;
    /// The energy watch of dynamic runs.
    EnergyBalance energy_balance{model, mass_nonzeros, damping};
    /// Pi of the last converged state, with what it was assembled at: the
    /// midpoint rule's next step starts from it (StepStart::start_energy).
    struct ConvergedEnergy
    {
      VectorType          u;
      double              load_factor = 0;
      std::vector<double> time_factors;
      double              value = 0;
      bool                known = false;
    } converged_energy;
    /// The converged state's energy of the step just committed where its
    /// scheme knows it (energy_at_end()), for describe_step(); else NaN.
    double step_energy = std::numeric_limits<double>::quiet_NaN();
    /// u_n - u_{n-1} and its step length (0: none yet), for the predictor.
    VectorType   last_increment;
    double       last_step_length = 0;
    unsigned int n_steps          = 0;
  };
} // namespace rodnet

#endif
