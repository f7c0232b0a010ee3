#include <deal.II/base/patterns.h>

#include <solvers/newton/newton_solver.h>

namespace rodnet
{
  void
  NewtonSolver::Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Line search",
                      "full step",
                      dealii::Patterns::Selection(
                        "energy|backtrack|polynomial|full step|trust region"),
                      "Newton's globalization (doc/nonlinear_solvers.md). "
                      "[-]");
    prm.declare_entry("Linear solver",
                      "auto",
                      dealii::Patterns::Selection("auto|klu|band"),
                      "Newton's direct solver: SuiteSparse KLU, LAPACK band "
                      "LU (one process); auto: band if 32 wide at most. [-]");
    prm.declare_entry(
      "Max iterations",
      "25",
      dealii::Patterns::Integer(1),
      "Newton iterations per step before the step is cut. [-]");
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
