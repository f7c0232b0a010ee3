#include <deal.II/base/patterns.h>

#include <solvers/statics/static_solver.h>

namespace rodnet
{
  void
  StaticSolver::Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    NewtonSolver::Parameters::declare_parameters(prm);
    prm.declare_entry("Relative tolerance",
                      "1e-9",
                      Double(0, 1),
                      "Converged when the residual force norm is below this "
                      "times the applied load norm (or the step's initial "
                      "residual). [-]");
    prm.declare_entry("Predictor",
                      "true",
                      Bool(),
                      "Start each load step from a prediction: the last "
                      "converged increment scaled to the step, or on the "
                      "first step the linear response to the prescribed "
                      "displacements. Keeps displacement-driven steps "
                      "converging on fine meshes. [-]");
    prm.declare_entry("Minimum step fraction",
                      "0.0009765625",
                      Double(0, 1),
                      "Failed load and time steps are halved; the run stops "
                      "with an error below this fraction of the nominal "
                      "step. [-]");
    prm.declare_entry("Max step time",
                      "0",
                      Double(0),
                      "Stop the run where a load step, over its attempts "
                      "and cuts, takes longer than this (checked after each "
                      "failed attempt); the outputs of the steps done stay. "
                      "Load stepping only, not time steps or continuation. "
                      "0: no bound. [s]");
    prm.declare_entry("Critical load search",
                      "false",
                      Bool(),
                      "Track the lowest eigenvalue of the tangent and locate "
                      "by bisection the load factor where it crosses "
                      "zero. [-]");
    prm.declare_entry("Critical load tolerance",
                      "1e-6",
                      Double(0, 1),
                      "Bracket width of the bisection, in load factor. [-]");
    prm.declare_entry(
      "Branch switching amplitude",
      "0.1",
      Double(0, 1),
      "Where an equilibrium is unstable (negative lowest eigenvalue) or a "
      "step fails past one, move the state along the lowest mode, both "
      "ways, by this fraction of the model size, and go on from the stable "
      "equilibrium of lower energy found nearby; 0: off. [-]");
  }

  void
  StaticSolver::Parameters::parse_parameters(
    const dealii::ParameterHandler &prm)
  {
    newton.parse_parameters(prm);
    relative_tolerance      = prm.get_double("Relative tolerance");
    min_step_fraction       = prm.get_double("Minimum step fraction");
    max_step_time           = prm.get_double("Max step time");
    predict                 = prm.get_bool("Predictor");
    find_critical_load      = prm.get_bool("Critical load search");
    critical_load_tolerance = prm.get_double("Critical load tolerance");
    branch_switch_amplitude = prm.get_double("Branch switching amplitude");
  }
} // namespace rodnet
