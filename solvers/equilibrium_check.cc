#include <solvers/equilibrium_check.h>
#include <solvers/stability.h>
#include <solvers/static_solver.h>

#include <limits>
#include <sstream>

namespace rodnet
{
  EquilibriumCheck
  check_equilibrium(const RodModel          &model,
                    const ResidualCriterion &criterion,
                    const VectorType        &u,
                    const double             load_factor,
                    MatrixType              &tangent,
                    const JudgedResult      &result,
                    const double             uncertainty_limit)
  {
    VectorType r = model.create_vector();
    model.assemble(u, load_factor, &r, &tangent, true);
    const ConstrainedFactorization factorization(tangent, model.constraints());
    EquilibriumCheck               check;
    check.negative_eigenvalues = factorization.inertia().negative;
    check.stable               = check.negative_eigenvalues == 0;
    if (!result.rounding_limited)
      return check;
    // Where the residual sits on its round-off floor it cannot show
    // equilibrium alone; the Newton step it calls for can.
    const double *values = r.trilinos_vector()[0];
    try
      {
        check.rounding_uncertainty = criterion.state_change(
          factorization.solve(std::vector<double>(values, values + r.size())));
      }
    catch (const std::exception &)
      {
        check.rounding_uncertainty = std::numeric_limits<double>::infinity();
      }
    if (!(check.rounding_uncertainty <= uncertainty_limit))
      check.rounding_warning =
        criterion.rounding_hint(tangent, result.noise, result.scale);
    return check;
  }

  void
  refuse_undetermined_state(const EquilibriumCheck &check,
                            const double            failure_limit,
                            const std::string      &where)
  {
    if (check.rounding_uncertainty <= failure_limit)
      return;
    std::ostringstream message;
    message << "the state at " << where
            << " is not determined: its residual is at the round-off floor, "
               "and the Newton correction of that residual is "
            << check.rounding_uncertainty << " of the model size (at most "
            << failure_limit << " for a converged step): "
            << check.rounding_warning;
    throw SolverFailure(message.str());
  }
} // namespace rodnet
