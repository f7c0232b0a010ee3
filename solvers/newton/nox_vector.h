#ifndef RODNET_SOLVERS_NEWTON_NOX_VECTOR_H
#define RODNET_SOLVERS_NEWTON_NOX_VECTOR_H

#include <deal.II/lac/trilinos_vector.h>

#include <NOX_Abstract_Vector.H>

namespace rodnet
{
  /**
   * NOX's vector interface over deal.II's Trilinos vector, so that NOX's
   * Newton solver works on the model's own vectors. (NOX's Epetra layer,
   * NOX::Epetra::Vector, would do the same but brings 24 more shared
   * libraries into every process: Thyra, Stratimikos, Tpetra, ...;
   * doc/performance.md, "Start-up".)
   */
  class NoxVector : public NOX::Abstract::Vector
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// A copy of @p values (or a vector of its layout, zero, if
    /// @p type is NOX::ShapeCopy).
    explicit NoxVector(const VectorType &values,
                       NOX::CopyType     type = NOX::DeepCopy);

    NoxVector(const NoxVector &) = default;

    /// Copies the values of @p y (the base's assignment is NOX's virtual
    /// one, which the implicit copy assignment would not call).
    NoxVector &
    operator=(const NoxVector &y)
    {
      vector = y.vector;
      return *this;
    }

    /// The deal.II vector.
    VectorType &
    values()
    {
      return vector;
    }
    const VectorType &
    values() const
    {
      return vector;
    }

    /// The deal.II vector of @p v, which must be a NoxVector.
    static const VectorType &
    values(const NOX::Abstract::Vector &v);
    static VectorType &
    values(NOX::Abstract::Vector &v);

    NOX::Abstract::Vector &
    init(double gamma) override;
    NOX::Abstract::Vector &
    random(bool use_seed = false, int seed = 1) override;
    NOX::Abstract::Vector &
    abs(const NOX::Abstract::Vector &y) override;
    NOX::Abstract::Vector &
    operator=(const NOX::Abstract::Vector &y) override;
    NOX::Abstract::Vector &
    reciprocal(const NOX::Abstract::Vector &y) override;
    NOX::Abstract::Vector &
    scale(double gamma) override;
    NOX::Abstract::Vector &
    scale(const NOX::Abstract::Vector &a) override;
    NOX::Abstract::Vector &
    update(double                       alpha,
           const NOX::Abstract::Vector &a,
           double                       gamma = 0.0) override;
    NOX::Abstract::Vector &
    update(double                       alpha,
           const NOX::Abstract::Vector &a,
           double                       beta,
           const NOX::Abstract::Vector &b,
           double                       gamma = 0.0) override;
    Teuchos::RCP<NOX::Abstract::Vector>
    clone(NOX::CopyType type = NOX::DeepCopy) const override;
    double
    norm(NOX::Abstract::Vector::NormType type =
           NOX::Abstract::Vector::TwoNorm) const override;
    double
    norm(const NOX::Abstract::Vector &weights) const override;
    double
    innerProduct(const NOX::Abstract::Vector &y) const override;
    NOX::size_type
    length() const override;

  private:
    /// The entries this process owns (all on one process).
    Epetra_MultiVector &
    entries()
    {
      return vector.trilinos_vector();
    }
    const Epetra_MultiVector &
    entries() const
    {
      return vector.trilinos_vector();
    }

    VectorType vector;
  };
} // namespace rodnet

#endif
