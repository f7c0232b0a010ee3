#ifndef RODNET_TESTS_COMMON_RIBBON_DOFS_H
#define RODNET_TESTS_COMMON_RIBBON_DOFS_H

// The DoFs that the developable ribbon family declares for itself, found
// from the model's declared blocks as any caller would: three per hinge of
// a developable rod (slope eta, multipliers mu_2 and mu_3), in the order of
// DofLayout::hinges().

#include <core/rod_model.h>

#include <stdexcept>

namespace rodnet::testing
{
  /// The block that family @p owner declared in @p model; throws if none.
  inline const DofBlock &
  declared_block(const RodModel &model, const std::string &owner)
  {
    for (const DofBlock &block : model.layout().declared_blocks())
      if (block.owner == owner)
        return block;
    throw std::logic_error("no block declared by \"" + owner + "\"");
  }

  /// Ribbon DoF @p c (0 eta, 1 mu_2, 2 mu_3) of hinge @p h of @p model.
  inline global_dof_index
  ribbon_dof(const RodModel &model, const unsigned int h, const unsigned int c)
  {
    const auto  &hinges = model.layout().hinges();
    unsigned int before = 0;
    for (unsigned int i = 0; i < h; ++i)
      before += model.network().rods()[hinges[i].rod].developable ? 1 : 0;
    if (!model.network().rods()[hinges[h].rod].developable)
      throw std::logic_error("hinge " + std::to_string(h) +
                             " is not one of a developable ribbon");
    return declared_block(model, "developable ribbons").first + 3 * before + c;
  }
} // namespace rodnet::testing

#endif
