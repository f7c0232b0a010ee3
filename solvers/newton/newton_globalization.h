#ifndef RODNET_SOLVERS_NEWTON_NEWTON_GLOBALIZATION_H
#define RODNET_SOLVERS_NEWTON_NEWTON_GLOBALIZATION_H

#include <base/registry.h>
#include <solvers/newton/newton_solver.h>

#include <string>

namespace rodnet
{
  /// What a solver must know of a line search before it solves with it.
  struct LineSearchTraits
  {
    /// Whether it judges steps by the problem's potential
    /// (NewtonSolver::Problem::energy).
    bool needs_potential = false;
    /// How messages name it ("the energy line search").
    std::string phrase;
  };

  /// The arguments of one NewtonSolver::solve() and the solver's
  /// parameters.
  struct NewtonSolve
  {
    const NewtonSolver::Problem    &problem;
    NewtonSolver::VectorType       &x;
    NewtonSolver::MatrixType       &tangent;
    TangentFactorizationCache      *factorizations;
    const NewtonSolver::Parameters &parameters;
  };

  /**
   * A globalization of Newton's method, selected by name
   * (NewtonSolver::Parameters::line_search, the scene entry "Line search"):
   * a line search run by NOX, or the trust region. A new one is a class
   * deriving from this one in a file pair of its own, registered by name in
   * newton_globalization.cc.
   */
  class NewtonGlobalization
  {
  public:
    virtual ~NewtonGlobalization() = default;

    /// NewtonSolver::solve(); the caller has checked that the problem has
    /// the potential the traits ask for.
    virtual NewtonSolver::Result
    solve(const NewtonSolve &call) const = 0;
  };

  /// Newton's globalizations by name, with their traits.
  using LineSearchRegistry =
    TraitRegistry<LineSearchTraits, NewtonGlobalization>;

  /**
   * The line searches, in the order of registration, which is the order of
   * the selection "Line search" and its help in --help: "energy",
   * "backtrack", "polynomial", "full step", "trust region".
   */
  const LineSearchRegistry &
  line_search_registry();
} // namespace rodnet

#endif
