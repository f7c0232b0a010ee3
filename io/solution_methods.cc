#include <io/solution_methods.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/relaxation/dynamic_relaxation.h>
#include <solvers/statics/static_solver.h>
#include <solvers/time/time_integrator.h>

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
       "load steps solved by Newton (NOX).",
       StaticSolver::Parameters::declare_parameters},
      {"dynamic relaxation",
       SolutionMethod::dynamic_relaxation,
       "the bending-active beam element, explicit with kinetic damping "
       "(doc/dynamic_relaxation.md).",
       declare_dynamic_relaxation},
      {"time stepping",
       SolutionMethod::time_stepping,
       "inertia or creep in time (subsection Time stepping; Newton's entries "
       "apply to each step).",
       declare_time_stepping},
      {"continuation",
       SolutionMethod::continuation,
       "the equilibrium path through limit points and bifurcations "
       "(subsection Continuation).",
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
