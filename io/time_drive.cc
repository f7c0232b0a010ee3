#include <io/parsed_function.h>
#include <io/scene_entries.h>
#include <io/time_drive.h>

#include <cmath>
#include <stdexcept>

namespace rodnet
{
  TimeFunction
  read_in_time(std::vector<std::string> &words,
               const std::string        &entry,
               const std::string        &context)
  {
    for (std::size_t i = 0; i + 1 < words.size(); ++i)
      if (words[i] == "in" && words[i + 1] == "time")
        {
          std::string expression;
          for (std::size_t k = i + 2; k < words.size(); ++k)
            expression += (expression.empty() ? "" : " ") + words[k];
          if (expression.empty())
            throw std::invalid_argument(
              context + "give the function of time after \"in time\", e.g. "
                        "\"in time 1 - exp(-t/2)\"");
          words.resize(i);
          const auto parsed =
            parse_function<1>({expression}, expression, "t", entry);
          auto f = std::make_shared<const std::function<double(double)>>(
            [parsed, context](const double t) {
              const double value = parsed->value(dealii::Point<1>(t));
              if (!std::isfinite(value))
                throw std::invalid_argument(
                  context + "the function of time is " +
                  scene_entries::number(value) +
                  " at t = " + scene_entries::number(t) + " s");
              return value;
            });
          return {expression, f};
        }
    return {};
  }
} // namespace rodnet
