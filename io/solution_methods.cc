#include <io/solution_methods.h>
#include <solvers/arclength_continuation.h>
#include <solvers/dynamic_relaxation.h>
#include <solvers/static_solver.h>
#include <solvers/time_integrator.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// Subsection "Dynamic relaxation" with the parameters of
    /// DynamicRelaxation.
    void
    declare_dynamic_relaxation(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Dynamic relaxation");
      DynamicRelaxation::Parameters::declare_parameters(prm);
      prm.leave_subsection();
    }

    /// Subsection "Time stepping" with the parameters of TimeIntegrator
    /// (the scene adds the entries of the initial state).
    void
    declare_time_stepping(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Time stepping");
      TimeIntegrator::Parameters::declare_parameters(prm);
      prm.leave_subsection();
    }

    /// Subsection "Continuation" with the parameters of
    /// ArclengthContinuation.
    void
    declare_continuation(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Continuation");
      ArclengthContinuation::Parameters::declare_parameters(prm);
      prm.leave_subsection();
    }
  } // namespace

  const std::vector<SolutionMethodEntry> &
  solution_methods()
  {
    static const std::vector<SolutionMethodEntry> methods = {
      {"newton",
       SolutionMethod::newton,
       "discrete elastic rods and junction elements, Newton per load step "
       "(Trilinos NOX).",
       StaticSolver::Parameters::declare_parameters},
      {"dynamic relaxation",
       SolutionMethod::dynamic_relaxation,
       "the bending-active beam element (position, normal and rotation per "
       "node) relaxed by explicit pseudo-dynamics with kinetic damping; see "
       "doc/dynamic_relaxation.md for which to pick.",
       declare_dynamic_relaxation},
      {"time stepping",
       SolutionMethod::time_stepping,
       "the discrete rods in time, with inertia or quasi-statically, for "
       "vibrations and viscoelastic materials (subsection Time stepping; "
       "the Newton entries of Solver apply to every time step).",
       declare_time_stepping},
      {"continuation",
       SolutionMethod::continuation,
       "the discrete rods along their equilibrium path in the load factor, "
       "through limit points and bifurcations (subsection Continuation).",
       declare_continuation}};
    return methods;
  }

  const SolutionMethodEntry &
  solution_method(const std::string &name)
  {
    std::string known;
    for (const SolutionMethodEntry &m : solution_methods())
      {
        if (m.name == name)
          return m;
        known += (known.empty() ? "" : ", ") + m.name;
      }
    throw std::invalid_argument("unknown solution method \"" + name +
                                "\"; known methods: " + known);
  }
} // namespace rodnet
