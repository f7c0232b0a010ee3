// The RodModel's side of history-dependent materials and of the state a
// solver advances: the time step of the incremental update, the commit of
// internal variables after a converged step, and taking and installing a
// ModelState.
#include <core/rod_model.h>
#include <elements/stretch_kernel.h>

#include <array>

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
    using Owner = InternalVariables::Owner;
    // The material must not write into the values it reads: update through
    // a scratch block (no material has more than a few variables).
    std::array<double, 16> updated;
    const auto commit = [&](const Owner owner, const unsigned int i) {
      double *block = history.block(owner, i);
      std::copy(updated.begin(),
                updated.begin() + history.size(owner, i),
                block);
    };
    const auto update_bending = [&](const Owner        owner,
                                    const unsigned int i,
                                    const Vector3     &kappa,
                                    const unsigned int rod,
                                    const double       voronoi_length) {
      if (history.size(owner, i) == 0)
        return;
      AssertThrow(history.size(owner, i) <= updated.size(),
                  dealii::ExcMessage("too many internal variables"));
      materials[rod]->hinge_increment(kappa,
                                      voronoi_length,
                                      history.block(owner, i),
                                      step_length,
                                      updated.data());
      commit(owner, i);
    };

    const auto &hinges = layout_->hinges();
    for (unsigned int h = 0; h < hinges.size(); ++h)
      update_bending(Owner::hinge,
                     h,
                     kernels[hinges[h].rod]->strains(
                       configuration_->hinge_dofs(u, hinges[h]),
                       configuration_->hinge_reference(h)) -
                       configuration_->natural_strains(h),
                     hinges[h].rod,
                     configuration_->voronoi_length(h));

    const auto &junctions = layout_->junctions();
    for (unsigned int e = 0; e < junctions.size(); ++e)
      update_bending(Owner::junction_element,
                     e,
                     junction_kernels[junctions[e].rod]->strains(
                       configuration_->junction_dofs(u, junctions[e]),
                       configuration_->junction_reference(e)),
                     junctions[e].rod,
                     configuration_->junction_voronoi_length(e));

    const auto   &segments = layout_->segments();
    StretchStrain stretch;
    for (unsigned int s = 0; s < segments.size(); ++s)
      {
        if (history.size(Owner::segment, s) == 0)
          continue;
        AssertThrow(history.size(Owner::segment, s) <= updated.size(),
                    dealii::ExcMessage("too many internal variables"));
        const double l0 = configuration_->rest_length(segments[s].cell);
        evaluate_stretch(configuration_->segment_dofs(u, segments[s]),
                         l0,
                         stretch,
                         false);
        materials[segments[s].rod]->segment_increment(
          stretch.strain,
          l0,
          history.block(Owner::segment, s),
          step_length,
          updated.data());
        commit(Owner::segment, s);
      }
  }
} // namespace rodnet
