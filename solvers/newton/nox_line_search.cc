#include <solvers/newton/nox_group.h>
#include <solvers/newton/nox_line_search.h>

#include <NOX.H>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_oblackholestream.hpp>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <iomanip>
#include <sstream>

namespace rodnet
{
  namespace
  {
    using VectorType = NewtonSolver::VectorType;
    using MatrixType = NewtonSolver::MatrixType;

    /// NOX's view of Problem::converged: the iterate and its residual (the
    /// deal.II vectors of our group), judged by the problem's own test.
    class CallbackTest : public NOX::StatusTest::Generic
    {
    public:
      explicit CallbackTest(const NewtonSolver::Problem &problem)
          : problem(problem)
      {
      }

      NOX::StatusTest::StatusType
      checkStatus(const NOX::Solver::Generic      &solver,
                  const NOX::StatusTest::CheckType check) override
      {
        const NOX::Abstract::Group &group = solver.getSolutionGroup();
        if (check == NOX::StatusTest::None || !group.isF())
          return status = NOX::StatusTest::Unevaluated;
        status = problem.converged(NoxVector::values(group.getX()),
                                   NoxVector::values(group.getF())) ?
                   NOX::StatusTest::Converged :
                   NOX::StatusTest::Unconverged;
        return status;
      }

      NOX::StatusTest::StatusType
      getStatus() const override
      {
        return status;
      }

      std::ostream &
      print(std::ostream &stream, int indent = 0) const override
      {
        return stream << std::string(indent, ' ') << status
                      << " residual test of the problem" << std::endl;
      }

    private:
      const NewtonSolver::Problem &problem;
      NOX::StatusTest::StatusType  status = NOX::StatusTest::Unevaluated;
    };

    /**
     * Stops a solve whose residual norm has stayed above growth() times
     * that of its initial guess for iterations() iterations in a row:
     * Newton is diverging from this start, and the iterations left (25 by
     * default, each a factorization) would be wasted before the caller
     * tries another start. On the soft welded lattice (issue 37) full
     * Newton from the flat state climbed from 0.3 N to 2.9e9 N over its 25
     * iterations. A converging Newton solve can overshoot by orders of
     * magnitude for an iteration or two (a large rotation stretching the
     * rods), not for five.
     */
    class DivergenceTest : public NOX::StatusTest::Generic
    {
    public:
      static constexpr double       growth     = 1e6;
      static constexpr unsigned int iterations = 5;

      NOX::StatusTest::StatusType
      checkStatus(const NOX::Solver::Generic &solver,
                  const NOX::StatusTest::CheckType) override
      {
        const NOX::Abstract::Group &group = solver.getSolutionGroup();
        if (!group.isF())
          return status = NOX::StatusTest::Unevaluated;
        const double norm = group.getNormF();
        if (solver.getNumIterations() == 0)
          initial = norm;
        above         = norm > growth * initial ? above + 1 : 0;
        last          = norm;
        return status = above >= iterations ? NOX::StatusTest::Failed :
                                              NOX::StatusTest::Unconverged;
      }

      NOX::StatusTest::StatusType
      getStatus() const override
      {
        return status;
      }

      std::ostream &
      print(std::ostream &stream, int indent = 0) const override
      {
        return stream << std::string(indent, ' ') << status
                      << " divergence test" << std::endl;
      }

      /// Why the solve stopped, where this test stopped it.
      std::string
      failure() const
      {
        if (status != NOX::StatusTest::Failed)
          return "";
        std::ostringstream text;
        text << std::setprecision(3)
             << "Newton diverges from this start: the residual grew from "
             << initial << " to " << last << ", above " << growth
             << " times its start for " << iterations << " iterations in a row";
        return text.str();
      }

    private:
      NOX::StatusTest::StatusType status  = NOX::StatusTest::Unevaluated;
      double                      initial = 0;
      double                      last    = 0;
      unsigned int                above   = 0;
    };

    /// NOX's parameters: a Newton direction, the line search @p method,
    /// made by @p user_defined if not null.
    Teuchos::RCP<Teuchos::ParameterList>
    nox_parameters(
      const std::string                                       &method,
      const Teuchos::RCP<NOX::LineSearch::UserDefinedFactory> &user_defined)
    {
      auto list = Teuchos::rcp(new Teuchos::ParameterList);
      list->set("Nonlinear Solver", "Line Search Based");
      Teuchos::ParameterList &printing = list->sublist("Printing");
      // NOX says nothing: its failures (a residual it cannot compute, a
      // line search that gives up) come back as an unconverged result that
      // the solvers report in their own words; some of its messages ignore
      // the print types, so its streams go nowhere. RODNET_NOX_DEBUG in the
      // environment prints NOX's iteration history and errors.
      if (std::getenv("RODNET_NOX_DEBUG") != nullptr)
        printing.set("Output Information",
                     NOX::Utils::OuterIteration + NOX::Utils::Error);
      else
        {
          const Teuchos::RCP<std::ostream> nowhere =
            Teuchos::rcp(new Teuchos::oblackholestream);
          printing.set("Output Information", 0);
          printing.set("Output Stream", nowhere);
          printing.set("Error Stream", nowhere);
        }
      Teuchos::ParameterList &search = list->sublist("Line Search");
      search.set("Method", method);
      if (!user_defined.is_null())
        search.set("User Defined Line Search Factory", user_defined);
      list->sublist("Direction").set("Method", "Newton");
      return list;
    }

