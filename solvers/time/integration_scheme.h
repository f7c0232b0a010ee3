#ifndef RODNET_SOLVERS_TIME_INTEGRATION_SCHEME_H
#define RODNET_SOLVERS_TIME_INTEGRATION_SCHEME_H

#include <core/solvable_model.h>
#include <solvers/newton/newton_solver.h>

#include <limits>
#include <string>
#include <vector>

namespace rodnet
{
  /// What the integration schemes of a TimeIntegrator share: the model and
  /// its mass matrix M (empty for quasi-static runs).
  struct StepSystem
  {
    SolvableModel    &model;
    const MatrixType &mass;             ///< unconstrained
    const MatrixType &constrained_mass; ///< fixed rows and columns zero
    /// The rows of this process's DoFs with a zero mass diagonal (junction
    /// quaternions without a body): they have no velocity or acceleration.
    const std::vector<global_dof_index> &massless_rows;
    /// The damping matrix C, empty (m() == 0) without damping.
    const MatrixType &damping; ///< unconstrained
    /// Fixed rows and columns zero but the tangent's diagonal there.
    const MatrixType &constrained_damping;
    /// The spectral radius at omega h -> infinity that a scheme with
    /// controllable numerical dissipation is asked for (generalized alpha).
    double spectral_radius_at_infinity = 1;

    /// Sets the massless rows of @p v to zero.
    void
    zero_massless_rows(VectorType &v) const;
  };

  /// The velocity at which a scheme's damping force C v acts, in terms of
  /// the step's unknown u: v = a (u - u_n) - b v_n.
  struct DampingVelocity
  {
    double a;
    double b;
  };

  /// A point y = (1 - s) u_n + s u_{n+1} of a step and a weight.
  struct ForcePoint
  {
    double s;
    double weight;
  };

  /// One step of length h from the state (u_n, v_n).
  struct StepStart
  {
    const VectorType &u;    ///< u_n
    const VectorType &base; ///< u_n + h v_n
    double            h;
    /// The load factor at the scheme's load_time().
    double load_factor;
    /// Pi(u_n) at load_factor where the integrator knows it already (the
    /// last converged state's energy, assembled at the same inputs), else
    /// NaN.
    double start_energy = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * The time discretization of one step of a TimeIntegrator (the equations
   * are listed there): the nonlinear system for u_{n+1} that NewtonSolver
   * solves, and the velocity that follows. TimeIntegrator does the rest,
   * the same for every scheme: the predictor, the tolerance, the Newton
   * solve, step cutting, commit and checks. A new scheme is a class
   * deriving from this one in a file pair of its own, registered by name in
   * integration_scheme_registry.cc.
   *
   * The functions a scheme puts into a NewtonSolver::Problem are called
   * once per Newton iteration (never per stencil), so that they are
   * virtual costs nothing measurable.
   */
  class IntegrationScheme
  {
  public:
    explicit IntegrationScheme(const StepSystem &system)
        : system(system)
    {
    }

    virtual ~IntegrationScheme() = default;

    /// The name that selects the scheme (TimeIntegrator's Integrator).
    virtual std::string
    name() const = 0;

    /// Pi at @p x where the last residual of the step assembled it there,
    /// at the step's load factor and fields, else NaN: the converged
    /// state's energy without another assembly.
    virtual double
    energy_at(const VectorType & /*x*/) const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Whether the scheme has inertia (needs the mass matrix): its
    /// registered trait (IntegrationSchemeTraits).
    bool
    dynamic() const;

    /// Whether the scheme needs a stored energy, which materials with
    /// internal variables do not have: its registered trait.
    bool
    needs_stored_energy() const;

    /// Whether set_up() gives the step's incremental potential
    /// (NewtonSolver::Problem::energy), which the energy line search needs.
    virtual bool
    has_incremental_potential() const
    {
      return true;
    }

    /// Whether the scheme carries the orientation-dependent inertia of rigid
    /// bodies with a general inertia tensor (BodyRotationInertia).
    virtual bool
    carries_inertia_tensors() const
    {
      return false;
    }

    /// Whether the total energy of a stable run under constant loads never
    /// grows, so that TimeIntegrator's energy watch may take growth for an
    /// instability.
    virtual bool
    energy_never_grows() const
    {
      return true;
    }

    /// What to try, besides a smaller time step, when the energy of a run
    /// with this scheme grows (appended to the message).
    virtual std::string
    instability_advice() const
    {
      return "";
    }

