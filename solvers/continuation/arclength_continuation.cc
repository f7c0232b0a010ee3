#include <deal.II/base/timer.h>

#include <solvers/checks/free_motions.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/stability/stability.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace rodnet
{
  namespace
  {
    std::string
    point_name(const ArclengthContinuation::PointKind kind)
    {
      switch (kind)
        {
          case ArclengthContinuation::PointKind::output_point:
            return " (output point)";
          case ArclengthContinuation::PointKind::limit_point:
            return " (past a limit point)";
          case ArclengthContinuation::PointKind::bifurcation:
            return " (bifurcation)";
          case ArclengthContinuation::PointKind::fold:
            return " (limit point)";
          case ArclengthContinuation::PointKind::jump:
            return " (snapped to, past a limit point)";
          default:
            return "";
        }
    }

    /**
     * When a corrector ends: the tolerance of its residual, judged at its
     * start (start()), and the test of each iterate (reached()).
     */
    class CorrectorEnd
    {
    public:
      /// The end of a corrector under @p parameters whose constraint has
      /// the length @p constraint_length.
      CorrectorEnd(const ResidualCriterion                 &criterion,
                   const ArclengthContinuation::Parameters &parameters,
                   const double                             constraint_length)
          : criterion(criterion)
          , parameters(parameters)
          , constraint_length(constraint_length)
      {
      }

      /// Judges the residuals of a corrector from (@p u, @p load_factor):
      /// sets the rounding noise, the loads' scale and whether rounding
      /// limits the residual in @p result, and the tolerance.
      void
      start(const VectorType &u, const double load_factor, JudgedResult &result)
      {
        result.noise = criterion.roundoff_noise(u, load_factor);
        result.scale =
          criterion.judging_scale(u, load_factor, result.noise.floor);
        result.rounding_limited =
          ResidualCriterion::inconclusive(result.noise.floor,
                                          result.scale,
                                          1e-3);
        tolerance = ResidualCriterion::tolerance(result.scale,
                                                 result.noise.floor,
                                                 parameters.relative_tolerance);
      }

      /**
       * Whether the corrector ends at its iterate, whose residual @p result
       * holds and whose constraint residual is @p g: converged (the
       * tolerance met and g within 1e-10 of the larger of the constraint's
       * length and the smallest step), or failed (a residual not finite,
       * the iterations spent); @p result says which.
       */
      bool
      reached(const double g, JudgedResult &result) const
      {
        if (!std::isfinite(result.residual_norm) || !std::isfinite(g))
          {
            result.failure = "the residual is not finite";
            return true;
          }
        if (ResidualCriterion::within(result.residual, tolerance) &&
            std::abs(g) <= 1e-10 * std::max(std::abs(constraint_length),
                                            parameters.min_step))
          {
            result.converged = true;
            return true;
          }
        if (result.iterations == parameters.max_iterations)
          {
            result.failure =
              "no convergence in " + std::to_string(parameters.max_iterations) +
              " corrector iterations (" +
              ResidualCriterion::describe(result.residual, tolerance) + ")";
            return true;
          }
        return false;
      }

    private:
      const ResidualCriterion                 &criterion;
      const ArclengthContinuation::Parameters &parameters;
      const double                             constraint_length;
      ResidualParts                            tolerance;
    };
  } // namespace

  ArclengthContinuation::ArclengthContinuation(SolvableModel    &model,
                                               const Parameters &parameters,
                                               std::ostream     *log)
      : model(model)
      , parameters(parameters)
      , log(log)
      , criterion(model)
      , strains(model, parameters.strain_limits)
  {
    if (model.has_internal_variables())
      // A path of equilibria has no time: a history-dependent material
      // would answer with an arbitrary rate.
      throw std::invalid_argument(
        "continuation cannot follow a material with internal variables (a "
        "viscoelastic law): its response depends on time; use time "
        "stepping (quasi-static or dynamic, doc/dynamics.md)");
    model.initialize_matrix(tangent);
    weights             = model.create_vector();
    const double length = model.length_scale();
    for (global_dof_index i = 0; i < criterion.roles().n_dofs(); ++i)
      switch (criterion.roles().kind(i))
        {
          case DofRoles::Kind::position:
            weights[i] = 1 / (length * length);
            break;
          case DofRoles::Kind::twist:
          case DofRoles::Kind::shape:
            weights[i] = 1;
            break;
          case DofRoles::Kind::quaternion:
            // A quaternion increment v turns by 2 |v|.
            weights[i] = 4;
            break;
          case DofRoles::Kind::multiplier:
          case DofRoles::Kind::inert:
            // Multipliers follow the path: forces, not a distance along it.
            weights[i] = 0;
            break;
        }
    weights.compress(dealii::VectorOperation::insert);
  }

  double
  ArclengthContinuation::dot_w(const VectorType &a, const VectorType &b) const
  {
    VectorType weighted = a;
    weighted.scale(weights);
    return weighted * b;
  }

  void
  ArclengthContinuation::project_out(VectorType                    &v,
                                     const std::vector<VectorType> &modes) const
  {
    for (const VectorType &m : modes)
      v.add(-dot_w(m, v), m);
  }

  void
  ArclengthContinuation::load_factor_derivative(const VectorType &u,
                                                const double      lambda,
                                                VectorType       &r_lambda,
                                                VectorType       &fixed_rate)
  {
    // Central differences: exact for dead loads and moments (linear in
    // lambda), O(h^2) for prescribed rotations.
    const double h  = 1e-6 * std::max(1.0, std::abs(lambda));
    VectorType   up = u, um = u, rm = model.create_vector();
    model.apply_boundary_values(up, lambda + h);
    model.apply_boundary_values(um, lambda - h);
    model.assemble(up, lambda + h, &r_lambda, nullptr);
    model.assemble(um, lambda - h, &rm, nullptr);
    r_lambda -= rm;
    r_lambda /= 2 * h;
    fixed_rate = up;
    fixed_rate -= um;
    fixed_rate /= 2 * h;
  }

  JudgedResult
  ArclengthContinuation::correct(const PathPoint  &base,
                                 const Constraint &constraint,
                                 VectorType       &u,
                                 double           &lambda)
  {
    JudgedResult result;
    VectorType   r = model.create_vector(), r_lambda = r, fixed_rate = r, a = r,
               b = r, change = r;
    try
      {
        model.apply_boundary_values(u, lambda);
        CorrectorEnd corrector_end(criterion, parameters, constraint.length);
        corrector_end.start(u, lambda, result);
        const auto factorization =
          factorizations.get(tangent, parameters.linear_solver);
        for (result.iterations = 0;; ++result.iterations)
          {
            model.assemble(u, lambda, &r, &tangent);
            result.residual      = criterion.norms(u, r);
            result.residual_norm = r.l2_norm();
            const double g =
              constraint_value(base, constraint, u, lambda, change);
            if (corrector_end.reached(g, result))
              return result;
            // Block elimination of the bordered system: K a = -R,
            // K b = R_lambda, du = a - dlambda b. R_lambda is taken at the
            // start of the corrector and kept: it is constant for dead
            // loads and changes little over a step otherwise, and two
            // residual assemblies per iteration would double its cost.
            if (result.iterations == 0)
              load_factor_derivative(u, lambda, r_lambda, fixed_rate);
            factorization->factorize();
            r *= -1;
            factorization->solve(r, a);
            factorization->solve(r_lambda, b);
            // Along a symmetry the tangent is singular and the residual
            // does not change: those components are rounding, left out.
            project_out(a, base.symmetries);
            project_out(b, base.symmetries);
            const double dlambda =
              load_factor_correction(constraint, g, a, b, fixed_rate);
            u.add(1.0, a, -dlambda, b);
            lambda += dlambda;
            model.apply_boundary_values(u, lambda);
          }
      }
    catch (const std::exception &e)
      {
        result.converged = false;
        result.failure   = e.what();
      }
    return result;
  }

  double
  ArclengthContinuation::constraint_value(const PathPoint  &base,
                                          const Constraint &constraint,
                                          const VectorType &u,
                                          const double      lambda,
                                          VectorType       &change) const
  {
    change = u;
    change -= base.u;
    return (constraint.n_u ? dot_w(*constraint.n_u, change) : 0.0) +
           constraint.n_lambda * (lambda - base.lambda) - constraint.length;
  }

  double
  ArclengthContinuation::load_factor_correction(
    const Constraint &constraint,
    const double      g,
    const VectorType &a,
    const VectorType &b,
    const VectorType &fixed_rate) const
  {
    if (!constraint.n_u)
      return -g / constraint.n_lambda;
    return -(g + dot_w(*constraint.n_u, a)) /
           (constraint.n_lambda + dot_w(*constraint.n_u, fixed_rate) -
            dot_w(*constraint.n_u, b));
  }

  void
  ArclengthContinuation::compute_tangent(PathPoint       &p,
                                         const PathPoint *previous)
  {
    VectorType r_lambda = model.create_vector(), fixed_rate = r_lambda,
               b = r_lambda;
    load_factor_derivative(p.u, p.lambda, r_lambda, fixed_rate);
    model.assemble(p.u, p.lambda, nullptr, &tangent);
    bool solved = true;
    try
      {
        const auto factorization =
          factorizations.get(tangent, parameters.linear_solver);
        factorization->factorize();
        factorization->solve(r_lambda, b);
      }
    catch (const SingularTangent &)
      {
        // Exactly at a singular point: the secant stands in.
        solved = false;
      }
    if (solved)
      {
        // du/dlambda: the fixed DoFs' rate, and K^-1 (-R_lambda) on the
        // free ones (b is zero at the fixed rows).
        project_out(b, p.symmetries);
        p.t_u = fixed_rate;
        p.t_u -= b;
        p.t_lambda = 1;
      }
    else if (previous != nullptr)
      {
        p.t_u = p.u;
        p.t_u -= previous->u;
        p.t_lambda = p.lambda - previous->lambda;
      }
    else
      throw SolverFailure("the tangent at load factor " + number(p.lambda) +
                          " is singular: the path has no direction there");
    const double norm =
      std::sqrt(dot_w(p.t_u, p.t_u) + p.t_lambda * p.t_lambda);
    p.t_u /= norm;
    p.t_lambda /= norm;
    // Orient along the chord from the previous point: the tangent is
    // continuous through a limit point, where dlambda/ds changes sign.
    if (previous != nullptr)
      {
        VectorType chord = p.u;
        chord -= previous->u;
        if (dot_w(p.t_u, chord) + p.t_lambda * (p.lambda - previous->lambda) <
            0)
          {
            p.t_u *= -1;
            p.t_lambda *= -1;
          }
      }
  }

  bool
  ArclengthContinuation::step(const PathPoint &p,
                              const double     ds,
                              VectorType      &u,
                              double          &lambda,
                              JudgedResult    &result)
  {
    model.set_state(*p.state);
    u = p.u;
    u.add(ds, p.t_u);
    lambda = p.lambda + ds * p.t_lambda;
    result = correct(p, Constraint{&p.t_u, p.t_lambda, ds}, u, lambda);
    if (!result.converged)
      return false;
    // A corrector that lands farther from the prediction than the step is
    // long has likely jumped to another branch.
    VectorType miss = u;
    miss -= p.u;
    miss.add(-ds, p.t_u);
    const double dl = lambda - p.lambda - ds * p.t_lambda;
    if (std::sqrt(dot_w(miss, miss) + dl * dl) > ds)
      {
        result.converged = false;
        result.failure   = "the corrector left the step's neighbourhood";
        return false;
      }
    return true;
  }

  ArclengthContinuation::PathPoint
  ArclengthContinuation::accept(const VectorType   &u,
                                const double        lambda,
                                const PathPoint    *previous,
                                const JudgedResult &result,
                                StepInfo           &info)
  {
    PathPoint q;
    q.u = u;
    if (previous != nullptr)
      {
        VectorType chord = u;
        chord -= previous->u;
        const double dl = lambda - previous->lambda;
        q.s = previous->s + std::sqrt(dot_w(chord, chord) + dl * dl);
      }
    q.lambda = lambda;
    model.reset_reference(q.u);
    q.state = model.state();
    for (VectorType &m : symmetry_modes(model, q.u, lambda))
      {
        // Gram-Schmidt in the W inner product.
        project_out(m, q.symmetries);
        const double norm = std::sqrt(dot_w(m, m));
        if (norm > 1e-8)
          {
            m /= norm;
            q.symmetries.push_back(std::move(m));
          }
      }
    compute_tangent(q, previous);
    info.load_factor      = lambda;
    info.arclength        = q.s;
    info.iterations       = result.iterations;
    info.residual         = result.residual;
    info.load_factor_rate = q.t_lambda;
    info.check            = check_equilibrium(model,
                                   criterion,
                                   q.u,
                                   lambda,
                                   tangent,
                                   result,
                                   1e-6,
                                   &factorizations);
    refuse_undetermined_state(info.check,
                              1e-3,
                              "load factor " + number(lambda));
    info.strain = strains.evaluate(q.u);
    q.negative  = info.check.negative_eigenvalues;
    return q;
  }

  std::optional<double>
  ArclengthContinuation::crossed_target(const double lambda0,
                                        const double lambda1) const
  {
    std::optional<double> nearest;
    std::vector<double>   targets = parameters.output_points;
    targets.push_back(parameters.lower_limit);
    targets.push_back(parameters.upper_limit);
    const double slack = 1e-12 * std::max(1.0, std::abs(lambda0));
    for (const double t : targets)
      {
        const bool crossed = lambda1 > lambda0 ?
                               (t > lambda0 + slack && t <= lambda1) :
                               (t < lambda0 - slack && t >= lambda1);
        if (crossed &&
            (!nearest || std::abs(t - lambda0) < std::abs(*nearest - lambda0)))
          nearest = t;
      }
    return nearest;
  }

  std::string
  ArclengthContinuation::number(const double value)
  {
    std::ostringstream out;
    out << std::setprecision(10) << value;
    return out.str();
  }

  void
  ArclengthContinuation::report(const StepInfo &info) const
  {
    if (log == nullptr)
      return;
    *log << "step " << info.step << ": load factor " << info.load_factor
         << ", arclength " << info.arclength << ", " << info.iterations
         << " iteration(s)" << point_name(info.kind);
    if (!info.check.stable)
      *log << ", unstable (" << info.check.negative_eigenvalues
           << " negative eigenvalue(s))";
    *log << std::endl;
    const std::string strain_warning = strains.warning(info.strain);
    if (!strain_warning.empty())
      *log << strain_warning << std::endl;
    if (!info.check.rounding_warning.empty())
      *log << "warning: rounding leaves the state at load factor "
           << info.load_factor << " uncertain by "
           << info.check.rounding_uncertainty
           << " of the model size: " << info.check.rounding_warning
           << std::endl;
  }
} // namespace rodnet
