#include <core/internal_variables.h>

namespace rodnet
{
  InternalVariables::InternalVariables(
    const std::vector<std::vector<unsigned int>> &sizes)
  {
    unsigned int total = 0;
    for (const auto &owner_sizes : sizes)
      {
        std::vector<unsigned int> starts{total};
        for (const unsigned int n : owner_sizes)
          starts.push_back(total += n);
        offsets.push_back(std::move(starts));
      }
    if (total > 0)
      values.assign(total, 0.0);
  }
} // namespace rodnet
