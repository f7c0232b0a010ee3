#ifndef RODNET_IO_SOLUTION_METHODS_H
#define RODNET_IO_SOLUTION_METHODS_H

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace rodnet
{
  /// How a scene is solved.
  enum class SolutionMethod
  {
    newton,             ///< discrete rods and junctions, StaticSolver
    dynamic_relaxation, ///< bending-active element, DynamicRelaxation
    time_stepping,      ///< discrete rods and junctions, TimeIntegrator
    continuation, ///< discrete rods and junctions, ArclengthContinuation
  };

  /**
   * A solution method as a scene names it ("Solver/Method = <name>"): its
   * description (a sentence of the help of "Method") and the declaration
   * of its entries in subsection Solver.
   */
  struct SolutionMethodEntry
  {
    std::string    name;
    SolutionMethod method;
    std::string    description;
    /// Declares the method's entries in subsection Solver (current).
    void (*declare_parameters)(dealii::ParameterHandler &prm);
  };

  /// Every solution method, in the order of the "Method" selection
  /// (registered in solution_methods.cc, one line each).
  const std::vector<SolutionMethodEntry> &
  solution_methods();

  /// The method called @p name; throws std::invalid_argument listing the
  /// known names otherwise.
  const SolutionMethodEntry &
  solution_method(const std::string &name);
} // namespace rodnet

#endif
