#include <deal.II/base/patterns.h>

#include <solvers/relaxation/dynamic_relaxation.h>

namespace rodnet
{
  void
  DynamicRelaxation::Parameters::declare_parameters(
    dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.declare_entry("Time step",
                      "1",
                      Double(0),
                      "Pseudo-time step; the fictitious masses are "
                      "scaled for it (stable up to sqrt(2 Mass "
                      "scaling)), and an unstable run halves it. [-]");
    prm.declare_entry("Mass scaling",
                      "1",
                      Double(1),
                      "Factor on the fictitious masses of the stability "
                      "bound (>= 1). [-]");
    prm.declare_entry("Residual tolerance",
                      "1e-6",
                      Double(0, 1),
                      "Converged when the out-of-balance force norm is "
                      "below this times the applied load norm (or the "
                      "step's initial residual). [-]");
    prm.declare_entry("Max iterations",
                      "1000000",
                      Integer(1),
                      "Pseudo-time iterations per load step. [-]");
    prm.declare_entry("Progress interval",
                      "0",
                      Integer(0),
                      "Print iteration, kinetic energy and residual every "
                      "this many iterations (0: once per load step). [-]");
  }

  void
  DynamicRelaxation::Parameters::parse_parameters(
    const dealii::ParameterHandler &prm)
  {
    time_step          = prm.get_double("Time step");
    mass_scaling       = prm.get_double("Mass scaling");
    residual_tolerance = prm.get_double("Residual tolerance");
    max_iterations     = prm.get_integer("Max iterations");
    progress_interval  = prm.get_integer("Progress interval");
  }
} // namespace rodnet
