#ifndef RODNET_SOLVERS_NEWTON_PHASE_TIMED_FACTORIZATION_H
#define RODNET_SOLVERS_NEWTON_PHASE_TIMED_FACTORIZATION_H

#include <solvers/newton/tangent_factorization.h>

#include <memory>

namespace rodnet
{
  /**
   * @p factorization, its factorize() charged to the numeric factorization
   * and its solves to the linear solves of base/phase_times.h: what
   * TangentFactorization::create() returns, whichever solver it made.
   */
  std::unique_ptr<TangentFactorization>
  phase_timed(std::unique_ptr<TangentFactorization> factorization);
} // namespace rodnet

#endif
