#include <deal.II/base/patterns.h>

#include <solvers/newton_solver.h>

namespace rodnet
{
  void
  NewtonSolver::Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Line search",
                      "full step",
                      dealii::Patterns::Selection(
                        "backtrack|polynomial|full step"),
                      "Globalization of Newton's method (Trilinos NOX). The "
                      "line searches reduce the residual norm, which for "
                      "nearly inextensible rods (large EA) rejects good "
                      "Newton steps; the default takes full steps and "
                      "relies on load-step cutting instead. [-]");
    prm.declare_entry(
      "Max iterations",
      "25",
      dealii::Patterns::Integer(1),
      "Newton iterations per load or time step before it is cut. [-]");
  }

  void
  NewtonSolver::Parameters::parse_parameters(
    const dealii::ParameterHandler &prm)
  {
    line_search    = prm.get("Line search");
    max_iterations = prm.get_integer("Max iterations");
  }
} // namespace rodnet
