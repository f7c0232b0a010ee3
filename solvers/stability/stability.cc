#include <base/phase_times.h>
#include <solvers/stability/stability.h>

#include <Eigen/SparseCholesky>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_LocalMap.h>
#include <algorithm>
#include <stdexcept>

namespace rodnet
{
  using dealii::types::global_dof_index;

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
      /// Per free DoF: whether it is a multiplier.
      std::vector<bool> multiplier;
      /// The free DoFs that are not multipliers (the eigen-space): their
      /// places in global, and their global indices.
      std::vector<unsigned int> space;
      std::vector<unsigned int> space_global;
    };
  } // namespace internal

  namespace
  {
    using internal::FreeBlock;

    /**
     * Size of the regularization of a multiplier row against its largest
     * entry a (see ConstrainedFactorization): -c a on its diagonal and the
     * penalty (1 / (c a)) g g^T of its row g on the other DoFs. As a
     * penalty it is a stretching rigidity EI / (c l^2) at the scale of
     * InextensibilityFamily, which moves the lowest eigenvalues by a
     * fraction c (l / L)^2 (L the wavelength); the pivots grow by 1 / c.
     * At 1e4 segments the count is rounding either way (c = 1e-4 and 1e-2
     * alike report a false bifurcation of the elastica at 0.28 P_cr, the
     * extensible rod of EA = 1e7 one at 0.69 P_cr: a tangent of condition
     * ~N^4, doc/inextensible_rods.md); 1e-2 keeps the growth small.
     */
    constexpr double multiplier_regularization = 1e-2;

    /**
     * Numbers the DoFs (@p n_dofs of them) that @p constraints leave
     * free: block.global, block.multiplier (the @p multipliers marked) and
     * the eigen-space of @p block. Returns per DoF its free index, -1 for
     * a constrained DoF.
     */
    std::vector<int>
    number_free_dofs(const unsigned int                       n_dofs,
                     const dealii::AffineConstraints<double> &constraints,
                     const std::vector<global_dof_index>     &multipliers,
                     FreeBlock                               &block)
    {
      std::vector<bool> is_multiplier(n_dofs, false);
      for (const global_dof_index d : multipliers)
        is_multiplier[d] = true;
      std::vector<int> free_index(n_dofs, -1);
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (!constraints.is_constrained(i))
          {
            free_index[i] = block.global.size();
            block.multiplier.push_back(is_multiplier[i]);
            if (!is_multiplier[i])
              {
                block.space.push_back(block.global.size());
                block.space_global.push_back(i);
              }
            block.global.push_back(i);
          }
      return free_index;
    }

    /**
     * The regularized diagonal of the multiplier row @p k, whose
     * off-diagonal entries @p row are its constraint's gradient g, and the
     * penalty g g^T (lower triangle) on the other DoFs, appended to
     * @p entries; the row's magnitude in block.diagonal.
     */
    void
    regularize_multiplier_row(const unsigned int                         k,
                              const std::vector<std::pair<int, double>> &row,
                              FreeBlock                                 &block,
                              std::vector<Eigen::Triplet<double>> &entries)
    {
      // K_reg = [H + rho G^T G, G^T; G, -I / rho] has the inertia of
      // H + 2 rho G^T G plus one negative pivot per multiplier, in any
      // elimination order.
      double largest = 0;
      for (const auto &[column, value] : row)
        largest = std::max(largest, std::abs(value));
      const double c = multiplier_regularization;
      entries.emplace_back(k, k, largest > 0 ? -c * largest : -1.0);
      block.diagonal[k] = largest > 0 ? c * largest : 1.0;
      for (const auto &[i, gi] : row)
        for (const auto &[j, gj] : row)
          if (j <= i)
            entries.emplace_back(i, j, gi * gj / (c * largest));
    }

    /**
     * The free block of @p tangent (sparse_free_block()), its diagonal
     * shifted by -@p shift, with the multiplier rows regularized.
     */
    FreeBlock
    sparse_free_block(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                      const dealii::AffineConstraints<double>      &constraints,
                      const std::vector<global_dof_index>          &multipliers,
                      const double                                  shift)
    {
      FreeBlock              block;
      const std::vector<int> free_index =
        number_free_dofs(tangent.m(), constraints, multipliers, block);
      const unsigned int                  n = block.global.size();
      std::vector<Eigen::Triplet<double>> entries;
      block.diagonal = Eigen::VectorXd::Zero(n);
      // Epetra's row views: deal.II's entry iterators cost more than the
      // factorization on large tangents.
      std::unique_ptr<Epetra_CrsMatrix>   gathered;
      const Epetra_CrsMatrix             &matrix = every_row(tangent, gathered);
      std::vector<std::pair<int, double>> row;
      for (unsigned int k = 0; k < n; ++k)
        {
          int     length;
          double *values;
          int    *columns;
          matrix.ExtractMyRowView(matrix.LRID(int(block.global[k])),
                                  length,
                                  values,
                                  columns);
          row.clear();
          for (int e = 0; e < length; ++e)
            {
              const int column = free_index[matrix.GCID(columns[e])];
              if (column == int(k))
                block.diagonal[k] = std::abs(values[e]);
              if (column >= 0 && column <= int(k))
                entries.emplace_back(k, column, values[e]);
              if (column >= 0 && column != int(k) && values[e] != 0)
                row.emplace_back(column, values[e]);
            }
          if (block.multiplier[k])
            regularize_multiplier_row(k, row, block, entries);
          else
            entries.emplace_back(k, k, -shift);
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
    unsigned int                                       n_multipliers = 0;
  };

  ConstrainedFactorization::ConstrainedFactorization(
    const dealii::TrilinosWrappers::SparseMatrix &tangent,
    const dealii::AffineConstraints<double>      &constraints,
    const double                                  shift,
    const std::vector<global_dof_index>          &multipliers)
      : data(std::make_unique<Data>())
  {
    const phase_times::Scope phase(phase_times::Phase::numeric_factorization);
    data->block = sparse_free_block(tangent, constraints, multipliers, shift);
    data->n_multipliers = data->block.global.size() - data->block.space.size();
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
    // One negative pivot per multiplier (sparse_free_block()): the rest
    // counts the eigenvalues on the constraint manifold.
    result.negative -= std::min(result.negative, data->n_multipliers);
    return result;
  }

  bool
  ConstrainedFactorization::positive_definite() const
  {
    const Inertia signs = inertia(0.0);
    return signs.negative == 0 && signs.zero == 0;
  }

  std::vector<double>
  ConstrainedFactorization::solve(const std::vector<double> &rhs) const
  {
    const FreeBlock    &block = data->block;
    std::vector<double> solution(rhs.size(), 0.0);
    if (block.space.empty())
      return solution;
    Eigen::MatrixXd b(block.space.size(), 1);
    for (unsigned int k = 0; k < block.space.size(); ++k)
      b(k, 0) = rhs[block.space_global[k]];
    solve_free(b);
    for (unsigned int k = 0; k < block.space.size(); ++k)
      solution[block.space_global[k]] = b(k, 0);
    return solution;
  }

  const std::vector<unsigned int> &
  ConstrainedFactorization::free_dofs() const
  {
    return data->block.space_global;
  }

  void
  ConstrainedFactorization::solve_free(Eigen::MatrixXd &block) const
  {
    const FreeBlock &free = data->block;
    if (free.space.empty())
      return;
    if (data->n_multipliers == 0)
      {
        if (data->ldlt.info() == Eigen::Success)
          block = data->ldlt.solve(block).eval();
      }
    else if (data->ldlt.info() == Eigen::Success)
      {
        // Zero right-hand sides at the multipliers, and only the other
        // rows of the solution: the inverse of the condensed operator.
        Eigen::MatrixXd full =
          Eigen::MatrixXd::Zero(free.global.size(), block.cols());
        for (unsigned int k = 0; k < free.space.size(); ++k)
          full.row(free.space[k]) = block.row(k);
        full = data->ldlt.solve(full).eval();
        for (unsigned int k = 0; k < free.space.size(); ++k)
          block.row(k) = full.row(free.space[k]);
      }
    if (data->ldlt.info() != Eigen::Success || !block.allFinite())
      throw std::runtime_error("the tangent is singular");
  }

  double
  ConstrainedFactorization::diagonal_scale() const
  {
    const FreeBlock &block = data->block;
    double           sum   = 0;
    for (const unsigned int k : block.space)
      sum += block.diagonal[k];
    return block.space.empty() ? 0.0 : sum / block.space.size();
  }

  const Epetra_CrsMatrix &
  every_row(const dealii::TrilinosWrappers::SparseMatrix &tangent,
            std::unique_ptr<Epetra_CrsMatrix>            &gathered)
  {
    const Epetra_CrsMatrix &matrix = tangent.trilinos_matrix();
    if (matrix.RowMap().NumMyElements() == matrix.RowMap().NumGlobalElements())
      return matrix;
    const Epetra_LocalMap every(matrix.NumGlobalRows(), 0, matrix.Comm());
    const Epetra_Import   import(every, matrix.RowMap());
    gathered = std::make_unique<Epetra_CrsMatrix>(Copy, every, 0);
    gathered->Import(matrix, import, Insert);
    gathered->FillComplete();
    return *gathered;
  }


  Inertia
  tangent_inertia(const dealii::TrilinosWrappers::SparseMatrix &tangent,
                  const dealii::AffineConstraints<double>      &constraints,
                  const std::vector<global_dof_index>          &multipliers,
                  const double                                  zero_ratio)
  {
    return ConstrainedFactorization(tangent, constraints, 0.0, multipliers)
      .inertia(zero_ratio);
  }

} // namespace rodnet
