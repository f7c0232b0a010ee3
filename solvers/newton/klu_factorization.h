#ifndef RODNET_SOLVERS_NEWTON_KLU_FACTORIZATION_H
#define RODNET_SOLVERS_NEWTON_KLU_FACTORIZATION_H

#include <solvers/newton/tangent_factorization.h>

#include <memory>

namespace rodnet
{
  /**
   * SuiteSparse KLU (Davis & Palamadai Natarajan, ACM TOMS 37, 2010) for the
   * tangent @p matrix of one process. Its analysis, done once on the values
   * of the first factorize(), orders the matrix by KLU's block triangular
   * form and AMD on the pattern of K + K^T, an order made for diagonal
   * pivots: the fill of a welded lattice's tangent is 2.0-2.7 times its
   * entries from 1e4 to 6e5 DoFs. Where a diagonal entry is zero there (the
   * multipliers of inextensible rods) the order is saddle_point_order()'s,
   * which puts each such row after the rows it couples, with partial
   * pivoting and one step of iterative refinement: on the KKT tangents of the
   * pop-up of Figs. 9-10 at 3276 DoFs, where AMD's order filled 5 to 32 times
   * the entries, this one fills 1.7 to 2.0 times, and its solves leave less
   * of the right-hand side, but for one nearly singular tangent (condition
   * 4e17: 2.8e-5 against 1.5e-5) (doc/performance.md, "Figs. 9-10").
   *
   * The order holds only while the pivots stay on the diagonal. KLU's
   * threshold partial pivoting takes a column's diagonal entry unless it is
   * below a tolerance times the column's largest. Amesos KLU, which rodnet
   * used before (unscaled rows, KLU's tolerance 1e-3), left the diagonal
   * on the indefinite tangents of Newton's first iterates on a lattice of
   * 5.8e5 DoFs sagging under gravity: 51, 962 and 1423 off-diagonal pivots
   * at the fourth, fifth and sixth iterate, 1.2, 2.7 and 7.1 times the
   * flops of the order; the sixth factorization took 140 s against 9.5 s
   * for the first (doc/performance.md, "Newton iteration scaling"). The tangent
   * is symmetric, so its diagonal is the natural pivot: here the rows are
   * scaled by their largest entry and the tolerance is 1e-8, and the same
   * iterates had no off-diagonal pivot, the order's fill and flops, and solves
   * that left 3e-8 to 4e-8 of the right-hand side (Amesos's pivoting: 1e-9
   * to 1.4e-7), on states with residual forces of 1e8 to 5e10 N. A pivot may
   * grow the entries by at most the inverse tolerance; a zero pivot is still
   * pivoted off.
   *
   * Each factorize() reads the matrix's values; the matrix must keep its
   * pattern (TangentFactorizationCache compares it, factorize() throws
   * std::logic_error otherwise). factorize() throws std::runtime_error
   * where KLU cannot analyse the pattern.
   */
  std::unique_ptr<TangentFactorization>
  make_klu_factorization(const TangentFactorization::MatrixType &matrix);
} // namespace rodnet

#endif
