#ifndef RODNET_SOLVERS_NEWTON_NOX_LINE_SEARCH_H
#define RODNET_SOLVERS_NEWTON_NOX_LINE_SEARCH_H

#include <solvers/newton/newton_globalization.h>

#include <NOX_LineSearch_UserDefinedFactory.H>
#include <Teuchos_RCP.hpp>
#include <string>

namespace rodnet
{
  /**
   * Newton's method with a line search, run by Trilinos NOX ("Line Search
   * Based" solver) on deal.II's Trilinos vectors and matrix through our own
   * NOX group (NoxGroup), with linear solves by SuiteSparse KLU or LAPACK's
   * band LU (TangentFactorization). deal.II 9.4 has no NOX wrapper; this is
   * the thin interface between the two.
   */
  class NoxLineSearch : public NewtonGlobalization
  {
  public:
    /// NOX's line search @p method ("Full Step", "Backtrack"); with
    /// @p user_defined, the method "User Defined" that factory makes.
    explicit NoxLineSearch(std::string method,
                           Teuchos::RCP<NOX::LineSearch::UserDefinedFactory>
                             user_defined = Teuchos::null);

    NewtonSolver::Result
    solve(const NewtonSolve &call) const override;

  private:
    std::string                                       method;
    Teuchos::RCP<NOX::LineSearch::UserDefinedFactory> user_defined;
  };
} // namespace rodnet

#endif
