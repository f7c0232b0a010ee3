#ifndef RODNET_TESTS_COMMON_FAMILY_NAMED_H
#define RODNET_TESTS_COMMON_FAMILY_NAMED_H

// An element family of a model found by its name (ElementFamily::name()),
// as a caller reads the internal variables of its stencils.

#include <core/solvable_model.h>

#include <stdexcept>
#include <string>

namespace rodnet::testing
{
  /// The family of @p model called @p name; throws if there is none.
  inline const ElementFamily &
  family_named(const SolvableModel &model, const std::string &name)
  {
    for (const auto &family : model.element_families())
      if (family->name() == name)
        return *family;
    throw std::logic_error("no element family \"" + name + "\"");
  }
} // namespace rodnet::testing

#endif
