#include <core/every_entry.h>
#include <solvers/newton/trust_region_newton.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/stability/stability.h>

#include <Eigen/Core>
#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    using VectorType = TrustRegionNewton::VectorType;
    using MatrixType = TrustRegionNewton::MatrixType;
    using Parameters = TrustRegionNewton::Parameters;

    /// Every value of @p v, on every process: the subproblem's algebra
    /// (the factorization of the scaled tangent, its eigenpair) is the same
    /// serial work on each process, as the stability check's.
    Eigen::VectorXd
    values_of(const VectorType &v)
    {
      const EveryEntry every(v);
      Eigen::VectorXd  result((*every).size());
      std::copy((*every).begin(), (*every).end(), result.data());
      return result;
    }

    /// No constraints: the scaled tangent is factorized whole (the rows of
    /// fixed DoFs hold their diagonal only, and the residual is zero there,
    /// so steps leave them alone).
    const dealii::AffineConstraints<double> &
    no_constraints()
    {
      static const dealii::AffineConstraints<double> none = [] {
        dealii::AffineConstraints<double> c;
        c.close();
        return c;
      }();
      return none;
    }

    /// The lowest eigenpair of the scaled tangent, where it is negative.
    struct Curvature
    {
      bool            negative = false;
      double          value    = 0;
      Eigen::VectorXd mode;
    };

    /// The scaled tangent D^-1 K D^-1 with D the running maximum of
    /// sqrt|K_ii| over the iterations (@p metric, updated here), and 1
    /// from where a diagonal entry is zero on (a row of no stiffness has
    /// no scale of its own).
    void
    scale_tangent(const MatrixType &tangent,
                  Eigen::VectorXd  &metric,
                  MatrixType       &scaled)
    {
      const unsigned int n = tangent.m();
      if (metric.size() != n)
        metric = Eigen::VectorXd::Zero(n);
      VectorType diagonal(tangent.locally_owned_range_indices(),
                          tangent.get_mpi_communicator());
      for (const auto i : diagonal.locally_owned_elements())
        diagonal[i] = tangent.diag_element(i);
      diagonal.compress(dealii::VectorOperation::insert);
      const Eigen::VectorXd every_diagonal = values_of(diagonal);
      for (unsigned int i = 0; i < n; ++i)
        {
          metric[i] =
            std::max(metric[i], std::sqrt(std::abs(every_diagonal[i])));
          if (metric[i] == 0)
            metric[i] = 1;
        }
      scaled.reinit(tangent);
      scaled.copy_from(tangent);
      // Epetra's row views give the stored values in place; each process
      // scales its own rows.
      const Epetra_CrsMatrix &rows = scaled.trilinos_matrix();
      for (int r = 0; r < rows.NumMyRows(); ++r)
        {
          int     length;
          double *values;
          int    *columns;
          rows.ExtractMyRowView(r, length, values, columns);
          for (int e = 0; e < length; ++e)
            values[e] /= metric[rows.GRID(r)] * metric[rows.GCID(columns[e])];
        }
    }

    /// q.A q for the matrix @p a.
    double
    quadratic_form(const MatrixType &a, const Eigen::VectorXd &q)
    {
      VectorType in(a.locally_owned_domain_indices(), a.get_mpi_communicator());
      VectorType out(in);
      for (const auto i : in.locally_owned_elements())
        in[i] = q[i];
      in.compress(dealii::VectorOperation::insert);
      a.vmult(out, in);
      return q.dot(values_of(out));
    }

    /// -(A - sigma I)^-1 g by @p factorization and the solve with its
    /// result, (A - sigma I)^-1 q; false where the solve failed.
    bool
    shifted_steps(const ConstrainedFactorization &factorization,
                  const Eigen::VectorXd          &g,
                  Eigen::VectorXd                &q,
                  Eigen::VectorXd                &w)
    {
      try
        {
          Eigen::MatrixXd block = -g;
          factorization.solve_free(block);
          q     = block.col(0);
          block = q;
          factorization.solve_free(block);
          w = block.col(0);
          return true;
        }
      catch (const std::runtime_error &)
        {
          return false;
        }
    }

    /// In the hard case, q completed along the unit mode v to |q + t v| =
    /// radius, with the root of the lower model: m(q + t v) - m(q) =
    /// t (g.v + lambda q.v) + lambda t^2 / 2.
    Eigen::VectorXd
    completed_along_mode(const Eigen::VectorXd &q,
                         const Eigen::VectorXd &g,
                         const double           radius,
                         const Curvature       &curvature)
    {
      const Eigen::VectorXd &v     = curvature.mode;
      const double           qv    = q.dot(v);
      const double           slope = g.dot(v) + curvature.value * qv;
      const double           root =
        std::sqrt(qv * qv + radius * radius - q.squaredNorm());
      const auto change = [&](const double t) {
        return t * slope + 0.5 * curvature.value * t * t;
      };
      const double t1 = -qv + root, t2 = -qv - root;
      return q + (change(t1) <= change(t2) ? t1 : t2) * v;
    }

    /// The step q of the scaled subproblem min g.q + 1/2 q.A q over
    /// |q| <= radius (Moré & Sorensen 1983): the Newton step if A
    /// (@p unshifted: its factorization) is positive definite and the step
    /// lies inside, else the step -(A + mu I)^-1 g of length radius, mu
    /// found by safeguarded Newton iterations on 1/|q(mu)| - 1/radius
    /// (d|q|^2/dmu = -2 q.(A + mu I)^-1 q); in the hard case completed
    /// along the negative curvature mode to the boundary.
    Eigen::VectorXd
    subproblem_step(const MatrixType               &a,
                    const ConstrainedFactorization &unshifted,
                    const Eigen::VectorXd          &g,
                    const double                    radius,
                    const Curvature                &curvature,
                    const Parameters               &p)
    {
      const dealii::AffineConstraints<double> &none = no_constraints();
      // A + mu I is positive definite for mu > low, and |q(high)| <= radius.
      double          low  = curvature.negative ? -curvature.value : 0.0;
      double          high = low + g.norm() / radius;
      double          mu   = curvature.negative ?
                               low + std::max(1e-6 * (high - low), 1e-8 * low) :
                               0.0;
      Eigen::VectorXd q    = Eigen::VectorXd::Zero(g.size()), w;
      for (unsigned int shift = 0; shift < p.max_shifts; ++shift)
        {
          std::unique_ptr<ConstrainedFactorization> shifted;
          if (mu > 0)
            shifted = std::make_unique<ConstrainedFactorization>(a, none, -mu);
          const ConstrainedFactorization &factorization =
            mu > 0 ? *shifted : unshifted;
          if (!factorization.positive_definite() ||
              !shifted_steps(factorization, g, q, w))
            {
              low  = mu;
              high = std::max(high, low + g.norm() / radius);
              mu   = 0.5 * (low + high);
              continue;
            }
          const double n = q.norm();
          if ((mu == 0 && n <= radius * (1 + p.boundary_accuracy)) ||
              std::abs(n - radius) <= p.boundary_accuracy * radius)
            return q;
          if (n < radius && curvature.negative && shift == 0)
            return completed_along_mode(q, g, radius, curvature);
          (n < radius ? high : low) = mu;
          const double next = mu + n * n / q.dot(w) * (n - radius) / radius;
          mu = next > low && next < high ? next : 0.5 * (low + high);
        }
      const double n = q.norm();
      if (curvature.negative && n < radius)
        return completed_along_mode(q, g, radius, curvature);
      return n > radius ? Eigen::VectorXd(q * (radius / n)) : q;
    }

    /// The iterate: state, energy and residual (the gradient).
    struct Iterate
    {
      VectorType x;
      VectorType residual;
      double     energy = 0;
    };

    /// @p trial's energy and residual; false where the problem cannot
    /// evaluate them (a flipped segment) or they are not finite.
    bool
    evaluate(const NewtonSolver::Problem &problem, Iterate &trial)
    {
      try
        {
          trial.energy = problem.energy(trial.x, &trial.residual);
        }
      catch (...)
        {
          return false;
        }
      return std::isfinite(trial.energy) &&
             std::isfinite(trial.residual.l2_norm());
    }

    /// @p base moved by D^-1 @p q.
    void
    move(const Iterate         &base,
         const Eigen::VectorXd &q,
         const Eigen::VectorXd &metric,
         Iterate               &trial)
    {
      trial.x = base.x;
      for (const auto i : trial.x.locally_owned_elements())
        trial.x[i] += q[i] / metric[i];
      trial.x.compress(dealii::VectorOperation::add);
    }

    /// The scaled length along the negative curvature mode over which the
    /// model's energy falls by 1e-6 of |@p energy| (lambda t^2 / 2), a
    /// first guess of how far the descent along it goes; 1e-6 if the
    /// energy is zero.
    double
    curvature_length(const double energy, const Curvature &curvature)
    {
      return energy != 0 ?
               std::sqrt(2e-6 * std::abs(energy) / -curvature.value) :
               1e-6;
    }

    /**
     * From a saddle @p at, steps along the negative curvature mode
     * downhill: step t from the one whose model decrease is 1e-6 of the
     * energy, doubled while the energy falls. Returns the scaled length of
     * the step taken, 0 if the first one did not lower the energy beyond
     * its resolution (a zero mode that rounding made negative).
     */
    double
    step_off_saddle(const NewtonSolver::Problem &problem,
                    Iterate                     &at,
                    const Curvature             &curvature,
                    const Eigen::VectorXd       &metric,
                    const Parameters            &p)
    {
      Eigen::VectorXd direction = curvature.mode;
      if (values_of(at.residual).dot(direction.cwiseQuotient(metric)) > 0)
        direction = -direction;
      const double rounding = p.energy_resolution * std::abs(at.energy);
      double       t        = curvature_length(at.energy, curvature);
      double       taken    = 0;
      Iterate      best = at, trial = at;
      for (unsigned int doubling = 0; doubling < 30; ++doubling, t *= 2)
        {
          move(at, t * direction, metric, trial);
          if (!evaluate(problem, trial) ||
              trial.energy >= best.energy - rounding)
            break;
          best  = trial;
          taken = t;
        }
      if (taken > 0)
        at = best;
      return taken;
    }

    /// The lowest eigenpair of the scaled tangent @p a where its
    /// factorization @p unshifted has a negative pivot (a pivot below 1e-12
    /// of its row's diagonal counts as zero, as in the stability checks).
    Curvature
    lowest_curvature(const MatrixType               &a,
                     const ConstrainedFactorization &unshifted)
    {
      Curvature curvature;
      if (unshifted.inertia(1e-12).negative == 0)
        return curvature;
      const Eigenpairs pair = lowest_eigenpairs(a, no_constraints(), 1);
      if (pair.values[0] >= 0)
        return curvature;
      curvature.negative = true;
      curvature.value    = pair.values[0];
      curvature.mode =
        Eigen::Map<const Eigen::VectorXd>(pair.vectors[0].data(),
                                          pair.vectors[0].size());
      return curvature;
    }

    /**
     * The ratio rho of the energy's actual decrease to the model's
     * @p predicted one. Where the predicted decrease is below the
     * energy's resolution (@p p.energy_resolution times |energy|: the
     * sum of large elastic and load terms loses that much to rounding,
     * 1e-8 relative on a stiff column near its reference), the energies
     * cannot judge the step and the residual does: rho is 1 if the step
     * lowers |residual|, else 0.
     */
    double
    decrease_ratio(const double      predicted,
                   const Iterate    &current,
                   const Iterate    &trial,
                   const bool        evaluated,
                   const Parameters &p)
    {
      if (!evaluated)
        return -std::numeric_limits<double>::infinity();
      if (std::abs(predicted) <= p.energy_resolution * std::abs(current.energy))
        return trial.residual.l2_norm() < current.residual.l2_norm() ? 1.0 :
                                                                       0.0;
      return (current.energy - trial.energy) / predicted;
    }

    /// The quadratic model of one iteration: the scaled tangent, its
    /// factorization, its negative curvature and the metric D.
    struct QuadraticModel
    {
      const MatrixType               &scaled;
      const ConstrainedFactorization &unshifted;
      const Curvature                &curvature;
      const Eigen::VectorXd          &metric;
    };

    /**
     * One iteration from @p current with the tangent's @p model: trial
     * steps of the subproblem, the radius quartered after each rejected
     * one (rho < 1/4) and doubled after an accepted one at the boundary
     * with rho > 3/4, in which case the doubled step is tried at once
     * (internal doubling, Dennis & Schnabel, Numerical Methods for
     * Unconstrained Optimization, 1983, alg. A6.4.5) and kept while the
     * model holds and the energy is lower. False if no step within
     * max_trials lowered the energy.
     */
    bool
    trust_region_iteration(const NewtonSolver::Problem &problem,
                           const QuadraticModel        &model,
                           Iterate                     &current,
                           double                      &radius,
                           const Parameters            &parameters)
    {
      const Eigen::VectorXd g =
        values_of(current.residual).cwiseQuotient(model.metric);
      Iterate trial = current, best = current;
      bool    improved = false;
      for (unsigned int t = 0; t < parameters.max_trials; ++t)
        {
          const Eigen::VectorXd q = subproblem_step(model.scaled,
                                                    model.unshifted,
                                                    g,
                                                    radius,
                                                    model.curvature,
                                                    parameters);
          const double          predicted =
            -(g.dot(q) + 0.5 * quadratic_form(model.scaled, q));
          move(current, q, model.metric, trial);
          const bool   evaluated = evaluate(problem, trial);
          const double rho =
            decrease_ratio(predicted, current, trial, evaluated, parameters);
          const double length = q.norm();
          const bool   boundary =
            length >= (1 - parameters.boundary_accuracy) * radius;
          if (improved)
            {
              if (rho > 0.75 && trial.energy < best.energy)
                {
                  best = trial;
                  if (boundary)
                    {
                      radius *= 2;
                      continue;
                    }
                }
              else
                radius /= 2;
              break;
            }
          if (rho < 0.25)
            radius = 0.25 * length;
          if (rho > parameters.acceptance)
            {
              best     = trial;
              improved = true;
              if (rho > 0.75 && boundary && std::isfinite(radius))
                {
                  radius *= 2;
                  continue;
                }
              break;
            }
        }
      if (improved)
        current = best;
      return improved;
    }

    /// The result where the energy cannot be evaluated at the start.
    NewtonSolver::Result
    unevaluable_start()
    {
      NewtonSolver::Result result;
      result.failure       = "the energy cannot be evaluated at the start";
      result.residual_norm = NAN;
      return result;
    }

    /// Whether @p it is in equilibrium: the problem's own test where it
    /// has one, else the residual norm against the tolerance.
    bool
    balanced(const NewtonSolver::Problem &problem,
             const Iterate               &it,
             const Parameters            &p)
    {
      return problem.converged ? problem.converged(it.x, it.residual) :
                                 it.residual.l2_norm() <= p.tolerance;
    }

    /**
     * The first radius where the tangent is not positive definite, so that
     * the Newton step is no measure of the distance to go: the scaled
     * length |D^-1 r| of the residual, or if longer the length along the
     * negative curvature mode over which the energy falls by 1e-6 of it.
     */
    double
    first_radius(const Iterate         &current,
                 const Curvature       &curvature,
                 const Eigen::VectorXd &metric)
    {
      return std::max(values_of(current.residual).cwiseQuotient(metric).norm(),
                      curvature.negative ?
                        curvature_length(current.energy, curvature) :
                        0.0);
    }

    /// Completes @p result with the residual norm of the last iterate
    /// @p current: named in a failure, and the failure named where the
    /// iterations ran out without another.
    void
    finish_result(const Iterate &current, NewtonSolver::Result &result)
    {
      result.residual_norm = current.residual.l2_norm();
      if (!result.failure.empty())
        result.failure +=
          " (residual " + std::to_string(result.residual_norm) + ")";
      if (!result.converged && result.failure.empty())
        result.failure = "the trust region did not converge in " +
                         std::to_string(result.iterations) +
                         " iterations (residual " +
                         std::to_string(result.residual_norm) + ")";
    }
  } // namespace

  TrustRegionNewton::TrustRegionNewton(const Parameters &parameters)
      : parameters(parameters)
  {
  }

  NewtonSolver::Result
  TrustRegionNewton::solve(const NewtonSolver::Problem &problem,
                           VectorType                  &x,
                           MatrixType                  &tangent) const
  {
    NewtonSolver::Result result;
    Iterate              current{x, x, 0};
    if (!evaluate(problem, current))
      return unevaluable_start();
    MatrixType      scaled;
    Eigen::VectorXd metric;
    double          radius = std::numeric_limits<double>::infinity();
    while (true)
      {
        const bool at_rest = balanced(problem, current, parameters);
        problem.tangent(current.x, tangent);
        scale_tangent(tangent, metric, scaled);
        const ConstrainedFactorization unshifted(scaled, no_constraints());
        const Curvature curvature = lowest_curvature(scaled, unshifted);
        if (at_rest && !curvature.negative)
          {
            result.converged = true;
            break;
          }
        if (result.iterations >= parameters.max_iterations)
          break;
        ++result.iterations;
        if (at_rest)
          {
            // A saddle: off it along the mode, or a zero mode after all.
            radius =
              step_off_saddle(problem, current, curvature, metric, parameters);
            result.converged = radius == 0;
            if (result.converged)
              break;
            continue;
          }
        if (!std::isfinite(radius) && !unshifted.positive_definite())
          radius = first_radius(current, curvature, metric);
        const QuadraticModel model{scaled, unshifted, curvature, metric};
        if (!trust_region_iteration(problem,
                                    model,
                                    current,
                                    radius,
                                    parameters))
          {
            result.failure = "the trust region found no lower energy in " +
                             std::to_string(parameters.max_trials) +
                             " trial steps";
            break;
          }
      }
    x = current.x;
    finish_result(current, result);
    return result;
  }

  NewtonSolver::Result
  TrustRegionGlobalization::solve(const NewtonSolve &call) const
  {
    // The trust region factorizes shifted scaled tangents of its own: no
    // use for call.factorizations.
    TrustRegionNewton::Parameters trust;
    trust.tolerance      = call.parameters.tolerance;
    trust.max_iterations = call.parameters.max_iterations;
    return TrustRegionNewton(trust).solve(call.problem, call.x, call.tangent);
  }
} // namespace rodnet
