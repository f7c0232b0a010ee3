#include <core/element_family.h>
#include <core/internal_variables.h>

namespace rodnet
{
  InternalVariables::InternalVariables(
    const std::vector<std::unique_ptr<ElementFamily>> &element_families)
  {
    unsigned int total = 0;
    for (const auto &family : element_families)
      {
        families.push_back(family.get());
        std::vector<unsigned int> starts{total};
        for (unsigned int s = 0; s < family->n_stencils(); ++s)
          starts.push_back(total += family->n_internal_variables(s));
        if (starts.back() == starts.front())
          starts.clear();
        offsets.push_back(std::move(starts));
      }
    if (total > 0)
      values.assign(total, 0.0);
  }
} // namespace rodnet
