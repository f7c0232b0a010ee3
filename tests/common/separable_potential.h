#ifndef RODNET_TESTS_COMMON_SEPARABLE_POTENTIAL_H
#define RODNET_TESTS_COMMON_SEPARABLE_POTENTIAL_H

#include <common/diagonal_tangent.h>
#include <solvers/newton/newton_solver.h>

#include <functional>
#include <string>
#include <vector>

namespace rodnet::testing
{
  using VectorType = NewtonSolver::VectorType;
  using MatrixType = NewtonSolver::MatrixType;

  /// A separable potential sum_i p(x_i - c_i) with derivatives p', p''.
  struct SeparablePotential
  {
    std::function<double(double)> p, dp, ddp;
    std::vector<double>           centre;

    NewtonSolver::Problem
    problem() const
    {
      NewtonSolver::Problem problem;
      problem.set_potential([this](const VectorType &x, VectorType *r) {
        double energy = 0;
        for (unsigned int i = 0; i < centre.size(); ++i)
          {
            energy += p(x[i] - centre[i]);
            if (r != nullptr)
              (*r)[i] = dp(x[i] - centre[i]);
          }
        if (r != nullptr)
          r->compress(dealii::VectorOperation::insert);
        return energy;
      });
      problem.tangent = [this](const VectorType &x, MatrixType &k) {
        k = 0;
        for (unsigned int i = 0; i < centre.size(); ++i)
          k.set(i, i, ddp(x[i] - centre[i]));
        k.compress(dealii::VectorOperation::insert);
      };
      return problem;
    }
  };

  /// The double well w(z) = z^4/4 - z^2/2 in @p n variables: minima
  /// w(+-1) = -1/4, a maximum at z = 0 where w'' = -1.
  inline SeparablePotential
  double_well(const unsigned int n)
  {
    return {[](double z) { return z * z * z * z / 4 - z * z / 2; },
            [](double z) { return z * z * z - z; },
            [](double z) { return 3 * z * z - 1; },
            std::vector<double>(n, 0.0)};
  }

  /// Newton from @p start with @p line_search; x holds the last iterate.
  inline NewtonSolver::Result
  solve(const SeparablePotential  &potential,
        const std::vector<double> &start,
        const std::string         &line_search,
        std::vector<double>       &x)
  {
    const unsigned int n = start.size();
    MatrixType         tangent;
    rodnet::testing::diagonal_tangent(n, tangent);
    VectorType u(tangent.locally_owned_domain_indices(), MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = start[i];
    u.compress(dealii::VectorOperation::insert);

    NewtonSolver::Parameters parameters;
    parameters.line_search              = line_search;
    parameters.tolerance                = 1e-12;
    parameters.max_iterations           = 50;
    const NewtonSolver::Problem problem = potential.problem();
    const NewtonSolver::Result  result =
      NewtonSolver(parameters).solve(problem, u, tangent);
    x.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      x[i] = u[i];
    return result;
  }
} // namespace rodnet::testing

#endif