    /// Stop when the state is not finite, when converged (the problem's
    /// test, or |R| below the tolerance), when diverging (@p divergence),
    /// or after max_iterations.
    Teuchos::RCP<NOX::StatusTest::Generic>
    status_tests(const NewtonSolver::Problem        &problem,
                 const NewtonSolver::Parameters     &parameters,
                 const Teuchos::RCP<DivergenceTest> &divergence)
    {
      Teuchos::RCP<NOX::StatusTest::Generic> converged;
      if (problem.converged)
        converged = Teuchos::rcp(new CallbackTest(problem));
      else
        converged = Teuchos::rcp(
          new NOX::StatusTest::NormF(parameters.tolerance,
                                     NOX::StatusTest::NormF::Unscaled));
      auto status =
        Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
      status->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));
      status->addStatusTest(converged);
      status->addStatusTest(divergence);
      status->addStatusTest(
        Teuchos::rcp(new NOX::StatusTest::MaxIters(parameters.max_iterations)));
      return status;
    }

    /// The message of the exception being handled (in a catch block).
    std::string
    current_exception_text()
    {
      try
        {
          throw;
        }
      catch (const std::exception &e)
        {
          return e.what();
        }
      catch (const char *text)
        {
          return text;
        }
      catch (...)
        {
          return "unknown exception";
        }
    }

    /// The result of a finished solve, with the reason of a failure.
    NewtonSolver::Result
    judge(const NOX::Solver::Generic       &solver,
          const NOX::StatusTest::StatusType outcome,
          const NoxGroup                   &state,
          const DivergenceTest             &divergence,
          const NewtonSolver::Parameters   &parameters)
    {
      const NOX::Abstract::Group &group = solver.getSolutionGroup();
      NewtonSolver::Result        result;
      result.iterations    = solver.getNumIterations();
      result.residual_norm = group.isF() ? group.getNormF() : NAN;
      result.converged     = outcome == NOX::StatusTest::Converged &&
                         std::isfinite(result.residual_norm);
      if (result.converged)
        return result;
      if (!state.failure().empty())
        result.failure = state.failure();
      else if (!std::isfinite(result.residual_norm))
        result.failure = "the residual is not finite";
      else if (!divergence.failure().empty())
        result.failure = divergence.failure();
      else if (result.iterations >= parameters.max_iterations)
        result.failure =
          "no convergence in " + std::to_string(parameters.max_iterations) +
          " iterations (residual " + std::to_string(result.residual_norm) + ")";
      else
        result.failure = "the line search failed (residual " +
                         std::to_string(result.residual_norm) + ")";
      return result;
    }
  } // namespace

  NoxLineSearch::NoxLineSearch(
    std::string                                       method,
    Teuchos::RCP<NOX::LineSearch::UserDefinedFactory> user_defined)
      : method(std::move(method))
      , user_defined(std::move(user_defined))
  {
  }

  NewtonSolver::Result
  NoxLineSearch::solve(const NewtonSolve &call) const
  {
    using Result                                   = NewtonSolver::Result;
    const NewtonSolver::Problem    &problem        = call.problem;
    VectorType                     &x              = call.x;
    MatrixType                     &tangent        = call.tangent;
    TangentFactorizationCache      *factorizations = call.factorizations;
    const NewtonSolver::Parameters &parameters     = call.parameters;
    const Teuchos::RCP<Teuchos::ParameterList> nox =
      nox_parameters(method, user_defined);
    Teuchos::RCP<NoxGroup>             group;
    Teuchos::RCP<NOX::Solver::Generic> solver;
    NOX::StatusTest::StatusType        outcome = NOX::StatusTest::Failed;
    const auto divergence = Teuchos::rcp(new DivergenceTest);
    try
      {
        group   = Teuchos::rcp(new NoxGroup(
          problem,
          x,
          tangent,
          factorizations != nullptr ?
              factorizations->get(tangent, parameters.linear_solver) :
              TangentFactorization::create(tangent, parameters.linear_solver)));
        solver  = NOX::Solver::buildSolver(group,
                                          status_tests(problem,
                                                       parameters,
                                                       divergence),
                                          nox);
        outcome = solver->solve();
      }
    catch (...)
      {
        // NOX reports a residual or tangent our group could not compute by
        // throwing a C string ("fill failed"); the reason is the one our
        // group recorded. x keeps the initial guess.
        Result result;
        result.failure =
          !group.is_null() && !group->failure().empty() ?
            group->failure() :
            "the nonlinear solver aborted: " + current_exception_text();
        result.residual_norm = NAN;
        return result;
      }
    x = NoxVector::values(solver->getSolutionGroup().getX());
    return judge(*solver, outcome, *group, *divergence, parameters);
  }
} // namespace rodnet
