#ifndef RODNET_SOLVERS_CONTINUATION_ARCLENGTH_CONTINUATION_H
#define RODNET_SOLVERS_CONTINUATION_ARCLENGTH_CONTINUATION_H

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <core/solvable_model.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/residual_criterion.h>
#include <solvers/checks/strain_range.h>
#include <solvers/newton/tangent_factorization.h>

#include <array>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * Pseudo-arclength continuation (Keller 1977) of the equilibria of a
   * SolvableModel in the load factor lambda: the path (u(s), lambda(s)) is
   * followed by steps of length ds along its tangent t, each corrected by
   * Newton on the bordered system
   *
   *   [ K        R_lambda ] [du     ]     [ R                          ]
   *   [ W t_u^T  t_lambda ] [dlambda] = - [ t.W (u - u0, lambda - l0) - ds ]
   *
   * (block elimination with two solves of the tangent K per iteration), so
   * that it passes limit points, where K is singular and lambda turns,
   * in either direction. R_lambda is the change of the residual with the
   * load factor, prescribed DoFs moving with it (central differences). The
   * norm W weighs positions by 1 / L^2 (L the model's length scale) and
   * angles by 1: ds is dimensionless.
   *
   * At every converged point the constrained tangent's negative
   * eigenvalues are counted (its inertia, check_equilibrium()). Where the
   * count changes while lambda keeps its direction, the path has crossed a
   * bifurcation: it is located by bisection of the step to
   * Parameters::bifurcation_tolerance in lambda, and, if asked, the path
   * switches there to the branch along the tangent's null vector (inverse
   * iteration on the tangent at the bracket). A change of direction of
   * lambda is a limit point (fold), reported with lambda at the turn; with
   * Parameters::snap_at_limit_points, at a maximum of lambda the path
   * jumps instead, as a structure under a growing load snaps, to a stable
   * state just past it (snap(), solvers/continuation/arclength_snap.cc).
   *
   * The reference configuration is reset at every converged point, as in
   * load stepping (StaticSolver).
   */
  class ArclengthContinuation
  {
  public:
    struct Parameters
    {
      /// Length of the first step (dimensionless arclength, see above).
      double initial_step = 0.05;
      double min_step     = 1e-6;
      double max_step     = 0.5;
      /// The path ends where lambda leaves [lower_limit, upper_limit],
      /// landing on the limit.
      double lower_limit = -1;
      double upper_limit = 1;
      /// Most converged points before the run stops with SolverFailure.
      unsigned int max_steps = 500;
      /// Step lengths adapt so that the corrector takes about this many
      /// iterations.
      unsigned int target_iterations = 6;
      unsigned int max_iterations    = 15;
      /// As StaticSolver::Parameters::relative_tolerance.
      double relative_tolerance = 1e-9;
      /// Load factors the path lands on exactly (with a corrector at fixed
      /// lambda), in any order.
      std::vector<double> output_points;
      /// Locate a bifurcation to this bracket width in lambda.
      double bifurcation_tolerance = 1e-8;
      /// At a located bifurcation, follow the branch along the null
      /// vector instead of the branch the path was on.
      bool switch_branches = true;
      /// With switch_branches: once the path has left the range (or Max
      /// points), follow each switched branch's other side too, from its
      /// bifurcation ("Switch branches = both").
      bool follow_both_branches = false;
      /// At a limit point where the load factor would fall, jump as a
      /// load-controlled structure snaps: to a stable equilibrium just past
      /// the fold, found from the fold's state moved along its critical
      /// mode, and follow the path on from there ("Limit points = snap").
      /// Off, the path turns back through the fold.
      bool         snap_at_limit_points = false;
      std::string  linear_solver        = "auto";
      StrainLimits strain_limits;

      /// Declares the entries in the current subsection of @p prm.
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /// Reads the entries of declare_parameters() from the current
      /// subsection of @p prm.
      void
      parse_parameters(const dealii::ParameterHandler &prm);
    };

    /// What a converged point of the path is.
    enum class PointKind
    {
      regular,
      output_point, ///< landed on one of Parameters::output_points
      limit_point,  ///< the path turned back in lambda at this step
      bifurcation,  ///< the stable side of a located bifurcation
      fold,         ///< a located limit point that the path snaps from
      jump          ///< the stable state the path snapped to past a limit point
    };

    struct StepInfo
    {
      unsigned int step        = 0;
      double       load_factor = 0;
      /// Sum of the chords' lengths (W norm) along the path so far.
      double       arclength  = 0;
      unsigned int iterations = 0;
      /// Which branch: 0 from the start, +1 at each switch.
      unsigned int  branch = 0;
      PointKind     kind   = PointKind::regular;
      ResidualParts residual;
      double        wall_time = 0;
      /// The tangent's direction dlambda/ds: negative where lambda falls.
      double           load_factor_rate = 0;
      EquilibriumCheck check;
      StrainRange      strain;
    };

    using Observer =
      std::function<void(const StepInfo &, const VectorType &solution)>;

    /// Throws std::invalid_argument for a model with internal variables
    /// (a viscoelastic material: its response depends on time, which a
    /// path of equilibria does not have).
    ArclengthContinuation(SolvableModel    &model,
                          const Parameters &parameters,
                          std::ostream     *log = nullptr);

    /**
     * Follows the path from the equilibrium @p u at load factor 0 (usually
     * the zero state) until lambda leaves the limits; @p u holds the last
     * point. Calls @p on_converged at every converged point. Throws
     * SolverFailure naming the load factor and the reason where a step
     * fails at the smallest step length or after max_steps points.
     */
    void
    run(VectorType &u, const Observer &on_converged);

    /// Load factors of the located bifurcations, in path order.
    const std::vector<double> &
    bifurcations() const
    {
      return located_bifurcations;
    }

    /// Load factors of the limit points passed (lambda at the turn,
    /// from a parabola through the three points around it, or located by
    /// bisection where the path snaps there).
    const std::vector<double> &
    limit_points() const
    {
      return passed_limit_points;
    }

  private:
    /// A converged point of the path with its tangent (t_u, t_lambda),
    /// unit in the W norm, and the model state it was reached with.
    struct PathPoint
    {
      VectorType   u;
      double       lambda = 0;
      double       s      = 0;
      VectorType   t_u;
      double       t_lambda = 0;
      unsigned int negative = 0;
      /// The symmetry modes at the point (symmetry_modes()), W-orthonormal:
      /// the tangent is singular along them, and steps leave them out.
      std::vector<VectorType> symmetries;
      /// Set once the point is accepted (ModelState has no empty value).
      std::optional<ModelState> state;
    };

    /// The linear constraint n.(u - u0, lambda - lambda0) = length that
    /// closes the corrector's system: the pseudo-arclength condition, or
    /// lambda = target (n_u = 0, n_lambda = 1).
    struct Constraint
    {
      const VectorType *n_u      = nullptr; ///< null: no u part
      double            n_lambda = 1;
      double            length   = 0;
    };

    /// Newton on the bordered system from (@p u, @p lambda), with the
    /// model's reference that of @p base; converged values on return.
    JudgedResult
    correct(const PathPoint  &base,
            const Constraint &constraint,
            VectorType       &u,
            double           &lambda);

    /// The value n.(u - u0, lambda - lambda0) - length of @p constraint at
    /// (@p u, @p lambda) from @p base's (u0, lambda0); @p change is
    /// scratch.
    double
    constraint_value(const PathPoint  &base,
                     const Constraint &constraint,
                     const VectorType &u,
                     double            lambda,
                     VectorType       &change) const;

    /// The load factor change dlambda of the corrector's step du = a -
    /// dlambda b that makes @p constraint, whose value is @p g, hold to
    /// first order (the fixed DoFs move by dlambda @p fixed_rate).
    double
    load_factor_correction(const Constraint &constraint,
                           double            g,
                           const VectorType &a,
                           const VectorType &b,
                           const VectorType &fixed_rate) const;

    /// The path's tangent at the converged @p p (its reference reset),
    /// oriented along @p previous (W inner product), or with lambda
    /// increasing if there is none.
    void
    compute_tangent(PathPoint &p, const PathPoint *previous);

    /// dR/dlambda at (@p u, @p lambda) with the fixed DoFs following
    /// lambda (free rows), and the fixed DoFs' rate in @p fixed_rate.
    void
    load_factor_derivative(const VectorType &u,
                           double            lambda,
                           VectorType       &r_lambda,
                           VectorType       &fixed_rate);

    /// Removes from @p v its W-projection on the W-orthonormal @p modes.
    void
    project_out(VectorType &v, const std::vector<VectorType> &modes) const;

    /// W inner product of two DoF vectors.
    double
    dot_w(const VectorType &a, const VectorType &b) const;

    /// One step of length @p ds from @p p along its tangent, corrected;
    /// false if the corrector fails or lands far from the prediction.
    bool
    step(const PathPoint &p,
         double           ds,
         VectorType      &u,
         double          &lambda,
         JudgedResult    &result);

    /**
     * Replaces the converged step (@p u, @p lambda, @p result) from @p p,
     * which crossed @p target, by the equilibrium at lambda = @p target
     * (from the chord's point there); @p ds becomes its pseudo-arclength
     * from @p p. False (nothing changed) if that corrector fails.
     */
    bool
    land(const PathPoint &p,
         double           target,
         VectorType      &u,
         double          &lambda,
         JudgedResult    &result,
         double          &ds);

    /**
     * Locates the bifurcation between @p lo and @p hi, the point at
     * pseudo-arclength @p ds_hi along lo's tangent, by bisection; returns
     * the stable side's point (lo itself if no closer one was found),
     * converged and accepted (@p info). Throws SolverFailure where the
     * bisection fails or the bracket's states do not meet
     * (require_continuous_bracket()).
     */
    PathPoint
    locate_bifurcation(const PathPoint &lo,
                       const PathPoint &hi,
                       double           ds_hi,
                       StepInfo        &info);

    /// The point at pseudo-arclength @p s along @p base's tangent (the
    /// constraint of a step of that length from @p base), predicted from
    /// the bracket's point (@p u_from, @p lambda_from) at @p s_from and
    /// corrected: the bisections' midpoint. The model's reference must be
    /// base's.
    JudgedResult
    point_along(const PathPoint  &base,
                double            s_from,
                const VectorType &u_from,
                double            lambda_from,
                double            s,
                VectorType       &u,
                double           &lambda);

    /// Throws SolverFailure where the states @p u_lo, @p u_hi that bracket
    /// a change of the negative eigenvalues are further apart than 1e-3 of
    /// the step from @p lo to @p hi (W norm with the load factor): they
    /// lie on two branches, and the change is a jump between them.
    void
    require_continuous_bracket(const PathPoint  &lo,
                               const PathPoint  &hi,
                               const VectorType &u_lo,
                               double            lambda_lo,
                               const VectorType &u_hi,
                               double            lambda_hi);

    /// Turns @p p's tangent to the null vector of the tangent stiffness at
    /// @p p (inverse iteration), W-orthogonal to the path it leaves, unit.
    void
    turn_to_null_vector(PathPoint &p);

    /**
     * The step from @p p to @p q (whose @p q_info is ready) crossed a
     * bifurcation: locates it, reports it, and either reports q and makes
     * it @p p, or (switch_branches) makes @p p the bifurcation point with
     * its tangent along the new branch. False where the bisection finds no
     * path from @p p to @p q's count (the step jumped onto another branch;
     * the caller halves it), unless the step is already the shortest.
     */
    bool
    follow_bifurcation(PathPoint       &p,
                       const PathPoint &q,
                       double           ds,
                       StepInfo        &q_info,
                       const Observer  &on_converged);

    /**
     * Locates the limit point between @p p, where the load factor rises,
     * and the point at pseudo-arclength @p ds along p's tangent, where it
     * falls, by bisection on the sign of dlambda/ds (and on the count of
     * negative eigenvalues, one of which crosses zero there); returns the
     * last point found before the turn (p itself if none is closer),
     * accepted (@p info), its tangent along the critical mode.
     */
    PathPoint
    locate_fold(const PathPoint &p, double ds, StepInfo &info);

    /**
     * Snapping at a limit point (Parameters::snap_at_limit_points): the
     * step of pseudo-arclength @p ds from @p p passed a maximum of the
     * load factor. Reports the fold, solves for a stable state just
     * past it (jump_past_fold()), reports that as the start of a new branch
     * and makes it @p p. Throws SolverFailure where no stable state is
     * found.
     */
    void
    snap(PathPoint &p, double ds, const Observer &on_converged);

    /**
     * A stable equilibrium at load factor @p lambda, past the fold @p fold,
     * found by the first of land_nearby(), descend() and follow_to_load()
     * that finds one. False (@p u undefined) if none does; @p tried says
     * what each gave.
     */
    bool
    jump_past_fold(const PathPoint &fold,
                   double           lambda,
                   VectorType      &u,
                   JudgedResult    &result,
                   std::string     &tried);

    /// Newton at @p lambda from @p fold's state, with the globalization
    /// @p line_search ("full step" or "trust region") and at most
    /// @p iterations iterations; true where it converges on a stable state
    /// (and, with @p within, no farther from the fold than that, W norm).
    bool
    solve_past_fold(const PathPoint   &fold,
                    double             lambda,
                    const std::string &line_search,
                    unsigned int       iterations,
                    double             within,
                    VectorType        &u,
                    JudgedResult      &result,
                    std::string       &tried);

    /**
     * The path followed on from @p fold, each point unreported, until it
     * comes back to the load factor @p lambda with the load factor rising;
     * the equilibrium there (land()) where it is stable. At most
     * Parameters::max_steps points. False (@p u undefined) otherwise.
     */
    bool
    follow_to_load(const PathPoint &fold,
                   double           lambda,
                   VectorType      &u,
                   JudgedResult    &result,
                   std::string     &tried);

    /// The next step length after a corrector of @p iterations iterations
    /// with step @p ds: ds scaled towards the target iterations.
    double
    next_step_length(double ds, unsigned int iterations) const;

    /**
     * Follows the path from @p p with first step length @p ds until it
     * leaves the load factor range; throws SolverFailure where a step
     * fails down to the minimum step or the points run out.
     */
    void
    follow_path(PathPoint &p, double ds, const Observer &on_converged);

    /// Throws SolverFailure, standing at @p p, where the path has used up
    /// its Parameters::max_steps points inside the load factor range.
    void
    check_points_left(const PathPoint &p) const;

    /**
     * A step() of length @p ds from @p p to (@p u, @p lambda); where it
     * crosses an output load factor, land()ed there instead (@p ds then
     * the pseudo-arclength to the landing) and marked an output point in
     * @p info. False if the step or the landing fails.
     */
    bool
    step_onto_path(const PathPoint &p,
                   double          &ds,
                   VectorType      &u,
                   double          &lambda,
                   JudgedResult    &result,
                   StepInfo        &info);

    /// Marks the step from @p p to @p q, across which t_lambda changes
    /// sign, as passing a limit point in @p info, and records (and logs)
    /// the limit load factor estimated from the points around it.
    void
    note_limit_point(const PathPoint &p, const PathPoint &q, StepInfo &info);

    /// Numbers, times, reports and observes the converged @p p.
    void
    finish_point(StepInfo        &info,
                 const PathPoint &p,
                 const Observer  &on_converged);

    /// Makes (@p u, @p lambda) a point of the path after @p previous: the
    /// reference reset, its tangent, checks; fills @p info.
    PathPoint
    accept(const VectorType   &u,
           double              lambda,
           const PathPoint    *previous,
           const JudgedResult &result,
           StepInfo           &info);

    /// The output point or limit between lambda0 and lambda1 (exclusive
    /// of lambda0) nearest to lambda0, if there is one.
    std::optional<double>
    crossed_target(double lambda0, double lambda1) const;

    void
    report(const StepInfo &info) const;

    /// @p value in the shortest form that keeps 10 digits, for messages.
    static std::string
    number(double value);

    SolvableModel            &model;
    Parameters                parameters;
    std::ostream             *log;
    ResidualCriterion         criterion;
    StrainMonitor             strains;
    MatrixType                tangent;
    TangentFactorizationCache factorizations;
    /// Diagonal of the norm W.
    VectorType          weights;
    std::vector<double> located_bifurcations;
    std::vector<double> passed_limit_points;

    /// Where run() stands: the points reported, the branch, the (s,
    /// lambda) of the last three points, whether the last step switched
    /// branches, the time since the last point.
    unsigned int                             n_points = 0;
    unsigned int                             branch   = 0;
    std::array<std::pair<double, double>, 3> recent{};
    /// Points reported since the path (re)started: recent holds as many.
    unsigned int points_on_path = 0;
    bool         just_switched  = false;
    /// The other sides of switched branches, for follow_both_branches:
    /// the bifurcation points with their tangents turned around.
    std::vector<std::pair<PathPoint, StepInfo>> other_sides;
    dealii::Timer                               timer;
  };
} // namespace rodnet

#endif
