#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <solvers/continuation/arclength_continuation.h>

#include <stdexcept>

namespace rodnet
{
  void
  ArclengthContinuation::Parameters::declare_parameters(
    dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Initial step",
                      "0.05",
                      Double(0),
                      "First step's arclength: positions over the model "
                      "size, angles in rad and the load factor. [-]");
    prm.declare_entry("Maximum step", "0.5", Double(0), "Longest step. [-]");
    prm.declare_entry("Minimum step",
                      "1e-6",
                      Double(0),
                      "The run stops with an error where a step fails "
                      "below this. [-]");
    prm.declare_entry("Load factor range",
                      "-1, 1",
                      List(Double(), 2, 2),
                      "The path ends where the load factor leaves this "
                      "range, landing on its end. [-]");
    prm.declare_entry("Output load factors",
                      "",
                      List(Double(), 0, 1000),
                      "Load factors the path lands on exactly. [-]");
    prm.declare_entry("Max points",
                      "500",
                      Integer(1),
                      "The run stops with an error after this many. [-]");
    prm.declare_entry("Switch branches",
                      "true",
                      dealii::Patterns::Selection("true|false|both"),
                      "At a located bifurcation, follow the branch along "
                      "the null vector; both: then its other side too. [-]");
    prm.declare_entry("Limit points",
                      "follow",
                      dealii::Patterns::Selection("follow|snap"),
                      "At a maximum of the load factor: follow the path "
                      "back, or snap to a stable state past it (column "
                      "jump). [-]");
    prm.declare_entry("Bifurcation tolerance",
                      "1e-8",
                      Double(0, 1),
                      "Bracket of the bisection, in load factor. [-]");
  }

  void
  ArclengthContinuation::Parameters::parse_parameters(
    const dealii::ParameterHandler &prm)
  {
    initial_step                    = prm.get_double("Initial step");
    max_step                        = prm.get_double("Maximum step");
    min_step                        = prm.get_double("Minimum step");
    const std::vector<double> range = dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(prm.get("Load factor range")));
    lower_limit = range[0];
    upper_limit = range[1];
    if (!(lower_limit < 0 && upper_limit > 0))
      throw std::invalid_argument(
        "entry \"Solver/Continuation/Load factor range\": the path starts "
        "at load factor 0, which must lie inside the range (" +
        prm.get("Load factor range") + ")");
    if (!(min_step <= initial_step && initial_step <= max_step))
      throw std::invalid_argument(
        "entries \"Solver/Continuation/Minimum step\", \"Initial step\", "
        "\"Maximum step\": they must increase (" +
        prm.get("Minimum step") + ", " + prm.get("Initial step") + ", " +
        prm.get("Maximum step") + ")");
    output_points = dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(prm.get("Output load factors")));
    for (const double point : output_points)
      if (!(point >= lower_limit && point <= upper_limit))
        throw std::invalid_argument(
          "entry \"Solver/Continuation/Output load factors\": " +
          prm.get("Output load factors") + ": the path never reaches " +
          std::to_string(point) + ", outside the load factor range (" +
          prm.get("Load factor range") + ")");
    max_steps             = prm.get_integer("Max points");
    switch_branches       = prm.get("Switch branches") != "false";
    follow_both_branches  = prm.get("Switch branches") == "both";
    bifurcation_tolerance = prm.get_double("Bifurcation tolerance");
    snap_at_limit_points  = prm.get("Limit points") == "snap";
  }
} // namespace rodnet
