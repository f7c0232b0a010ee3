#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <materials/cross_section.h>
#include <materials/input_limits.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rodnet
{
  namespace internal
  {
    std::string
    entry_message(const std::string &context,
                  const std::string &entry,
                  const std::string &requirement,
                  const double       value)
    {
      std::ostringstream text;
      text << context << ": entry \"" << entry << "\" " << requirement
           << ", got " << value;
      return text.str();
    }


    void
    check_positive_entry(const std::string &context,
                         const std::string &entry,
                         const double       value)
    {
      static_assert(max_input_magnitude == 1e100, "the message says");
      // AssertThrow builds its exception only on failure.
      AssertThrow(value > 0. && value <= max_input_magnitude,
                  dealii::ExcMessage(
                    entry_message(context,
                                  entry,
                                  "must be positive and at most 1e100",
                                  value)));
    }

    void
    check_derived_value(const std::string &context,
                        const std::string &inputs,
                        const std::string &name,
                        const double       value)
    {
      std::ostringstream text;
      text << context << ": " << name << " = " << value << " from " << inputs
           << " is beyond 1e100; give them in SI units (Pa, m)";
      AssertThrow(std::abs(value) <= max_input_magnitude,
                  dealii::ExcMessage(text.str()));
    }
  } // namespace internal

  namespace
  {
    /// @p section, after checking that @p inputs did not make any of its
    /// constants overflow (a radius of 1e90 m has I = inf).
    CrossSection
    checked(const CrossSection &section,
            const std::string  &context,
            const std::string  &inputs)
    {
      internal::check_derived_value(context, inputs, "the area", section.area);
      internal::check_derived_value(context, inputs, "I1", section.I1);
      internal::check_derived_value(context, inputs, "I2", section.I2);
      internal::check_derived_value(context, inputs, "J", section.J);
      return section;
    }
  } // namespace


  CrossSection
  circle_section(const double radius)
  {
    internal::check_positive_entry("circle cross section", "Radius", radius);
    const double r2 = radius * radius;
    const double pi = dealii::numbers::PI;
    return checked(
      {pi * r2, pi * r2 * r2 / 4., pi * r2 * r2 / 4., pi * r2 * r2 / 2.},
      "circle cross section",
      "\"Radius\"");
  }


  CrossSection
  rectangle_section(const double width, const double height)
  {
    internal::check_positive_entry("rectangle cross section", "Width", width);
    internal::check_positive_entry("rectangle cross section", "Height", height);

    const double a  = std::max(width, height);
    const double b  = std::min(width, height);
    const double pi = dealii::numbers::PI;

    // Saint-Venant's series. Its terms fall off like 1/n^5 (tanh -> 1), so
    // stopping once 1/n^5 < 1e-17 leaves a tail below double round-off.
    double sum = 0.;
    for (unsigned int n = 1; 1. / std::pow(n, 5) > 1e-17; n += 2)
      sum += std::tanh(n * pi * a / (2. * b)) / std::pow(n, 5);
    const double J =
      a * b * b * b / 3. * (1. - 192. / std::pow(pi, 5) * (b / a) * sum);

    return checked({width * height,
                    width * height * height * height / 12.,
                    height * width * width * width / 12.,
                    J},
                   "rectangle cross section",
                   "\"Width\" and \"Height\"");
  }


  CrossSection
  explicit_section(const double area,
                   const double I1,
                   const double I2,
                   const double J)
  {
    const std::string context = "explicit cross section";
    internal::check_positive_entry(context, "Area", area);
    internal::check_positive_entry(context, "I1", I1);
    internal::check_positive_entry(context, "I2", I2);
    internal::check_positive_entry(context, "J", J);
    return {area, I1, I2, J};
  }


  void
  CrossSectionParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Selection;

    prm.declare_entry("Cross section",
                      "circle",
                      Selection("circle|rectangle|explicit"),
                      "Shape of the cross-section, used when \"Stiffness "
                      "input\" is \"section\": circle (reads Radius), "
                      "rectangle (reads Width, Height) or explicit (reads "
                      "Area, I1, I2, J).");
    prm.declare_entry("Radius",
                      "0",
                      Double(0),
                      "Radius of a circular cross-section (m). Required for "
                      "\"circle\"; 0 means unset and is rejected.");
    prm.declare_entry("Width",
                      "0",
                      Double(0),
                      "Extent of a rectangular cross-section along the "
                      "director d1 (m), so that I2 = Height Width^3/12. "
                      "Required for \"rectangle\".");
    prm.declare_entry("Height",
                      "0",
                      Double(0),
                      "Extent of a rectangular cross-section along the "
                      "director d2 (m), so that I1 = Width Height^3/12. "
                      "Required for \"rectangle\".");
    prm.declare_entry("Area",
                      "0",
                      Double(0),
                      "Cross-sectional area A (m^2). Required for "
                      "\"explicit\".");
    prm.declare_entry("I1",
                      "0",
                      Double(0),
                      "Second moment of area for bending about d1, "
                      "int y2^2 dA with y2 along d2 (m^4). Required for "
                      "\"explicit\".");
    prm.declare_entry("I2",
                      "0",
                      Double(0),
                      "Second moment of area for bending about d2, "
                      "int y1^2 dA with y1 along d1 (m^4). Required for "
                      "\"explicit\".");
    prm.declare_entry("J",
                      "0",
                      Double(0),
                      "Torsion constant (m^4), torque = G J twist rate. "
                      "Required for \"explicit\".");
  }


  CrossSection
  CrossSectionParameters::parse_parameters(const dealii::ParameterHandler &prm)
  {
    const std::string shape = prm.get("Cross section");
    if (shape == "circle")
      return circle_section(prm.get_double("Radius"));
    if (shape == "rectangle")
      return rectangle_section(prm.get_double("Width"),
                               prm.get_double("Height"));
    Assert(shape == "explicit", dealii::ExcInternalError());
    return explicit_section(prm.get_double("Area"),
                            prm.get_double("I1"),
                            prm.get_double("I2"),
                            prm.get_double("J"));
  }
} // namespace rodnet
