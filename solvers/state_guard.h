#ifndef RODNET_SOLVERS_STATE_GUARD_H
#define RODNET_SOLVERS_STATE_GUARD_H

#include <core/solvable_model.h>

namespace rodnet
{
  /**
   * Saves a SolvableModel's ModelState on construction and installs it again on
   * destruction, unless keep() was called: a trial (a step attempt, a
   * branch-switch search, a critical-load bisection) that fails or throws
   * leaves the model's reference configuration, internal variables and
   * time step as they were before it, never half advanced.
   */
  class StateGuard
  {
  public:
    explicit StateGuard(SolvableModel &model)
        : model(model)
        , saved(model.state())
    {}

    StateGuard(const StateGuard &) = delete;
    StateGuard &
    operator=(const StateGuard &) = delete;

    ~StateGuard()
    {
      if (!kept)
        model.set_state(saved);
    }

    /// The model's state now stays, on destruction as well.
    void
    keep()
    {
      kept = true;
    }

    /// The state saved on construction.
    const ModelState &
    saved_state() const
    {
      return saved;
    }

  private:
    SolvableModel   &model;
    const ModelState saved;
    bool             kept = false;
  };
} // namespace rodnet

#endif
