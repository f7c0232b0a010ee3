#ifndef RODNET_SOLVERS_NEWTON_NOX_GROUP_H
#define RODNET_SOLVERS_NEWTON_NOX_GROUP_H

#include <solvers/newton/newton_solver.h>
#include <solvers/newton/nox_vector.h>
#include <solvers/newton/tangent_factorization.h>

#include <NOX_Abstract_Group.H>
#include <memory>
#include <string>

namespace rodnet
{
  /**
   * NOX's group (a state x with its residual F(x), Jacobian and Newton
   * direction) for NewtonSolver::Problem, on deal.II's Trilinos vectors:
   * the residual and tangent come from the problem's callbacks, the
   * Newton direction from a TangentFactorization (KLU or band LU), with
   * the Sherman-Morrison formula where the problem has a rank-one part
   * a b^T: J^-1 f = x - y (b.x) / (1 + b.y), with K x = f and K y = a.
   *
   * The groups NOX clones from one another share the tangent matrix and
   * its factorization; the Jacobian belongs to the group that computed it
   * last (or was assigned from it), as in NOX's Epetra groups.
   */
  class NoxGroup : public NOX::Abstract::Group
  {
  public:
    /// A group at @p x of @p problem, which assembles into @p tangent and
    /// solves with a factorization of @p linear_solver's kind
    /// (TangentFactorization::create()).
    NoxGroup(const NewtonSolver::Problem          &problem,
             const NoxVector::VectorType          &x,
             NewtonSolver::MatrixType             &tangent,
             std::shared_ptr<TangentFactorization> factorization);

    /// Why the last residual, tangent or solve failed (empty if none did).
    const std::string &
    failure() const;

    /// Forgets the recorded failure (a line search that stepped back from
    /// a state it could not evaluate).
    void
    forget_failure();

    /// The problem's potential energy at x (Problem::energy), NaN unless
    /// computeF() computed it there.
    double
    energy() const;

    /// The kind of factorization used ("klu", "band").
    std::string
    linear_solver() const;

    /// Not the implicit copy (it would call the base's pure assignment):
    /// assign through NOX::Abstract::Group.
    NoxGroup &
    operator=(const NoxGroup &) = delete;

    NOX::Abstract::Group &
    operator=(const NOX::Abstract::Group &source) override;
    void
    setX(const NOX::Abstract::Vector &y) override;
    void
    computeX(const NOX::Abstract::Group  &grp,
             const NOX::Abstract::Vector &d,
             double                       step) override;
    ReturnType
    computeF() override;
    ReturnType
    computeJacobian() override;
    ReturnType
    computeGradient() override;
    ReturnType
    computeNewton(Teuchos::ParameterList &params) override;
    ReturnType
    applyJacobian(const NOX::Abstract::Vector &input,
                  NOX::Abstract::Vector       &result) const override;
    ReturnType
    applyJacobianTranspose(const NOX::Abstract::Vector &input,
                           NOX::Abstract::Vector       &result) const override;
    ReturnType
    applyJacobianInverse(Teuchos::ParameterList      &params,
                         const NOX::Abstract::Vector &input,
                         NOX::Abstract::Vector       &result) const override;
    bool
    isF() const override;
    bool
    isJacobian() const override;
    bool
    isGradient() const override;
    bool
    isNewton() const override;
    const NOX::Abstract::Vector &
    getX() const override;
    const NOX::Abstract::Vector &
    getF() const override;
    double
    getNormF() const override;
    const NOX::Abstract::Vector &
    getGradient() const override;
    const NOX::Abstract::Vector &
    getNewton() const override;
    Teuchos::RCP<const NOX::Abstract::Vector>
    getXPtr() const override;
    Teuchos::RCP<const NOX::Abstract::Vector>
    getFPtr() const override;
    Teuchos::RCP<const NOX::Abstract::Vector>
    getGradientPtr() const override;
    Teuchos::RCP<const NOX::Abstract::Vector>
    getNewtonPtr() const override;
    Teuchos::RCP<NOX::Abstract::Group>
    clone(NOX::CopyType type = NOX::DeepCopy) const override;

  private:
    struct Shared;

    /// A group of the same problem as @p source, its vectors copied
    /// (DeepCopy) or of the same layout (ShapeCopy).
    NoxGroup(const NoxGroup &source, NOX::CopyType type);

    /// J @p input (or J^T @p input if @p transpose) into @p result.
    ReturnType
    apply(const NOX::Abstract::Vector &input,
          NOX::Abstract::Vector       &result,
          bool                         transpose) const;

    /// Forgets F, the Jacobian, the gradient and the Newton direction
    /// (x changed).
    void
    reset();

    /// Records @p what as the failure (the first one is kept).
    void
    record(const std::string &what) const;

    std::shared_ptr<Shared> shared;
    Teuchos::RCP<NoxVector> x, f, gradient, newton;
    /// Problem::energy at x, computed with F.
    double energy_value = 0;
    bool   f_valid = false, gradient_valid = false, newton_valid = false,
         jacobian_valid = false;
  };
} // namespace rodnet

#endif