    /**
     * Where the step's balance of momentum M (v_{n+1} - v_n) / h + f = R
     * takes the internal force: f = sum_k w_k grad Pi((1 - s_k) u_n + s_k
     * u_{n+1}) under the loads and fields of the time t_n + s_k h (the
     * mass term's correction and forces that do no work aside), so that
     * the work of the loads and of a moving support's reaction R is the
     * one the step's energy balance holds with (EnergyBalance). The
     * trapezoidal rule's: Newmark's, whose M (v_{n+1} - v_n) / h is the
     * mean of M a_n and M a_{n+1}, each under its own loads.
     */
    virtual std::vector<ForcePoint>
    force_points() const
    {
      return {{0, 0.5}, {1, 0.5}};
    }

    /// Time at which the loads of the step from @p start to @p end act
    /// (the end: there exactly, which discontinuous loads need).
    virtual double
    load_time(const double start, const double end) const
    {
      (void)start;
      return end;
    }

    /// Coefficient c of the mass term c M (u - u_n - h v_n).
    virtual double
    mass_coefficient(double h) const = 0;

    /**
     * The velocity of the damping force C v of a step of length @p h: the
     * velocity of the step's equation of motion (backward Euler:
     * (u - u_n)/h; Newmark: v_{n+1} = 2 (u - u_n)/h - v_n; midpoint:
     * (v_n + v_{n+1})/2 = (u - u_n)/h, which makes the energy fall by
     * exactly the dissipated work h vbar.C vbar).
     */
    virtual DampingVelocity
    damping_velocity(const double h) const
    {
      return {1 / h, 0};
    }

    /// Called once before the first step from @p u, @p v at
    /// @p load_factor.
    virtual void
    start(const VectorType &u, const VectorType &v, const double load_factor)
    {
      (void)u;
      (void)v;
      (void)load_factor;
    }

    /**
     * Puts the residual and tangent of the step @p step into @p problem
     * (which then refers to this scheme and to @p step: both must outlive
     * the solve). Called after the model's time step is set; may evaluate
     * the model and throw.
     */
    virtual void
    set_up(const StepStart &step, NewtonSolver::Problem &problem);

    /**
     * The velocity @p v (v_n on entry) at the converged @p x = u_{n+1},
     * and whatever else the scheme carries to the next step. The rows
     * without mass are TimeIntegrator's to zero.
     */
    virtual void
    finish(const StepStart &step, const VectorType &x, VectorType &v) = 0;

    /**
     * The model's unconstrained residual at @p x and the load factor of the
     * step set_up() last prepared (SolvableModel::assemble() without
     * constraints or extra force) if the scheme needs it later in that
     * step, then assembled once for both; else null. The tolerance's load
     * scale takes it instead of assembling it again.
     */
    virtual const VectorType *
    shared_gradient(const VectorType &x)
    {
      (void)x;
      return nullptr;
    }

  protected:
    /**
     * Adds c M (@p y - base) (and -extra_inertial_force()) to @p r (if not
     * null), then zeroes its fixed rows; returns the potential of those
     * terms, c/2 (y - base).M(y - base) - p.y. Nothing without inertia.
     */
    double
    add_inertia(const StepStart &step, const VectorType &y, VectorType *r);

    /**
     * The damping force C v of damping_velocity() at @p y added to @p r
     * (if not null; its fixed rows are left to the caller), and its
     * potential a/2 (y - u_n).C(y - u_n) - b y.C v_n. Nothing without
     * damping.
     */
    double
    add_damping(const StepStart &step, const VectorType &y, VectorType *r);

    /// The damping's tangent a C added to @p k (constrained).
    void
    add_damping_tangent(double h, MatrixType &k) const;

    /// A force the scheme adds to the residual of its mass term, or null.
    virtual const VectorType *
    extra_inertial_force() const
    {
      return nullptr;
    }

    /**
     * The out-of-balance force lambda f - grad Pi(@p u) - C @p v of the
     * start, M a_0, on the rows that carry mass (zero on the others), into
     * @p force: the inertial force of the start that Newmark and
     * generalized alpha carry.
     */
    void
    initial_inertial_force(const VectorType &u,
                           const VectorType &v,
                           double            load_factor,
                           VectorType       &force) const;

    /// v = (x - u_n) / h.
    static void
    first_order_velocity(const StepStart  &step,
                         const VectorType &x,
                         VectorType       &v);

    /// v = 2 (x - u_n) / h - v_n (the trapezoidal rule's).
    static void
    second_order_velocity(const StepStart  &step,
                          const VectorType &x,
                          VectorType       &v);

    const StepSystem &system;
    /// Scratch: x - base and M (x - base); the damping velocity and C v.
    VectorType difference, product, damped_velocity, damping_force;
  };
} // namespace rodnet

#endif
