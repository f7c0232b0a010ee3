#include <io/entry_numbers.h>
#include <materials/input_limits.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    bool
    is_word_character(const char c)
    {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    }

    std::string
    lower_case(std::string word)
    {
      std::transform(word.begin(), word.end(), word.begin(), [](char c) {
        return std::tolower(static_cast<unsigned char>(c));
      });
      return word;
    }

    /// Throws naming @p path unless every number in @p value is finite and
    /// within the limit.
    void
    check_value(const std::string &path, const std::string &value)
    {
      const std::string where =
        "entry \"" + path + "\": in \"" + value + "\", ";
      std::size_t i = 0;
      while (i < value.size())
        {
          const char c = value[i];
          // A word: a name (vertex, probe, function) or one of the
          // spellings of a non-finite number that strtod would accept.
          if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
            {
              std::size_t end = i;
              while (end < value.size() && is_word_character(value[end]))
                ++end;
              const std::string word = lower_case(value.substr(i, end - i));
              if (word == "nan" || word == "inf" || word == "infinity")
                throw std::invalid_argument(
                  where + "\"" + value.substr(i, end - i) +
                  "\" is not a finite number; every number of a scene must "
                  "be finite");
              i = end;
              continue;
            }
          const bool starts_number =
            std::isdigit(static_cast<unsigned char>(c)) ||
            (c == '.' && i + 1 < value.size() &&
             std::isdigit(static_cast<unsigned char>(value[i + 1])));
          if (!starts_number)
            {
              ++i;
              continue;
            }
          const char *begin        = value.c_str() + i;
          char       *end          = nullptr;
          errno                    = 0;
          const double      number = std::strtod(begin, &end);
          const std::string text(begin, static_cast<const char *>(end));
          // ERANGE with a tiny result is an underflow to (nearly) zero,
          // which is harmless; with a huge one the number overflows.
          if ((errno == ERANGE && std::abs(number) > 1) ||
              !std::isfinite(number))
            throw std::invalid_argument(where + text +
                                        " is beyond the range of a double "
                                        "(1.8e308)");
          static_assert(max_input_magnitude == 1e100, "the message says");
          if (std::abs(number) > max_input_magnitude)
            throw std::invalid_argument(
              where + text +
              " exceeds 1e100 in magnitude, the largest number rodnet "
              "accepts (no rod quantity in SI units comes near it)");
          i += end - begin;
        }
    }
  } // namespace

  void
  check_entry_numbers(const EntryNode             &tree,
                      const std::set<std::string> &exempt)
  {
    for_each_entry(tree, [&](const std::string &path, const EntryNode &entry) {
      if (exempt.count(path) == 0)
        check_value(path, entry.value);
    });
  }
} // namespace rodnet
