#ifndef RODNET_BASE_NEAREST_NAMES_H
#define RODNET_BASE_NEAREST_NAMES_H

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * The @p n names of @p names nearest to @p name, for the message that
   * refuses an unknown name: by edit distance (the insertions, deletions
   * and substitutions of characters that turn one into the other), ties in
   * the order of @p names. All of them where there are no more than @p n.
   */
  std::vector<std::string>
  nearest_names(const std::vector<std::string> &names,
                const std::string              &name,
                unsigned int                    n);

  /// @p names quoted and separated by commas: "a", "b", "c".
  std::string
  quoted_list(const std::vector<std::string> &names);
} // namespace rodnet

#endif
