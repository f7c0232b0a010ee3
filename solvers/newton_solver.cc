#include <solvers/newton_solver.h>

#include <Epetra_Vector.h>
#include <NOX.H>
#include <NOX_Epetra_Group.H>
#include <NOX_Epetra_Interface_Jacobian.H>
#include <NOX_Epetra_Interface_Required.H>
#include <NOX_Epetra_LinearSystem_Amesos.H>
#include <NOX_Epetra_Vector.H>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    using VectorType = NewtonSolver::VectorType;
    using MatrixType = NewtonSolver::MatrixType;

    /// NOX's view of the problem. Copies between NOX's Epetra_Vector and the
    /// deal.II vector (which holds an Epetra_FEVector) on every call; the
    /// copies are cheap beside an assembly.
    class NoxInterface : public NOX::Epetra::Interface::Required,
                         public NOX::Epetra::Interface::Jacobian
    {
    public:
      NoxInterface(const NewtonSolver::Problem &problem,
                   const VectorType            &layout,
                   MatrixType                  &tangent)
          : problem(problem)
          , x(layout)
          , r(layout)
          , tangent(tangent)
      {
        if (problem.rank_one)
          {
            rank_one_a.reinit(layout);
            rank_one_b.reinit(layout);
          }
      }

      bool
      computeF(const Epetra_Vector &x_in,
               Epetra_Vector       &f,
               const FillType) override
      {
        try
          {
            copy_in(x_in);
            problem.residual(x, r);
            const Epetra_MultiVector &rv = r.trilinos_vector();
            for (int i = 0; i < f.MyLength(); ++i)
              f[i] = rv[0][i];
            return true;
          }
        catch (const std::exception &e)
          {
            record(e.what());
            return false;
          }
      }

      bool
      computeJacobian(const Epetra_Vector &x_in, Epetra_Operator &) override
      {
        try
          {
            copy_in(x_in);
            problem.tangent(x, tangent);
            if (problem.rank_one)
              problem.rank_one(x, rank_one_a, rank_one_b);
            return true;
          }
        catch (const std::exception &e)
          {
            record(e.what());
            return false;
          }
      }

      std::string failure;
      /// The Jacobian's rank-one part a b^T at the last computeJacobian().
      VectorType rank_one_a, rank_one_b;

    private:
      void
      copy_in(const Epetra_Vector &x_in)
      {
        Epetra_MultiVector &xv = x.trilinos_vector();
        for (int i = 0; i < x_in.MyLength(); ++i)
          xv[0][i] = x_in[i];
      }

      void
      record(const std::string &what)
      {
        if (failure.empty())
          failure = what;
      }

      const NewtonSolver::Problem &problem;
      VectorType                   x;
      VectorType                   r;
      MatrixType                  &tangent;
    };

    /**
     * Amesos solves with the Jacobian J = K + a b^T, K the assembled
     * tangent and a, b the interface's rank-one vectors (Sherman-Morrison):
     * J^-1 f = x - y (b.x) / (1 + b.y), with K x = f and K y = a.
     */
    class RankOneAmesos : public NOX::Epetra::LinearSystemAmesos
    {
    public:
      RankOneAmesos(Teuchos::ParameterList              &printing,
                    Teuchos::ParameterList              &linear,
                    const Teuchos::RCP<NoxInterface>    &interface,
                    const Teuchos::RCP<Epetra_Operator> &jacobian,
                    const NOX::Epetra::Vector           &clone)
          : NOX::Epetra::LinearSystemAmesos(printing,
                                            linear,
                                            interface,
                                            interface,
                                            jacobian,
                                            clone)
          , interface(interface)
      {
      }

      bool
      applyJacobian(const NOX::Epetra::Vector &input,
                    NOX::Epetra::Vector       &result) const override
      {
        if (!NOX::Epetra::LinearSystemAmesos::applyJacobian(input, result))
          return false;
        result.getEpetraVector().Update(dot(b(), input.getEpetraVector()),
                                        a(),
                                        1.0);
        return true;
      }

      bool
      applyJacobianInverse(Teuchos::ParameterList    &params,
                           const NOX::Epetra::Vector &input,
                           NOX::Epetra::Vector       &result) override
      {
        NOX::Epetra::Vector a_vector(a(), NOX::DeepCopy);
        NOX::Epetra::Vector y(a_vector, NOX::ShapeCopy);
        if (!NOX::Epetra::LinearSystemAmesos::applyJacobianInverse(params,
                                                                   input,
                                                                   result) ||
            !NOX::Epetra::LinearSystemAmesos::applyJacobianInverse(params,
                                                                   a_vector,
                                                                   y))
          return false;
        const double denominator = 1 + dot(b(), y.getEpetraVector());
        if (!(std::abs(denominator) > 0) || !std::isfinite(denominator))
          return false;
        result.getEpetraVector().Update(-dot(b(), result.getEpetraVector()) /
                                          denominator,
                                        y.getEpetraVector(),
                                        1.0);
        return true;
      }

    private:
      const Epetra_Vector &
      a() const
      {
        return *interface->rank_one_a.trilinos_vector()(0);
      }
      const Epetra_Vector &
      b() const
      {
        return *interface->rank_one_b.trilinos_vector()(0);
      }
      static double
      dot(const Epetra_Vector &u, const Epetra_Vector &v)
      {
        double value = 0;
        u.Dot(v, &value);
        return value;
      }

      Teuchos::RCP<NoxInterface> interface;
    };

    /// NOX's view of Problem::converged: the iterate and its residual,
    /// copied into deal.II vectors, judged by the problem's own test.
    class CallbackTest : public NOX::StatusTest::Generic
    {
    public:
      CallbackTest(const NewtonSolver::Problem &problem,
                   const VectorType            &layout)
          : problem(problem)
          , x(layout)
          , r(layout)
      {
      }

      NOX::StatusTest::StatusType
      checkStatus(const NOX::Solver::Generic      &solver,
                  const NOX::StatusTest::CheckType check) override
      {
        const NOX::Abstract::Group &group = solver.getSolutionGroup();
        if (check == NOX::StatusTest::None || !group.isF())
          return status = NOX::StatusTest::Unevaluated;
        copy(group.getX(), x);
        copy(group.getF(), r);
        status = problem.converged(x, r) ? NOX::StatusTest::Converged :
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
      static void
      copy(const NOX::Abstract::Vector &from, VectorType &to)
      {
        const Epetra_Vector &source =
          dynamic_cast<const NOX::Epetra::Vector &>(from).getEpetraVector();
        Epetra_MultiVector &target = to.trilinos_vector();
        for (int i = 0; i < source.MyLength(); ++i)
          target[0][i] = source[i];
      }

      const NewtonSolver::Problem &problem;
      VectorType                   x;
      VectorType                   r;
      NOX::StatusTest::StatusType  status = NOX::StatusTest::Unevaluated;
    };

    std::string
    nox_line_search_name(const std::string &name)
    {
      if (name == "backtrack")
        return "Backtrack";
      if (name == "polynomial")
        return "Polynomial";
      if (name == "full step")
        return "Full Step";
      throw std::invalid_argument(
        "unknown line search \"" + name +
        "\"; known: backtrack, polynomial, full step");
    }

    /// NOX's parameters: a Newton direction by KLU, the named line search.
    Teuchos::RCP<Teuchos::ParameterList>
    nox_parameters(const NewtonSolver::Parameters &parameters)
    {
      auto list = Teuchos::rcp(new Teuchos::ParameterList);
      list->set("Nonlinear Solver", "Line Search Based");
      Teuchos::ParameterList &printing = list->sublist("Printing");
      // RODNET_NOX_DEBUG in the environment prints NOX's iteration history.
      printing.set("Output Information",
                   std::getenv("RODNET_NOX_DEBUG") != nullptr ?
                     NOX::Utils::OuterIteration + NOX::Utils::Error :
                     NOX::Utils::Error);
      Teuchos::ParameterList &search = list->sublist("Line Search");
      search.set("Method", nox_line_search_name(parameters.line_search));
      Teuchos::ParameterList &direction = list->sublist("Direction");
      direction.set("Method", "Newton");
      Teuchos::ParameterList &linear =
        direction.sublist("Newton").sublist("Linear Solver");
      linear.set("Amesos Solver", "Amesos_Klu");
      return list;
    }

    /// KLU on the tangent, with Sherman-Morrison where the problem has a
    /// rank-one part.
    Teuchos::RCP<NOX::Epetra::LinearSystem>
    linear_system(Teuchos::ParameterList           &nox,
                  const Teuchos::RCP<NoxInterface> &interface,
                  const NewtonSolver::Problem      &problem,
                  MatrixType                       &tangent,
                  const NOX::Epetra::Vector        &initial_guess)
    {
      Teuchos::ParameterList &printing = nox.sublist("Printing");
      Teuchos::ParameterList &linear =
        nox.sublist("Direction").sublist("Newton").sublist("Linear Solver");
      Teuchos::RCP<Epetra_Operator> jacobian_operator = Teuchos::rcp(
        const_cast<Epetra_CrsMatrix *>(&tangent.trilinos_matrix()), false);
      if (problem.rank_one)
        return Teuchos::rcp(new RankOneAmesos(
          printing, linear, interface, jacobian_operator, initial_guess));
      Teuchos::RCP<NOX::Epetra::Interface::Required> required = interface;
      Teuchos::RCP<NOX::Epetra::Interface::Jacobian> jacobian = interface;
      return Teuchos::rcp(new NOX::Epetra::LinearSystemAmesos(printing,
                                                              linear,
                                                              required,
                                                              jacobian,
                                                              jacobian_operator,
                                                              initial_guess));
    }

    /// Stop when the state is not finite, when converged (the problem's
    /// test, or |R| below the tolerance), or after max_iterations.
    Teuchos::RCP<NOX::StatusTest::Generic>
    status_tests(const NewtonSolver::Problem    &problem,
                 const VectorType               &x,
                 const NewtonSolver::Parameters &parameters)
    {
      Teuchos::RCP<NOX::StatusTest::Generic> converged;
      if (problem.converged)
        converged = Teuchos::rcp(new CallbackTest(problem, x));
      else
        converged = Teuchos::rcp(
          new NOX::StatusTest::NormF(parameters.tolerance,
                                     NOX::StatusTest::NormF::Unscaled));
      auto status = Teuchos::rcp(
        new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
      status->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));
      status->addStatusTest(converged);
      status->addStatusTest(
        Teuchos::rcp(new NOX::StatusTest::MaxIters(parameters.max_iterations)));
      return status;
    }

    /// The result of a finished solve, with the reason of a failure.
    NewtonSolver::Result
    judge(const NOX::Solver::Generic     &solver,
          const NOX::StatusTest::StatusType outcome,
          const NoxInterface             &interface,
          const NewtonSolver::Parameters &parameters)
    {
      const NOX::Abstract::Group &group = solver.getSolutionGroup();
      NewtonSolver::Result        result;
      result.iterations    = solver.getNumIterations();
      result.residual_norm = group.isF() ? group.getNormF() : NAN;
      result.converged     = outcome == NOX::StatusTest::Converged &&
                         std::isfinite(result.residual_norm);
      if (result.converged)
        return result;
      if (!interface.failure.empty())
        result.failure = interface.failure;
      else if (!std::isfinite(result.residual_norm))
        result.failure = "the residual is not finite";
      else if (result.iterations >= parameters.max_iterations)
        result.failure = "no convergence in " +
                         std::to_string(parameters.max_iterations) +
                         " iterations (residual " +
                         std::to_string(result.residual_norm) + ")";
      else
        result.failure = "the line search failed (residual " +
                         std::to_string(result.residual_norm) + ")";
      return result;
    }
  } // namespace

  NewtonSolver::NewtonSolver(const Parameters &parameters)
      : parameters(parameters)
  {
    nox_line_search_name(parameters.line_search);
  }

  NewtonSolver::Result
  NewtonSolver::solve(const Problem &problem,
                      VectorType    &x,
                      MatrixType    &tangent) const
  {
    const Teuchos::RCP<Teuchos::ParameterList> nox = nox_parameters(parameters);
    auto interface = Teuchos::rcp(new NoxInterface(problem, x, tangent));
    Teuchos::RCP<NOX::Epetra::Interface::Required> required = interface;
    Epetra_Vector       x_view(View, x.trilinos_vector(), 0);
    NOX::Epetra::Vector initial_guess(x_view, NOX::DeepCopy);
    auto                group = Teuchos::rcp(new NOX::Epetra::Group(
      nox->sublist("Printing"),
      required,
      initial_guess,
      linear_system(*nox, interface, problem, tangent, initial_guess)));

    Teuchos::RCP<NOX::Solver::Generic> solver;
    NOX::StatusTest::StatusType        outcome = NOX::StatusTest::Failed;
    try
      {
        solver  = NOX::Solver::buildSolver(group,
                                          status_tests(problem, x, parameters),
                                          nox);
        outcome = solver->solve();
      }
    catch (...)
      {
        // NOX reports a residual or tangent our interface could not
        // compute by throwing a C string ("fill failed"); the reason is the
        // exception our interface recorded. x keeps the initial guess.
        Result result;
        result.failure       = interface->failure.empty() ?
                                 "the nonlinear solver aborted" :
                                 interface->failure;
        result.residual_norm = NAN;
        return result;
      }

    const Epetra_Vector &final_x =
      dynamic_cast<const NOX::Epetra::Vector &>(
        solver->getSolutionGroup().getX())
        .getEpetraVector();
    for (int i = 0; i < final_x.MyLength(); ++i)
      x_view[i] = final_x[i];
    return judge(*solver, outcome, *interface, parameters);
  }
} // namespace rodnet
