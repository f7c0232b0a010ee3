#include <deal.II/base/utilities.h>

#include <io/natural_shape_ramp.h>

#include <stdexcept>

namespace rodnet
{
  namespace
  {
    [[noreturn]] void
    refuse(const std::string &word, const std::string &expected)
    {
      throw std::invalid_argument("entry \"" + natural_shape_ramp_entry +
                                  "\": \"" + word + "\" is not " + expected);
    }

    /// Sets the part @p word names in @p parts.
    void
    add_part(const std::string &word, NaturalShapeParts &parts)
    {
      if (word == "curvature")
        parts.curvature = true;
      else if (word == "twist")
        parts.twist = true;
      else if (word == "eigenstrain")
        parts.eigenstrain = true;
      else
        refuse(word,
               "a part of the natural shape (curvature, twist or "
               "eigenstrain)");
    }

    unsigned int
    rod_number(const std::string &word)
    {
      std::size_t used = 0;
      try
        {
          const long rod = std::stol(word, &used);
          if (used == word.size() && rod >= 0)
            return static_cast<unsigned int>(rod);
        }
      catch (const std::exception &)
        {
        }
      refuse(word, "a rod number");
    }
  } // namespace

  std::optional<NaturalShapeRamp>
  parse_natural_shape_ramp(const std::string &text)
  {
    const std::string trimmed = dealii::Utilities::trim(text);
    if (trimmed.empty())
      return std::nullopt;
    const std::size_t colon = trimmed.find(':');
    NaturalShapeRamp  ramp;
    for (const std::string &word :
         dealii::Utilities::split_string_list(trimmed.substr(0, colon), ','))
      add_part(word, ramp.parts);
    if (colon != std::string::npos)
      {
        for (const std::string &word :
             dealii::Utilities::split_string_list(trimmed.substr(colon + 1),
                                                  ','))
          ramp.rods.push_back(rod_number(word));
        if (ramp.rods.empty())
          refuse(trimmed, "followed by rod numbers after its ':'");
      }
    return ramp;
  }
} // namespace rodnet
