#include <deal.II/base/patterns.h>

#include <solvers/newton/newton_globalization.h>
#include <solvers/newton/newton_solver.h>

namespace rodnet
{
  void
  NewtonSolver::Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    const LineSearchRegistry &searches = line_search_registry();
    prm.declare_entry("Line search",
                      "full step",
                      dealii::Patterns::Selection(searches.selection()),
                      "Newton's globalization (doc/nonlinear_solvers.md). " +
                        searches.listing() + "[-]");
    prm.declare_entry("Linear solver",
                      "auto",
                      dealii::Patterns::Selection(TangentFactorization::kinds),
                      "Newton's direct solver: SuiteSparse KLU, LAPACK band "
                      "LU (one process), MUMPS's LDL^T; auto: band if 32 "
                      "wide at most, else KLU below 30000 DoFs and MUMPS "
                      "from there (and on several processes). [-]");
    prm.declare_entry("Max iterations",
                      "25",
                      dealii::Patterns::Integer(1),
                      "Newton iterations per step before the step is cut. [-]");
  }

  bool
  NewtonSolver::Parameters::needs_potential() const
  {
    return line_search_registry().traits(line_search).needs_potential;
  }

  void
  NewtonSolver::Parameters::parse_parameters(
    const dealii::ParameterHandler &prm)
  {
    line_search    = prm.get("Line search");
    linear_solver  = prm.get("Linear solver");
    max_iterations = prm.get_integer("Max iterations");
  }
} // namespace rodnet
