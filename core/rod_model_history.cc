// The RodModel's side of history-dependent materials and of the state a
// solver advances: the time step of the incremental update, the commit of
// internal variables after a converged step, and taking and installing a
// ModelState.
#include <core/every_entry.h>
#include <core/rod_model.h>

#include <algorithm>
#include <vector>

namespace rodnet
{
  void
  RodModel::set_time_step(const double time_step)
  {
    if (has_internal_variables())
      RodMaterial::check_time_step(time_step);
    step_length = time_step;
  }

  ModelState
  RodModel::state() const
  {
    return ModelState{*configuration_, history, step_length};
  }

  void
  RodModel::set_state(const ModelState &state)
  {
    *configuration_ = state.configuration;
    history         = state.committed;
    step_length     = state.time_step;
  }

  void
  RodModel::commit_internal_variables(const VectorType &u)
  {
    if (!has_internal_variables())
      return;
    // Every process keeps every stencil's variables (the output writes
    // them all), so it reads every entry: a replica on several processes.
    const EveryEntry   every(u);
    const StencilState state{*every,
                             *configuration_,
                             history,
                             step_length,
                             0.0};
    // A family must not write into the values it reads: it updates into
    // scratch, which is then committed.
    std::vector<double> updated;
    for (const auto &family : families)
      for (unsigned int s = 0; s < family->n_stencils(); ++s)
        {
          updated.resize(history.size(*family, s));
          if (updated.empty())
            continue;
          family->update_internal_variables(s, state, updated.data());
          std::copy(updated.begin(), updated.end(), history.block(*family, s));
        }
  }
} // namespace rodnet
