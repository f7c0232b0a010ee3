#ifndef RODNET_TESTS_SOLVE_MODEL_H
#define RODNET_TESTS_SOLVE_MODEL_H

#include <core/rod_model.h>
#include <solvers/statics/static_solver.h>

namespace rodnet::testing
{
  /// Finalizes @p model and solves it in @p steps equal load steps from
  /// the undeformed state; returns the final state, and the negative
  /// eigenvalues of its tangent in @p negative_eigenvalues if given.
  inline VectorType
  solve(RodModel          &model,
        const unsigned int steps,
        unsigned int      *negative_eigenvalues = nullptr)
  {
    model.finalize();
    VectorType               u = model.create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps = steps;
    StaticSolver(model, parameters)
      .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
        if (negative_eigenvalues != nullptr)
          *negative_eigenvalues = info.check.negative_eigenvalues;
      });
    return u;
  }
} // namespace rodnet::testing

#endif
