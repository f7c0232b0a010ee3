#include <solvers/newton/nox_group.h>

#include <cmath>
#include <exception>
#include <limits>

namespace rodnet
{
  /// What the clones of one group share: the problem, the tangent and its
  /// factorization, the rank-one part, and which group owns the Jacobian.
  struct NoxGroup::Shared
  {
    const NewtonSolver::Problem          &problem;
    NewtonSolver::MatrixType             &tangent;
    std::shared_ptr<TangentFactorization> factorization;
    /// Whether the factorization is of the tangent's current values.
    bool factorized = false;
    /// The rank-one part a b^T of the Jacobian (if the problem has one).
    NoxVector::VectorType rank_one_a, rank_one_b;
    /// K^-1 a, where rank_one_solved: the Sherman-Morrison solve that
    /// modified Newton's iterations share with the first.
    NoxVector::VectorType rank_one_solution;
    bool                  rank_one_solved = false;
    /// The group whose Jacobian the tangent holds.
    const NoxGroup *owner = nullptr;
    std::string     failure;
  };


  NoxGroup::NoxGroup(const NewtonSolver::Problem          &problem,
                     const NoxVector::VectorType          &x,
                     NewtonSolver::MatrixType             &tangent,
                     std::shared_ptr<TangentFactorization> factorization)
      : shared(new Shared{problem,
                          tangent,
                          std::move(factorization),
                          false,
                          {},
                          {},
                          {},
                          false,
                          nullptr,
                          {}})
      , x(Teuchos::rcp(new NoxVector(x)))
      , f(Teuchos::rcp(new NoxVector(x, NOX::ShapeCopy)))
      , gradient(Teuchos::rcp(new NoxVector(x, NOX::ShapeCopy)))
      , newton(Teuchos::rcp(new NoxVector(x, NOX::ShapeCopy)))
  {
    if (problem.rank_one)
      {
        shared->rank_one_a.reinit(x);
        shared->rank_one_b.reinit(x);
        shared->rank_one_solution.reinit(x);
      }
  }


  NoxGroup::NoxGroup(const NoxGroup &source, const NOX::CopyType type)
      : shared(source.shared)
      , x(Teuchos::rcp(new NoxVector(source.x->values(), type)))
      , f(Teuchos::rcp(new NoxVector(source.f->values(), type)))
      , gradient(Teuchos::rcp(new NoxVector(source.gradient->values(), type)))
      , newton(Teuchos::rcp(new NoxVector(source.newton->values(), type)))
  {
    if (type == NOX::DeepCopy)
      operator=(static_cast<const NOX::Abstract::Group &>(source));
  }


  const std::string &
  NoxGroup::failure() const
  {
    return shared->failure;
  }


  std::string
  NoxGroup::linear_solver() const
  {
    return shared->factorization->name();
  }


  void
  NoxGroup::record(const std::string &what) const
  {
    if (shared->failure.empty())
      shared->failure = what;
  }


  void
  NoxGroup::forget_failure()
  {
    shared->failure.clear();
  }


  double
  NoxGroup::energy() const
  {
    return f_valid && shared->problem.energy ?
             energy_value :
             std::numeric_limits<double>::quiet_NaN();
  }


  void
  NoxGroup::reset()
  {
    f_valid = gradient_valid = newton_valid = jacobian_valid = false;
  }


  NOX::Abstract::Group &
  NoxGroup::operator=(const NOX::Abstract::Group &source_group)
  {
    const auto &source = dynamic_cast<const NoxGroup &>(source_group);
    if (&source == this)
      return *this;
    *x             = *source.x;
    *f             = *source.f;
    *gradient      = *source.gradient;
    *newton        = *source.newton;
    energy_value   = source.energy_value;
    f_valid        = source.f_valid;
    gradient_valid = source.gradient_valid;
    newton_valid   = source.newton_valid;
    // The Jacobian moves with the copy (NOX's Epetra groups do the same).
    jacobian_valid = source.isJacobian();
    if (jacobian_valid)
      shared->owner = this;
    return *this;
  }


  void
  NoxGroup::setX(const NOX::Abstract::Vector &y)
  {
    reset();
    *x = y;
  }


