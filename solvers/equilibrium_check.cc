#include <solvers/equilibrium_check.h>
#include <solvers/stability.h>

#include <limits>

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
} // namespace rodnet
