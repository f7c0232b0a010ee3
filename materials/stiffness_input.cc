#include <deal.II/base/patterns.h>

#include <materials/input_limits.h>
#include <materials/linear_elastic_rod.h>
#include <materials/stiffness_input.h>

namespace rodnet
{
  void
  declare_stiffness_input(dealii::ParameterHandler &prm,
                          const std::string        &help)
  {
    prm.declare_entry("Stiffness input",
                      "section",
                      dealii::Patterns::Selection("section|direct"),
                      help);
  }

  StiffnessInput
  parse_stiffness_input(dealii::ParameterHandler &prm,
                        const std::string        &context,
                        const std::string        &modulus_entry,
                        const bool                shear_modulus_entry)
  {
    StiffnessInput input;
    if (prm.get("Stiffness input") != "section")
      {
        input.stiffness = parse_direct_rigidities(prm);
        return input;
      }
    const double E = prm.get_double(modulus_entry);
    double       G = shear_modulus_entry ? prm.get_double("Shear modulus") : 0.;
    if (G == 0.)
      G =
        isotropic_shear_modulus(context, E, prm.get_double("Poisson's ratio"));
    // Checked before the section, so a missing modulus is named first.
    internal::check_positive_entry(context, modulus_entry, E);
    input.section   = CrossSectionParameters::parse_parameters(prm);
    input.stiffness = stiffness_from_section(E, G, *input.section);
    return input;
  }
} // namespace rodnet
