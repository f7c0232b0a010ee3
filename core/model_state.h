#ifndef RODNET_CORE_MODEL_STATE_H
#define RODNET_CORE_MODEL_STATE_H

#include <core/configuration.h>
#include <core/internal_variables.h>

namespace rodnet
{
  /**
   * The part of a RodModel that a solver advances besides the DoF vector:
   * the reference configuration (Korner et al. 2c; reset after every
   * converged step), the committed internal variables of history materials
   * and the time step of the next assemblies. A plain value: a solver
   * keeps copies (the state before a trial step, the last stable state of a
   * critical-load bisection, the best state of a branch switch) and
   * installs one with RodModel::set_state() instead of restoring fields by
   * hand; StateGuard does so when a step throws.
   *
   * The model keeps its installed state as members and assemble() reads
   * them there: assemble's signature and cost stay what they were, and a
   * copy is made only where a solver saves a state (once per step attempt,
   * never per stencil or per Newton iteration).
   */
  struct ModelState
  {
    Configuration     configuration;
    InternalVariables committed;
    double            time_step = 0;
  };
} // namespace rodnet

#endif