  void
  NoxGroup::computeX(const NOX::Abstract::Group  &grp,
                     const NOX::Abstract::Vector &d,
                     const double                 step)
  {
    reset();
    x->update(1.0, grp.getX(), step, d, 0.0);
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::computeF()
  {
    if (f_valid)
      return Ok;
    try
      {
        if (shared->problem.energy)
          energy_value = shared->problem.energy(x->values(), &f->values());
        else
          shared->problem.residual(x->values(), f->values());
      }
    catch (const std::exception &e)
      {
        record(e.what());
        return Failed;
      }
    f_valid = true;
    return Ok;
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::computeJacobian()
  {
    if (isJacobian())
      return Ok;
    if (shared->problem.reuse_first_jacobian && shared->owner != nullptr)
      {
        // Modified Newton: the tangent and factorization of the first
        // iterate stand for this one's.
        shared->owner  = this;
        jacobian_valid = true;
        return Ok;
      }
    shared->owner           = this;
    shared->factorized      = false;
    shared->rank_one_solved = false;
    try
      {
        shared->problem.tangent(x->values(), shared->tangent);
        if (shared->problem.rank_one)
          shared->problem.rank_one(x->values(),
                                   shared->rank_one_a,
                                   shared->rank_one_b);
      }
    catch (const std::exception &e)
      {
        shared->owner = nullptr;
        record(e.what());
        return Failed;
      }
    jacobian_valid = true;
    return Ok;
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::computeGradient()
  {
    if (gradient_valid)
      return Ok;
    if (computeF() != Ok || computeJacobian() != Ok)
      return Failed;
    const ReturnType status = applyJacobianTranspose(*f, *gradient);
    gradient_valid          = status == Ok;
    return status;
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::computeNewton(Teuchos::ParameterList &params)
  {
    if (newton_valid)
      return Ok;
    if (computeF() != Ok || computeJacobian() != Ok)
      return Failed;
    const ReturnType status = applyJacobianInverse(params, *f, *newton);
    if (status != Ok)
      return status;
    newton->scale(-1.0);
    newton_valid = true;
    return Ok;
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::apply(const NOX::Abstract::Vector &input,
                  NOX::Abstract::Vector       &result,
                  const bool                   transpose) const
  {
    if (!isJacobian())
      return BadDependency;
    const auto &in  = NoxVector::values(input);
    auto       &out = NoxVector::values(result);
    // J = K + a b^T, J^T = K^T + b a^T.
    const auto &a = transpose ? shared->rank_one_b : shared->rank_one_a;
    const auto &b = transpose ? shared->rank_one_a : shared->rank_one_b;
    if (transpose)
      shared->tangent.Tvmult(out, in);
    else
      shared->tangent.vmult(out, in);
    if (shared->problem.rank_one)
      out.add(b * in, a);
    return Ok;
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::applyJacobian(const NOX::Abstract::Vector &input,
                          NOX::Abstract::Vector       &result) const
  {
    return apply(input, result, false);
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::applyJacobianTranspose(const NOX::Abstract::Vector &input,
                                   NOX::Abstract::Vector       &result) const
  {
    return apply(input, result, true);
  }


  NOX::Abstract::Group::ReturnType
  NoxGroup::applyJacobianInverse(Teuchos::ParameterList &,
                                 const NOX::Abstract::Vector &input,
                                 NOX::Abstract::Vector       &result) const
  {
    if (!isJacobian())
      return BadDependency;
    const auto &in  = NoxVector::values(input);
    auto       &out = NoxVector::values(result);
    try
      {
        if (!shared->factorized)
          {
            shared->factorization->factorize();
            shared->factorized = true;
          }
        const auto &b = shared->rank_one_b;
        const auto &y = shared->rank_one_solution;
        if (shared->problem.rank_one && !shared->rank_one_solved)
          {
            // K^-1 a of the Sherman-Morrison formula with the first solve.
            shared->factorization->solve(in,
                                         out,
                                         shared->rank_one_a,
                                         shared->rank_one_solution);
            shared->rank_one_solved = true;
          }
        else
          shared->factorization->solve(in, out);
        if (!shared->problem.rank_one)
          return Ok;
        const double denominator = 1 + b * y;
        if (!(std::abs(denominator) > 0) || !std::isfinite(denominator))
          {
            record("the Jacobian with its rank-one part is singular");
            return Failed;
          }
        out.add(-(b * out) / denominator, y);
      }
    catch (const std::exception &e)
      {
        record(e.what());
        return Failed;
      }
    return Ok;
  }


  bool
  NoxGroup::isF() const
  {
    return f_valid;
  }


  bool
  NoxGroup::isJacobian() const
  {
    return jacobian_valid && shared->owner == this;
  }


  bool
  NoxGroup::isGradient() const
  {
    return gradient_valid;
  }


  bool
  NoxGroup::isNewton() const
  {
    return newton_valid;
  }


  const NOX::Abstract::Vector &
  NoxGroup::getX() const
  {
    return *x;
  }


  const NOX::Abstract::Vector &
  NoxGroup::getF() const
  {
    return *f;
  }


  double
  NoxGroup::getNormF() const
  {
    return f_valid ? f->norm() : NAN;
  }


  const NOX::Abstract::Vector &
  NoxGroup::getGradient() const
  {
    return *gradient;
  }


  const NOX::Abstract::Vector &
  NoxGroup::getNewton() const
  {
    return *newton;
  }


  Teuchos::RCP<const NOX::Abstract::Vector>
  NoxGroup::getXPtr() const
  {
    return x;
  }


  Teuchos::RCP<const NOX::Abstract::Vector>
  NoxGroup::getFPtr() const
  {
    return f;
  }


  Teuchos::RCP<const NOX::Abstract::Vector>
  NoxGroup::getGradientPtr() const
  {
    return gradient;
  }


  Teuchos::RCP<const NOX::Abstract::Vector>
  NoxGroup::getNewtonPtr() const
  {
    return newton;
  }


  Teuchos::RCP<NOX::Abstract::Group>
  NoxGroup::clone(const NOX::CopyType type) const
  {
    return Teuchos::rcp(new NoxGroup(*this, type));
  }
} // namespace rodnet
