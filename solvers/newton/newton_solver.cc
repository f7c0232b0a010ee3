#include <solvers/newton/newton_globalization.h>
#include <solvers/newton/newton_solver.h>

#include <cmath>
#include <stdexcept>

namespace rodnet
{
  NewtonSolver::NewtonSolver(const Parameters &parameters)
      : parameters(parameters)
      , globalization(line_search_registry().create(parameters.line_search))
  {
    TangentFactorization::check_kind(parameters.linear_solver);
  }

  NewtonSolver::~NewtonSolver() = default;

  NewtonSolver::Result
  NewtonSolver::solve(const Problem             &problem,
                      VectorType                &x,
                      MatrixType                &tangent,
                      TangentFactorizationCache *factorizations) const
  {
    const LineSearchTraits &traits =
      line_search_registry().traits(parameters.line_search);
    if (traits.needs_potential && (!problem.energy || problem.rank_one))
      {
        Result result;
        result.failure = traits.phrase + " needs the potential of the problem, "
                                         "which this solve does not have";
        result.residual_norm = NAN;
        return result;
      }
    return globalization->solve(
      {problem, x, tangent, factorizations, parameters});
  }
} // namespace rodnet
