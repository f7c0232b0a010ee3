#ifndef RODNET_SOLVERS_SOLVER_FAILURE_H
#define RODNET_SOLVERS_SOLVER_FAILURE_H

#include <stdexcept>

namespace rodnet
{
  /**
   * Thrown when a solver cannot go on: a load step that fails even at the
   * smallest allowed step, an eigen-solve that does not converge. Earlier
   * converged steps have already been reported; rodnet-run ends such a run
   * with exit code 2 and keeps its outputs.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace rodnet

#endif
