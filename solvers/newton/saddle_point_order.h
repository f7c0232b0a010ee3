#ifndef RODNET_SOLVERS_NEWTON_SADDLE_POINT_ORDER_H
#define RODNET_SOLVERS_NEWTON_SADDLE_POINT_ORDER_H

#include <vector>

namespace rodnet
{
  /**
   * A fill-reducing elimination order for a matrix with zero diagonal
   * entries, such as the KKT tangent of inextensible rods (the Lagrange
   * multipliers' rows, families/inextensibility_family.h), for a sparse LU
   * (KLU, solvers/newton/klu_factorization.h).
   *
   * AMD (Amestoy, Davis & Duff 1996) on the symmetric pattern of K + K^T
   * sees a multiplier as a row of a few entries and eliminates it early,
   * before the rows it couples: its pivot is then zero, the LU has to take
   * another row, and the order's prediction of the fill no longer holds.
   * Here AMD orders only the rows with a nonzero diagonal, on the pattern
   * of K_xx + |G|^T |G| (the rows a multiplier couples made one clique, the
   * fill its elimination brings), and each zero-diagonal row follows the
   * last of the rows it couples. Its pivot is then the Schur complement
   * -G K_xx^-1 G^T of its constraint, nonzero where the constraint is
   * independent, and the row exchanges of partial pivoting stay among the
   * rows of a few neighbouring segments, near the fill of the order.
   *
   * @p offsets and @p columns are the compressed rows of the matrix's
   * pattern (n + 1 and offsets[n] entries); @p zero_diagonal marks the rows
   * whose diagonal is zero. Returns order[k], the row eliminated k-th.
   * Throws std::runtime_error where AMD fails (no memory).
   */
  std::vector<int>
  saddle_point_order(const std::vector<int>  &offsets,
                     const std::vector<int>  &columns,
                     const std::vector<bool> &zero_diagonal);
} // namespace rodnet

#endif
