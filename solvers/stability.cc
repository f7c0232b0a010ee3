
#include <solvers/stability.h>

#include <Eigen/SparseCholesky>
#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <stdexcept>

namespace rodnet
{
  namespace internal
  {
    /// The tangent restricted to the free DoFs as an Eigen sparse matrix
    /// (lower triangle: all SimplicialLDLT reads), the map from free to
    /// global indices and the magnitudes of the diagonal. Not in the
    /// anonymous namespace: ConstrainedFactorization::Data holds one.
    struct FreeBlock
    {
      Eigen::SparseMatrix<double> matrix;
      std::vector<unsigned int>   global;
      Eigen::VectorXd             diagonal;
    };
  } // namespace internal

  namespace
  {
    using internal::FreeBlock;

    FreeBlock
    sparse_free_block(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                      const dealii::AffineConstraints<double>      &constraints)
    {
      const unsigned int n_dofs = tangent.m();
      std::vector<int>   free_index(n_dofs, -1);
      FreeBlock          block;
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (!constraints.is_constrained(i))
          {
            free_index[i] = block.global.size();
            block.global.push_back(i);
          }
      const unsigned int                  n = block.global.size();
      std::vector<Eigen::Triplet<double>> entries;
      block.diagonal = Eigen::VectorXd::Zero(n);
      // Epetra's row views: deal.II's entry iterators cost more than the
      // factorization on large tangents.
      const Epetra_CrsMatrix &matrix = tangent.trilinos_matrix();
      for (unsigned int k = 0; k < n; ++k)
        {
          int     length;
          double *values;
          int    *columns;
          matrix.ExtractMyRowView(matrix.LRID(int(block.global[k])),
                                  length,
                                  values,
                                  columns);
          for (int e = 0; e < length; ++e)
            {
              const int column = free_index[matrix.GCID(columns[e])];
              if (column == int(k))
                block.diagonal[k] = std::abs(values[e]);
              if (column >= 0 && column <= int(k))
                entries.emplace_back(k, column, values[e]);
            }
        }
      block.matrix.resize(n, n);
      block.matrix.setFromTriplets(entries.begin(), entries.end());
      return block;
    }
  } // namespace

  struct ConstrainedFactorization::Data
  {
    FreeBlock                                          block;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  };

  ConstrainedFactorization::ConstrainedFactorization(
    const dealii::TrilinosWrappers::SparseMatrix &tangent,
    const dealii::AffineConstraints<double>      &constraints,
    const double                                  shift)
      : data(std::make_unique<Data>())
  {
    data->block = sparse_free_block(tangent, constraints);
    // Eigen factorizes scale A + offset I.
    data->ldlt.setShift(-shift);
    if (!data->block.global.empty())
      data->ldlt.compute(data->block.matrix);
  }

  ConstrainedFactorization::~ConstrainedFactorization() = default;

  Inertia
  ConstrainedFactorization::inertia(const double zero_ratio) const
  {
    const FreeBlock &block = data->block;
    Inertia          result;
    if (block.global.empty())
      return result;
    if (data->ldlt.info() != Eigen::Success)
      {
        // An exactly zero pivot stops the factorization, wherever it is.
        result.zero          = 1;
        result.weakest_ratio = 0;
        result.weakest_dof   = dealii::numbers::invalid_unsigned_int;
        return result;
      }
    // Pivot k of P K P^T belongs to the free DoF i with P(i) = k.
    const Eigen::VectorXd &pivots = data->ldlt.vectorD();
    const auto            &order  = data->ldlt.permutationP().indices();
    for (unsigned int i = 0; i < block.global.size(); ++i)
      {
        const double pivot = pivots[order[i]];
        const double ratio = block.diagonal[i] > 0 ?
                               std::abs(pivot) / block.diagonal[i] :
                               std::abs(pivot);
        if (ratio < result.weakest_ratio)
          {
            result.weakest_ratio = ratio;
            result.weakest_dof   = block.global[i];
          }
        if (ratio < zero_ratio)
          ++result.zero;
        else if (pivot < 0)
          ++result.negative;
        else
          ++result.positive;
      }
    return result;
  }

  std::vector<double>
  ConstrainedFactorization::solve(const std::vector<double> &rhs) const
  {
    const FreeBlock    &block = data->block;
    std::vector<double> solution(rhs.size(), 0.0);
    if (block.global.empty())
      return solution;
    Eigen::VectorXd b(block.global.size());
    for (unsigned int k = 0; k < block.global.size(); ++k)
      b[k] = rhs[block.global[k]];
    const Eigen::VectorXd x = data->ldlt.solve(b);
    if (data->ldlt.info() != Eigen::Success || !x.allFinite())
      throw std::runtime_error("the tangent is singular");
    for (unsigned int k = 0; k < block.global.size(); ++k)
      solution[block.global[k]] = x[k];
    return solution;
  }

  const std::vector<unsigned int> &
  ConstrainedFactorization::free_dofs() const
  {
    return data->block.global;
  }

  void
  ConstrainedFactorization::solve_free(Eigen::MatrixXd &block) const
  {
    if (data->block.global.empty())
      return;
    if (data->ldlt.info() == Eigen::Success)
      block = data->ldlt.solve(block).eval();
    if (data->ldlt.info() != Eigen::Success || !block.allFinite())
      throw std::runtime_error("the tangent is singular");
  }

  double
  ConstrainedFactorization::diagonal_scale() const
  {
    const Eigen::VectorXd &diagonal = data->block.diagonal;
    return diagonal.size() == 0 ? 0.0 : diagonal.mean();
  }

  Inertia
  tangent_inertia(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                  const dealii::AffineConstraints<double>      &constraints,
                  const double                                  zero_ratio)
  {
    return ConstrainedFactorization(tangent, constraints).inertia(zero_ratio);
  }

} // namespace rodnet
