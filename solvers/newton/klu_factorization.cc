#include <solvers/newton/epetra_entries.h>
#include <solvers/newton/klu_factorization.h>
#include <solvers/newton/saddle_point_order.h>

#include <algorithm>
#include <klu.h>
#include <stdexcept>
#include <vector>

namespace rodnet
{
  namespace
  {
    using VectorType = TangentFactorization::VectorType;
    using MatrixType = TangentFactorization::MatrixType;

    /// KLU's pivot tolerance (see make_klu_factorization()): a diagonal
    /// entry at least this fraction of its column's largest, rows scaled by
    /// their largest entry, is the pivot.
    constexpr double diagonal_pivot_tolerance = 1e-8;

    /// KLU's pivot tolerance on a matrix with zero diagonal entries, ordered
    /// by saddle_point_order(), where a solve is refined once (see
    /// SuiteSparseKlu::solve()): there the rows eliminated before a
    /// multiplier include the directions only its constraint stiffens,
    /// whose diagonal may be tiny, and a pivot of 1e-8 of its column grew
    /// the entries by 3e11 and left 2e-5 of the right-hand side in a solve
    /// (the pop-up of Figs. 9-10, 3276 DoFs). KLU's default, 1e-3, left
    /// 9e-12 there (3e-12 refined) and kept the fill within 1.2 times the
    /// order's; 0.1 filled 1.7 times the order's on an inextensible lattice
    /// (doc/performance.md, "Figs. 9-10").
    constexpr double saddle_point_pivot_tolerance = 1e-3;

    /**
     * KLU on the compressed rows of the tangent, read as the compressed
     * columns of its transpose: KLU factorizes K^T and solves K x = b by
     * its transposed solve.
     */
    class SuiteSparseKlu : public TangentFactorization
    {
    public:
      explicit SuiteSparseKlu(const MatrixType &matrix)
          : matrix(matrix)
      {
        const Epetra_CrsMatrix &m = matrix.trilinos_matrix();
        offsets.assign(m.NumMyRows() + 1, 0);
        for_each_entry(m, [&](const int row, const int column, double) {
          ++offsets[row + 1];
          columns.push_back(column);
        });
        for (std::size_t row = 0; row + 1 < offsets.size(); ++row)
          offsets[row + 1] += offsets[row];
        values.resize(columns.size());
        klu_defaults(&common);
        common.tol   = diagonal_pivot_tolerance;
        common.scale = 2; // rows by their largest entry, KLU's default
      }

      ~SuiteSparseKlu() override
      {
        klu_free_numeric(&numeric, &common);
        klu_free_symbolic(&symbolic, &common);
      }

      void
      factorize() override
      {
        if (std::size_t(matrix.trilinos_matrix().NumMyNonzeros()) !=
            values.size())
          throw std::logic_error("the tangent's pattern changed after KLU's "
                                 "analysis of it");
        std::size_t k = 0;
        for_each_entry(matrix.trilinos_matrix(),
                       [&](int, int, const double value) {
                         values[k++] = value;
                       });
        if (symbolic == nullptr)
          analyse();
        klu_free_numeric(&numeric, &common);
        numeric = klu_factor(offsets.data(),
                             columns.data(),
                             values.data(),
                             symbolic,
                             &common);
        if (numeric == nullptr)
          throw SingularTangent("the tangent is singular (KLU found no pivot)");
      }

      using TangentFactorization::solve;

      void
      solve(const VectorType &b, VectorType &x) override
      {
        if (saddle_point) // b may be x: kept for refine()
          rhs.assign(b.trilinos_vector()[0], b.trilinos_vector()[0] + n());
        x          = b;
        double *xs = x.trilinos_vector()[0];
        if (klu_tsolve(symbolic, numeric, n(), 1, xs, &common) != 1)
          throw std::runtime_error("KLU's solve failed");
        if (saddle_point)
          refine(xs);
      }

