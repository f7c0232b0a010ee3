#include <deal.II/base/exceptions.h>
#include <deal.II/base/signaling_nan.h>

#include <materials/input_limits.h>
#include <materials/linear_elastic_rod.h>
#include <materials/stiffness_input.h>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace rodnet
{
  RODNET_REGISTER_MATERIAL(LinearElasticRod,
                           "linear elastic",
                           "Linear elastic Kirchhoff rod with natural "
                           "curvature, natural twist and axial eigenstrain "
                           "(Lestringant & Kochmann eqs. 16-17).")

  namespace
  {
    // Prefix of every message, so a user sees which subsection is at fault.
    constexpr char linear_elastic_context[] = "linear elastic rod";
  } // namespace


  RodStiffness
  stiffness_from_section(const double        E,
                         const double        G,
                         const CrossSection &section)
  {
    internal::check_positive_entry(linear_elastic_context,
                                   "Young's modulus",
                                   E);
    internal::check_positive_entry(linear_elastic_context, "Shear modulus", G);
    const RodStiffness stiffness = {E * section.area,
                                    E * section.I1,
                                    E * section.I2,
                                    G * section.J};
    const std::string  inputs    = "the modulus and the cross section";
    internal::check_derived_value(linear_elastic_context,
                                  inputs,
                                  "EA",
                                  stiffness.EA);
    internal::check_derived_value(linear_elastic_context,
                                  inputs,
                                  "EI1",
                                  stiffness.EI1);
    internal::check_derived_value(linear_elastic_context,
                                  inputs,
                                  "EI2",
                                  stiffness.EI2);
    internal::check_derived_value(linear_elastic_context,
                                  inputs,
                                  "GJ",
                                  stiffness.GJ);
    return stiffness;
  }


  double
  isotropic_shear_modulus(const std::string &context,
                          const double       E,
                          const double       nu)
  {
    // Isotropic elasticity needs nu > -1; the entry's pattern admits -1.
    AssertThrow(nu > -1. && nu <= 0.5,
                dealii::ExcMessage(
                  internal::entry_message(context,
                                          "Poisson's ratio",
                                          "must lie in (-1, 0.5]",
                                          nu)));
    return E / (2. * (1. + nu));
  }


  void
  declare_direct_rigidities(dealii::ParameterHandler &prm,
                            const std::string        &qualifier)
  {
    const auto help = [&qualifier](const std::string &what) {
      std::string text = qualifier + what;
      text[0]          = std::toupper(text[0]);
      return text + " Required for \"direct\".";
    };
    using dealii::Patterns::Double;
    prm.declare_entry("EA", "0", Double(0), help("axial rigidity (N)."));
    prm.declare_entry("EI1",
                      "0",
                      Double(0),
                      help("bending rigidity about d1 (N m^2)."));
    prm.declare_entry("EI2",
                      "0",
                      Double(0),
                      help("bending rigidity about d2 (N m^2)."));
    prm.declare_entry("GJ",
                      "0",
                      Double(0),
                      help("torsional rigidity (N m^2)."));
  }


  RodStiffness
  parse_direct_rigidities(dealii::ParameterHandler &prm)
  {
    return {prm.get_double("EA"),
            prm.get_double("EI1"),
            prm.get_double("EI2"),
            prm.get_double("GJ")};
  }


  LinearElasticRod::LinearElasticRod()
      : rigidities{dealii::numbers::signaling_nan<double>(),
                   dealii::numbers::signaling_nan<double>(),
                   dealii::numbers::signaling_nan<double>(),
                   dealii::numbers::signaling_nan<double>()}
  {
  }


  LinearElasticRod::LinearElasticRod(const RodStiffness    &stiffness,
                                     const RodNaturalShape &natural_shape)
      : rigidities(stiffness)
      , rest_shape(natural_shape)
  {
    internal::check_positive_entry(linear_elastic_context, "EA", stiffness.EA);
    internal::check_positive_entry(linear_elastic_context,
                                   "EI1",
                                   stiffness.EI1);
    internal::check_positive_entry(linear_elastic_context,
                                   "EI2",
                                   stiffness.EI2);
    internal::check_positive_entry(linear_elastic_context, "GJ", stiffness.GJ);

    const auto check_finite = [](const char *entry, const double value) {
      AssertThrow(std::abs(value) <= max_input_magnitude,
                  dealii::ExcMessage(
                    internal::entry_message(linear_elastic_context,
                                            entry,
                                            "must be finite and at most 1e100",
                                            value)));
    };
    check_finite("Natural curvature 1", natural_shape.curvature1);
    check_finite("Natural curvature 2", natural_shape.curvature2);
    check_finite("Natural twist", natural_shape.twist);

    // The stress-free length (1 + eps0) l0 of a segment must stay positive.
    AssertThrow(natural_shape.axial_eigenstrain > -1. &&
                  natural_shape.axial_eigenstrain <= max_input_magnitude,
                dealii::ExcMessage(
                  internal::entry_message(linear_elastic_context,
                                          "Axial eigenstrain",
                                          "must be finite and exceed -1",
                                          natural_shape.axial_eigenstrain)));
  }


  std::shared_ptr<const RodMaterial>
  LinearElasticRod::with_natural_shape_scaled(const NaturalShapeParts &parts,
                                              const double factor) const
  {
    auto        scaled = std::make_shared<LinearElasticRod>(*this);
    RodNaturalShape &shape = scaled->rest_shape;
    if (parts.curvature)
      {
        shape.curvature1 *= factor;
        shape.curvature2 *= factor;
      }
    if (parts.twist)
      shape.twist *= factor;
    if (parts.eigenstrain)
      shape.axial_eigenstrain *= factor;
    // A stress-free length (1 + eps0) l0 that is not positive has no rod.
    if (!(shape.axial_eigenstrain > -1.))
      throw std::invalid_argument(
        "the axial eigenstrain " + std::to_string(rest_shape.axial_eigenstrain) +
        " ramped by the load factor " + std::to_string(factor) +
        " is -1 or less: no rod has a stress-free length of zero or less");
    return scaled;
  }


  MaterialResponse<3>
  LinearElasticRod::hinge_energy(const Eigen::Vector3d &kappa,
                                 const double           voronoi_length) const
  {
    Assert(!std::isnan(rigidities.EI1),
           dealii::ExcMessage("LinearElasticRod used before its constants "
                              "were set by parse_parameters()"));
    Assert(voronoi_length > 0., dealii::ExcMessage("Voronoi length <= 0"));

    const Eigen::Vector3d rigidity(rigidities.EI1,
                                   rigidities.EI2,
                                   rigidities.GJ);
    const Eigen::Vector3d natural(rest_shape.curvature1,
                                  rest_shape.curvature2,
                                  rest_shape.twist);
    // kappa is integrated over the Voronoi cell: kappa / l is the strain
    // density that converges to the continuous curvature (Korner et al.
    // eq. 4.2), so the natural curvature is compared with it, not with kappa.
    const Eigen::Vector3d excess = kappa / voronoi_length - natural;

    MaterialResponse<3> response;
    response.energy =
      0.5 * voronoi_length * rigidity.dot(excess.cwiseProduct(excess));
    // The factor l of the energy cancels the 1/l of d(kappa/l)/d kappa.
    response.stress  = rigidity.cwiseProduct(excess);
    response.tangent = (rigidity / voronoi_length).asDiagonal();
    return response;
  }


  MaterialResponse<1>
  LinearElasticRod::segment_energy(const double strain,
                                   const double rest_length) const
  {
    Assert(!std::isnan(rigidities.EA),
           dealii::ExcMessage("LinearElasticRod used before its constants "
                              "were set by parse_parameters()"));
    Assert(rest_length > 0., dealii::ExcMessage("rest length <= 0"));

    // Lestringant & Kochmann eq. 17.
    const double excess = strain - rest_shape.axial_eigenstrain;

    MaterialResponse<1> response;
    response.energy     = 0.5 * rest_length * rigidities.EA * excess * excess;
    response.stress(0)  = rest_length * rigidities.EA * excess;
    response.tangent(0) = rest_length * rigidities.EA;
    return response;
  }


  void
  LinearElasticRod::declare_parameters(dealii::ParameterHandler &prm) const
  {
    using dealii::Patterns::Double;

    declare_stiffness_input(prm,
                            "How the rigidities are given: \"section\" from "
                            "Young's modulus, shear modulus (or Poisson's "
                            "ratio) and a cross-section; \"direct\" as EA, "
                            "EI1, EI2, GJ.");

    prm.declare_entry("Young's modulus",
                      "0",
                      Double(0),
                      "Young's modulus E (Pa). Required for \"section\"; 0 "
                      "means unset and is rejected.");
    prm.declare_entry("Poisson's ratio",
                      "0.5",
                      Double(-1, 0.5),
                      "Poisson's ratio nu (-), in (-1, 0.5]; used only when "
                      "\"Shear modulus\" is 0, to set G = E / (2 (1 + nu)). "
                      "The default 0.5 (incompressible, G = E/3) is "
                      "Lestringant & Kochmann's choice.");
    prm.declare_entry("Shear modulus",
                      "0",
                      Double(0),
                      "Shear modulus G (Pa); 0 computes it from \"Young's "
                      "modulus\" and \"Poisson's ratio\".");
    CrossSectionParameters::declare_parameters(prm);

    declare_direct_rigidities(prm, "");

    prm.declare_entry("Natural curvature 1",
                      "0",
                      Double(),
                      "Natural curvature about d1 (1/m), the stress-free "
                      "value of kappa_1 / l.");
    prm.declare_entry("Natural curvature 2",
                      "0",
                      Double(),
                      "Natural curvature about d2 (1/m), the stress-free "
                      "value of kappa_2 / l.");
    prm.declare_entry("Natural twist",
                      "0",
                      Double(),
                      "Natural twist rate (rad/m), the stress-free value of "
                      "kappa_3 / l.");
    prm.declare_entry("Axial eigenstrain",
                      "0",
                      Double(-1),
                      "Stress-free axial strain eps0 (-), greater than -1; "
                      "positive values make segments want to lengthen.");
  }


  void
  LinearElasticRod::parse_parameters(dealii::ParameterHandler &prm)
  {
    const StiffnessInput input = parse_stiffness_input(prm,
                                                       linear_elastic_context,
                                                       "Young's modulus",
                                                       true);
    RodNaturalShape      shape;
    shape.curvature1        = prm.get_double("Natural curvature 1");
    shape.curvature2        = prm.get_double("Natural curvature 2");
    shape.twist             = prm.get_double("Natural twist");
    shape.axial_eigenstrain = prm.get_double("Axial eigenstrain");

    // The constructor validates; assigning only afterwards leaves *this
    // untouched when an entry is rejected.
    *this         = LinearElasticRod(input.stiffness, shape);
    given_section = input.section;
  }


  std::optional<CrossSection>
  LinearElasticRod::cross_section() const
  {
    return given_section;
  }


  std::optional<RodStiffness>
  LinearElasticRod::straight_linear_elastic_stiffness() const
  {
    const RodNaturalShape &shape = rest_shape;
    if (shape.curvature1 != 0 || shape.curvature2 != 0 || shape.twist != 0 ||
        shape.axial_eigenstrain != 0)
      return std::nullopt;
    return rigidities;
  }


  const RodStiffness &
  LinearElasticRod::stiffness() const
  {
    return rigidities;
  }


  const RodNaturalShape &
  LinearElasticRod::natural_shape() const
  {
    return rest_shape;
  }
} // namespace rodnet
