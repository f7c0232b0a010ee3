#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <materials/cross_section.h>
#include <materials/ribbon_constants.h>

#include <sstream>

namespace rodnet
{
  void
  declare_ribbon_constants(dealii::ParameterHandler &prm,
                           const std::string        &poisson_help,
                           const std::string        &width_help)
  {
    using dealii::Patterns::Double;
    prm.declare_entry("Young's modulus",
                      "0",
                      Double(0),
                      "Young's modulus Y (Pa); 0 means unset and is "
                      "rejected.");
    prm.declare_entry("Poisson's ratio",
                      "0.5",
                      Double(-1, 0.5),
                      "Poisson's ratio nu (-), in (-1, 0.5]: " + poisson_help);
    prm.declare_entry("Width", "0", Double(0), width_help + " Required.");
    prm.declare_entry("Thickness",
                      "0",
                      Double(0),
                      "Thickness h along d2 (m), less than the width. "
                      "Required.");
  }


  RibbonConstants
  parse_ribbon_constants(dealii::ParameterHandler &prm)
  {
    return {prm.get_double("Young's modulus"),
            prm.get_double("Poisson's ratio"),
            prm.get_double("Width"),
            prm.get_double("Thickness")};
  }


  void
  check_ribbon_constants(const std::string     &context,
                         const RibbonConstants &constants)
  {
    internal::check_positive_entry(context,
                                   "Young's modulus",
                                   constants.young_modulus);
    internal::check_positive_entry(context, "Width", constants.width);
    internal::check_positive_entry(context, "Thickness", constants.thickness);
    // The models are those of thin strips; a section thicker than wide
    // would also make the "soft" bending the stiff one.
    std::ostringstream requirement;
    requirement << "must be less than \"Width\" = " << constants.width
                << " (the model is that of a thin ribbon)";
    AssertThrow(constants.thickness < constants.width,
                dealii::ExcMessage(
                  internal::entry_message(context,
                                          "Thickness",
                                          requirement.str(),
                                          constants.thickness)));
    const double nu = constants.poisson_ratio;
    AssertThrow(nu > -1 && nu <= 0.5,
                dealii::ExcMessage(
                  internal::entry_message(context,
                                          "Poisson's ratio",
                                          "must lie in (-1, 0.5]",
                                          nu)));
  }
} // namespace rodnet
