#include <deal.II/base/utilities.h>

#include <io/parsed_function.h>
#include <io/scene_entries.h>
#include <io/time_drive.h>

#include <cmath>
#include <regex>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// The index of the words "in time" in @p words; words.size() if they
    /// are not there.
    std::size_t
    in_time_position(const std::vector<std::string> &words)
    {
      for (std::size_t i = 0; i + 1 < words.size(); ++i)
        if (words[i] == "in" && words[i + 1] == "time")
          return i;
      return words.size();
    }
  } // namespace

  bool
  follows_time_function(const std::string &text)
  {
    return in_time_offset(text) != std::string::npos;
  }


  std::size_t
  in_time_offset(const std::string &text)
  {
    static const std::regex words(R"((^|\s)in\s+time(\s|$))");
    std::smatch             match;
    if (!std::regex_search(text, match, words))
      return std::string::npos;
    return match.position(0) + match.length(1);
  }


  TimeFunction
  read_in_time(std::vector<std::string> &words,
               const std::string        &entry,
               const std::string        &context)
  {
    const std::size_t i = in_time_position(words);
    if (i == words.size())
      return {};
    std::string expression;
    for (std::size_t k = i + 2; k < words.size(); ++k)
      expression += (expression.empty() ? "" : " ") + words[k];
    if (expression.empty())
      throw std::invalid_argument(
        context + "give the function of time after \"in time\", e.g. "
                  "\"in time 1 - exp(-t/2)\"");
    words.resize(i);
    const auto parsed = parse_function<1>({expression}, expression, "t", entry);
    auto       f      = std::make_shared<const std::function<double(double)>>(
      [parsed, context](const double t) {
        const double value = parsed->value(dealii::Point<1>(t));
        if (!std::isfinite(value))
          throw std::invalid_argument(context + "the function of time is " +
                                      scene_entries::number(value) +
                                      " at t = " + scene_entries::number(t) +
                                      " s");
        return value;
      });
    return {expression, f};
  }
} // namespace rodnet
