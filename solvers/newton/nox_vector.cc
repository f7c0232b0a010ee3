#include <solvers/newton/nox_vector.h>

#include <Epetra_MultiVector.h>
#include <cmath>
#include <stdexcept>

namespace rodnet
{
  NoxVector::NoxVector(const VectorType &values, const NOX::CopyType type)
      : vector(values)
  {
    if (type == NOX::ShapeCopy)
      vector = 0;
  }


  const NoxVector::VectorType &
  NoxVector::values(const NOX::Abstract::Vector &v)
  {
    const auto *own = dynamic_cast<const NoxVector *>(&v);
    if (own == nullptr)
      throw std::logic_error("NoxVector: NOX handed over a vector of "
                             "another kind");
    return own->vector;
  }


  NoxVector::VectorType &
  NoxVector::values(NOX::Abstract::Vector &v)
  {
    return const_cast<VectorType &>(
      values(static_cast<const NOX::Abstract::Vector &>(v)));
  }


  NOX::Abstract::Vector &
  NoxVector::init(const double gamma)
  {
    entries().PutScalar(gamma);
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::random(const bool use_seed, const int seed)
  {
    if (use_seed)
      entries().SetSeed(seed);
    entries().Random();
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::abs(const NOX::Abstract::Vector &y)
  {
    entries().Abs(values(y).trilinos_vector());
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::operator=(const NOX::Abstract::Vector &y)
  {
    entries() = values(y).trilinos_vector();
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::reciprocal(const NOX::Abstract::Vector &y)
  {
    entries().Reciprocal(values(y).trilinos_vector());
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::scale(const double gamma)
  {
    entries().Scale(gamma);
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::scale(const NOX::Abstract::Vector &a)
  {
    entries().Multiply(1.0, values(a).trilinos_vector(), entries(), 0.0);
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::update(const double                 alpha,
                    const NOX::Abstract::Vector &a,
                    const double                 gamma)
  {
    entries().Update(alpha, values(a).trilinos_vector(), gamma);
    return *this;
  }


  NOX::Abstract::Vector &
  NoxVector::update(const double                 alpha,
                    const NOX::Abstract::Vector &a,
                    const double                 beta,
                    const NOX::Abstract::Vector &b,
                    const double                 gamma)
  {
    entries().Update(alpha,
                     values(a).trilinos_vector(),
                     beta,
                     values(b).trilinos_vector(),
                     gamma);
    return *this;
  }


  Teuchos::RCP<NOX::Abstract::Vector>
  NoxVector::clone(const NOX::CopyType type) const
  {
    return Teuchos::rcp(new NoxVector(vector, type));
  }


  double
  NoxVector::norm(const NOX::Abstract::Vector::NormType type) const
  {
    double value = 0;
    switch (type)
      {
        case NOX::Abstract::Vector::MaxNorm:
          entries().NormInf(&value);
          break;
        case NOX::Abstract::Vector::OneNorm:
          entries().Norm1(&value);
          break;
        default:
          entries().Norm2(&value);
      }
    return value;
  }


  double
  NoxVector::norm(const NOX::Abstract::Vector &weights) const
  {
    // NOX's weighted norm: sqrt(sum_i w_i x_i^2).
    Epetra_MultiVector weighted(entries());
    weighted.Multiply(1.0, values(weights).trilinos_vector(), entries(), 0.0);
    double value = 0;
    entries().Dot(weighted, &value);
    return std::sqrt(value);
  }


  double
  NoxVector::innerProduct(const NOX::Abstract::Vector &y) const
  {
    double value = 0;
    entries().Dot(values(y).trilinos_vector(), &value);
    return value;
  }


  NOX::size_type
  NoxVector::length() const
  {
    return vector.size();
  }
} // namespace rodnet
