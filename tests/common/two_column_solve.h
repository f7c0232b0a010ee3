#ifndef RODNET_TESTS_TWO_COLUMN_SOLVE_H
#define RODNET_TESTS_TWO_COLUMN_SOLVE_H

#include <solvers/newton/tangent_factorization.h>

#include <gtest/gtest.h>
#include <utility>

namespace rodnet::testing
{
  /// The solutions x and y of @p solver's two-column solve of K x = @p b,
  /// K y = @p c (the last factorization), expected to equal two single
  /// solves to 1e-12 of their size: to round-off, which the tangent's
  /// condition amplifies and whose order of additions differs where the
  /// BLAS takes two columns at once (MUMPS with OpenBLAS: 1.8e-14 on a
  /// lattice's tangent on two processes, 2026-12-07).
  inline std::pair<TangentFactorization::VectorType,
                   TangentFactorization::VectorType>
  two_column_solve(TangentFactorization                   &solver,
                   const TangentFactorization::VectorType &b,
                   const TangentFactorization::VectorType &c)
  {
    TangentFactorization::VectorType x = b, y = c, x1 = b, y1 = c;
    solver.solve(b, x, c, y);
    solver.solve(b, x1);
    solver.solve(c, y1);
    x1.add(-1.0, x);
    y1.add(-1.0, y);
    EXPECT_LT(x1.l2_norm(), 1e-12 * x.l2_norm());
    EXPECT_LT(y1.l2_norm(), 1e-12 * y.l2_norm());
    return {x, y};
  }
} // namespace rodnet::testing

#endif