      /// KLU's solve of both columns at once: its arithmetic on each is
      /// that of a one-column solve, in one pass over the factors.
      void
      solve(const VectorType &b,
            VectorType       &x,
            const VectorType &c,
            VectorType       &y) override
      {
        if (saddle_point)
          return TangentFactorization::solve(b, x, c, y);
        const double *columns_in[] = {b.trilinos_vector()[0],
                                      c.trilinos_vector()[0]};
        pair.resize(2 * std::size_t(n()));
        for (unsigned int j = 0; j < 2; ++j)
          std::copy(columns_in[j], columns_in[j] + n(), pair.data() + j * n());
        if (klu_tsolve(symbolic, numeric, n(), 2, pair.data(), &common) != 1)
          throw std::runtime_error("KLU's solve failed");
        x                     = b;
        y                     = c;
        double *columns_out[] = {x.trilinos_vector()[0],
                                 y.trilinos_vector()[0]};
        for (unsigned int j = 0; j < 2; ++j)
          std::copy(pair.data() + j * n(),
                    pair.data() + (j + 1) * n(),
                    columns_out[j]);
      }

      std::string
      name() const override
      {
        return "klu";
      }

      double
      factor_entries() const override
      {
        return numeric == nullptr ?
                 0.0 :
                 double(numeric->lnz) + numeric->unz + numeric->nzoff;
      }

    private:
      /**
       * KLU's analysis of the pattern, on the first values: KLU's own order
       * (make_klu_factorization()) where no diagonal entry is zero, else
       * saddle_point_order(), which puts the zero-diagonal rows (the
       * multipliers) after the rows they couple, partial pivoting with
       * saddle_point_pivot_tolerance and refined solves.
       */
      void
      analyse()
      {
        std::vector<bool> zero_diagonal(n(), true);
        for (int row = 0; row < n(); ++row)
          for (int k = offsets[row]; k < offsets[row + 1]; ++k)
            if (columns[k] == row && values[k] != 0.0)
              zero_diagonal[row] = false;
        if (std::find(zero_diagonal.begin(), zero_diagonal.end(), true) ==
            zero_diagonal.end())
          symbolic = klu_analyze(n(), offsets.data(), columns.data(), &common);
        else
          {
            saddle_point = true;
            common.tol   = saddle_point_pivot_tolerance;
            std::vector<int> order =
              saddle_point_order(offsets, columns, zero_diagonal);
            symbolic = klu_analyze_given(n(),
                                         offsets.data(),
                                         columns.data(),
                                         order.data(),
                                         order.data(),
                                         &common);
          }
        if (symbolic == nullptr)
          throw std::runtime_error(
            "KLU could not analyse the tangent's pattern (status " +
            std::to_string(common.status) + ")");
      }

      /**
       * One step of iterative refinement of the solution @p xs of K x = rhs
       * (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed.,
       * ch. 12): x += K^-1 (rhs - K x), the residual taken with the values
       * factorized. Where partial pivoting lets the entries grow, it brings
       * the residual back to what a stable solve leaves: on the pop-up's
       * tangents at 3276 DoFs, 7.7e-8 to 8e-10 at worst.
       */
      void
      refine(double *xs)
      {
        correction.resize(n());
        for (int row = 0; row < n(); ++row)
          {
            correction[row] = rhs[row];
            for (int k = offsets[row]; k < offsets[row + 1]; ++k)
              correction[row] -= values[k] * xs[columns[k]];
          }
        if (klu_tsolve(symbolic, numeric, n(), 1, correction.data(), &common) !=
            1)
          throw std::runtime_error("KLU's solve failed");
        for (int row = 0; row < n(); ++row)
          xs[row] += correction[row];
      }

      int
      n() const
      {
        return offsets.size() - 1;
      }

      const MatrixType   &matrix;
      std::vector<int>    offsets, columns;
      std::vector<double> values;
      /// The right-hand side of solve() and the correction of refine().
      std::vector<double> rhs, correction;
      /// The two columns of the two-column solve().
      std::vector<double> pair;
      /// Whether the analysis took saddle_point_order() (analyse()).
      bool          saddle_point = false;
      klu_common    common;
      klu_symbolic *symbolic = nullptr;
      klu_numeric  *numeric  = nullptr;
    };
  } // namespace


  std::unique_ptr<TangentFactorization>
  make_klu_factorization(const TangentFactorization::MatrixType &matrix)
  {
    return std::make_unique<SuiteSparseKlu>(matrix);
  }
} // namespace rodnet
