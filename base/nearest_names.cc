#include <base/nearest_names.h>

#include <algorithm>
#include <numeric>

namespace rodnet
{
  namespace
  {
    /// Levenshtein distance of @p a and @p b, row by row of the table of
    /// the distances between their prefixes.
    std::size_t
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<std::size_t> row(b.size() + 1);
      std::iota(row.begin(), row.end(), 0);
      for (std::size_t i = 1; i <= a.size(); ++i)
        {
          std::size_t diagonal = row[0];
          row[0]               = i;
          for (std::size_t j = 1; j <= b.size(); ++j)
            {
              const std::size_t above = row[j];
              row[j]                  = std::min({row[j] + 1,
                                                  row[j - 1] + 1,
                                                  diagonal + (a[i - 1] != b[j - 1])});
              diagonal                = above;
            }
        }
      return row[b.size()];
    }
  } // namespace

  std::vector<std::string>
  nearest_names(const std::vector<std::string> &names,
                const std::string              &name,
                const unsigned int              n)
  {
    std::vector<std::pair<std::size_t, std::size_t>> distances;
    for (std::size_t i = 0; i < names.size(); ++i)
      distances.emplace_back(edit_distance(names[i], name), i);
    std::sort(distances.begin(), distances.end());
    std::vector<std::string> nearest;
    for (std::size_t k = 0; k < std::min<std::size_t>(n, distances.size()); ++k)
      nearest.push_back(names[distances[k].second]);
    return nearest;
  }

  std::string
  quoted_list(const std::vector<std::string> &names)
  {
    std::string list;
    for (const std::string &name : names)
      list += (list.empty() ? "\"" : ", \"") + name + "\"";
    return list;
  }
} // namespace rodnet
