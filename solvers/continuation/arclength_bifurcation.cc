#include <solvers/continuation/arclength_continuation.h>
#include <solvers/stability/stability.h>
#include <solvers/statics/static_solver.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace rodnet
{
  ArclengthContinuation::PathPoint
  ArclengthContinuation::locate_bifurcation(const PathPoint &lo,
                                            const PathPoint &hi,
                                            const double     ds_hi,
                                            StepInfo        &info)
  {
    double       s_lo = 0, s_hi = ds_hi;
    double       lambda_lo = lo.lambda, lambda_hi = hi.lambda;
    VectorType   u_lo = lo.u, u_hi = hi.u;
    JudgedResult result_lo;
    const double tolerance =
      parameters.bifurcation_tolerance * std::max(1.0, std::abs(lo.lambda));
    model.set_state(*lo.state);
    // Down to the load factor's tolerance, and to 1e-6 of the step in
    // arclength, for the continuity check below (near a limit point the
    // load factor changes little along the path).
    while ((std::abs(lambda_hi - lambda_lo) > tolerance ||
            s_hi - s_lo > 1e-6 * ds_hi) &&
           s_hi - s_lo > 1e-14 * ds_hi)
      {
        const double       s_mid = 0.5 * (s_lo + s_hi);
        VectorType         u;
        double             lambda;
        const JudgedResult result =
          point_along(lo, s_lo, u_lo, lambda_lo, s_mid, u, lambda);
        if (!result.converged)
          throw SolverFailure("locating the bifurcation near load factor " +
                              number(lambda) + " failed: " + result.failure);
        if (negative_eigenvalues(model, u, lambda, tangent, &factorizations) ==
            lo.negative)
          {
            s_lo      = s_mid;
            lambda_lo = lambda;
            u_lo      = u;
            result_lo = result;
          }
        else
          {
            s_hi      = s_mid;
            lambda_hi = lambda;
            u_hi      = u;
          }
      }
    require_continuous_bracket(lo, hi, u_lo, lambda_lo, u_hi, lambda_hi);
    located_bifurcations.push_back(0.5 * (lambda_lo + lambda_hi));
    if (s_lo == 0)
      {
        model.set_state(*lo.state);
        info.load_factor = lo.lambda;
        return lo;
      }
    PathPoint b = accept(u_lo, lambda_lo, &lo, result_lo, info);
    return b;
  }

  JudgedResult
  ArclengthContinuation::point_along(const PathPoint  &base,
                                     const double      s_from,
                                     const VectorType &u_from,
                                     const double      lambda_from,
                                     const double      s,
                                     VectorType       &u,
                                     double           &lambda)
  {
    u      = u_from;
    lambda = lambda_from + (s - s_from) * base.t_lambda;
    u.add(s - s_from, base.t_u);
    return correct(base, Constraint{&base.t_u, base.t_lambda, s}, u, lambda);
  }

  void
  ArclengthContinuation::require_continuous_bracket(const PathPoint  &lo,
                                                    const PathPoint  &hi,
                                                    const VectorType &u_lo,
                                                    const double      lambda_lo,
                                                    const VectorType &u_hi,
                                                    const double      lambda_hi)
  {
    // On one path the states on either side of a bifurcation meet as the
    // bracket closes; states that stay apart belong to two branches, the
    // corrector having jumped from one to the other within the bracket
    // (a sharp turn of the path next to another branch).
    VectorType difference = u_hi;
    difference -= u_lo;
    const double gap =
      std::sqrt(dot_w(difference, difference) +
                (lambda_hi - lambda_lo) * (lambda_hi - lambda_lo));
    // The step's chord, measured when hi was accepted (before the reset of
    // its reference).
    const double chord = hi.s - lo.s;
    if (gap > 1e-3 * chord)
      throw SolverFailure(
        "the states on either side of the change of negative eigenvalues near "
        "load factor " +
        number(lambda_lo) + " stay " + number(gap / chord) +
        " of the step apart as the bracket closes: two branches, no "
        "bifurcation between them");
  }

  void
  ArclengthContinuation::turn_to_null_vector(PathPoint &p)
  {
    model.assemble(p.u, p.lambda, nullptr, &tangent);
    const ConstrainedFactorization factorization(tangent,
                                                 model.constraints(),
                                                 0.0,
                                                 model.multiplier_dofs());
    // Inverse iteration from a fixed pseudo-random start: near a
    // bifurcation the tangent's smallest eigenvalue is far below the next.
    std::mt19937                           random(1);
    std::uniform_real_distribution<double> uniform(-1, 1);
    std::vector<double>                    x(tangent.m());
    for (double &v : x)
      v = uniform(random);
    for (unsigned int k = 0; k < 6; ++k)
      {
        x = factorization.solve(x);
        const double norm =
          std::sqrt(std::inner_product(x.begin(), x.end(), x.begin(), 0.0));
        for (double &v : x)
          v /= norm;
      }
    // A fixed sign: the first of the largest entries positive. Symmetric
    // structures have several entries of one size (the over-curved ring's
    // mirror points); which of them is largest by rounding differs between
    // partitions, and so would the branch taken.
    double largest = 0;
    for (const double v : x)
      largest = std::max(largest, std::abs(v));
    const auto first_largest =
      std::find_if(x.begin(), x.end(), [&](const double v) {
        return std::abs(v) >= (1 - 1e-6) * largest;
      });
    const double sign = *first_largest < 0 ? -1 : 1;
    VectorType   phi  = model.create_vector();
    for (const global_dof_index i : phi.locally_owned_elements())
      phi[i] = sign * x[i];
    phi.compress(dealii::VectorOperation::insert);
    // W-orthogonal to the path it leaves, unit.
    const double along = dot_w(phi, p.t_u);
    phi.add(-along, p.t_u);
    const double phi_lambda = -along * p.t_lambda;
    const double norm = std::sqrt(dot_w(phi, phi) + phi_lambda * phi_lambda);
    p.t_u             = phi;
    p.t_u /= norm;
    p.t_lambda = phi_lambda / norm;
  }
} // namespace rodnet
