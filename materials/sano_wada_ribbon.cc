#include <deal.II/base/exceptions.h>
#include <deal.II/base/signaling_nan.h>

#include <materials/cross_section.h>
#include <materials/input_limits.h>
#include <materials/linear_elastic_rod.h>
#include <materials/sano_wada_ribbon.h>

#include <cmath>
#include <sstream>

namespace rodnet
{
  RODNET_REGISTER_MATERIAL(SanoWadaRibbon,
                           "sano-wada ribbon",
                           "Extensible ribbon of Sano & Wada (Korner et al. "
                           "eq. 5.5): width along d1, soft bending about d1, "
                           "twist stiffened by a quartic term.")

  namespace
  {
    // Prefix of every message, so a user sees which subsection is at fault.
    constexpr char sano_wada_context[] = "sano-wada ribbon";

    /// Throws unless the modulus @p name = @p value derived from the
    /// entries is positive and at most max_input_magnitude (a product of
    /// admissible entries may overflow, or underflow to 0).
    void
    check_ribbon_modulus(const std::string &name, const double value)
    {
      std::ostringstream text;
      text << sano_wada_context << ": " << name << " = " << value
           << " from \"Young's modulus\", \"Width\" and \"Thickness\" must be "
              "positive and at most 1e100; give them in SI units (Pa, m)";
      AssertThrow(value > 0. && value <= max_input_magnitude,
                  dealii::ExcMessage(text.str()));
    }

    RibbonModuli
    ribbon_moduli(const RibbonConstants &c)
    {
      const double Y = c.young_modulus;
      const double w = c.width;
      const double h = c.thickness;
      // Korner et al. section 5(c); A3 = G w h^3 / 3 with the thin strip's
      // torsion constant w h^3 / 3 and G = Y / (2 (1 + nu)).
      const double G =
        isotropic_shear_modulus(sano_wada_context, Y, c.poisson_ratio);
      const double nu = c.poisson_ratio;
      return {Y * h * h * h * w / 12.,
              Y * h * w * w * w / 12.,
              G * w * h * h * h / 3.,
              (1. - nu * nu) * (w * w / h) * (w * w / h) / 60.,
              Y * w * h};
    }
  } // namespace


  SanoWadaRibbon::SanoWadaRibbon()
      : given{dealii::numbers::signaling_nan<double>(),
              dealii::numbers::signaling_nan<double>(),
              dealii::numbers::signaling_nan<double>(),
              dealii::numbers::signaling_nan<double>()}
      , derived{dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>()}
  {
  }


  SanoWadaRibbon::SanoWadaRibbon(const RibbonConstants &constants)
      : given(constants)
  {
    check_ribbon_constants(sano_wada_context, constants);
    derived = ribbon_moduli(constants);
    check_ribbon_modulus("the soft bending modulus Y h^3 w / 12",
                         derived.soft_bending);
    check_ribbon_modulus("the stiff bending modulus Y h w^3 / 12",
                         derived.stiff_bending);
    check_ribbon_modulus("the twisting modulus Y h^3 w / (6 (1 + nu))",
                         derived.twisting);
    check_ribbon_modulus("xi^2 = (1 - nu^2) w^4 / (60 h^2)",
                         derived.xi_squared);
    check_ribbon_modulus("EA = Y w h", derived.axial);
  }


  MaterialResponse<3>
  SanoWadaRibbon::hinge_energy(const Eigen::Vector3d &kappa,
                               const double           voronoi_length) const
  {
    Assert(!std::isnan(derived.soft_bending),
           dealii::ExcMessage("SanoWadaRibbon used before its constants "
                              "were set by parse_parameters()"));
    Assert(voronoi_length > 0., dealii::ExcMessage("Voronoi length <= 0"));

    const double l = voronoi_length;
    const double a = kappa(0); // soft bending, about d1 (paper's kappa_2)
    const double b = kappa(1); // stiff bending, about d2 (paper's kappa_1)
    const double t = kappa(2); // twist

    // Eq. 5.5's quartic term A2 t^4 / D with D = l^2/xi^2 + a^2 > 0, formed
    // from q = t / D and r = t^2 / D so that no power of t above 2 is
    // formed (t^4 would overflow first).
    const double D = l * l / derived.xi_squared + a * a;
    const double q = t / D;
    const double r = t * q;

    const double A1 = derived.stiff_bending;
    const double A2 = derived.soft_bending;
    const double A3 = derived.twisting;

    MaterialResponse<3> response;
    response.energy =
      (A2 * (a * a + t * t * r) + A1 * b * b + A3 * t * t) / (2. * l);
    // d(t^4/D)/da = -2 a r^2, d(t^4/D)/dt = 4 t r.
    response.stress(0) = A2 * (a - a * r * r) / l;
    response.stress(1) = A1 * b / l;
    response.stress(2) = (2. * A2 * t * r + A3 * t) / l;
    // d2(t^4/D)/da2 = t^4 (8 a^2 - 2 D) / D^3 = 2 r^2 (4 a^2 / D - 1),
    // d2(t^4/D)/da dt = -8 a r q, d2(t^4/D)/dt2 = 12 r.
    response.tangent.setZero();
    response.tangent(0, 0) = A2 * (1. + r * r * (4. * a * a / D - 1.)) / l;
    response.tangent(1, 1) = A1 / l;
    response.tangent(2, 2) = (6. * A2 * r + A3) / l;
    response.tangent(0, 2) = -4. * A2 * a * r * q / l;
    response.tangent(2, 0) = response.tangent(0, 2);
    return response;
  }


  MaterialResponse<1>
  SanoWadaRibbon::segment_energy(const double strain,
                                 const double rest_length) const
  {
    Assert(!std::isnan(derived.axial),
           dealii::ExcMessage("SanoWadaRibbon used before its constants "
                              "were set by parse_parameters()"));
    Assert(rest_length > 0., dealii::ExcMessage("rest length <= 0"));

    const double        EA = derived.axial;
    MaterialResponse<1> response;
    response.energy     = 0.5 * rest_length * EA * strain * strain;
    response.stress(0)  = rest_length * EA * strain;
    response.tangent(0) = rest_length * EA;
    return response;
  }


  void
  SanoWadaRibbon::declare_parameters(dealii::ParameterHandler &prm) const
  {
    declare_ribbon_constants(prm,
                             "twisting modulus Y h^3 w / (6 (1 + nu)), xi^2 = "
                             "(1 - nu^2) w^4 / (60 h^2).",
                             "Width w along d1 (m): soft bending Y h^3 w / 12 "
                             "about d1, stiff Y h w^3 / 12 about d2, EA = Y w "
                             "h.");
  }


  void
  SanoWadaRibbon::parse_parameters(dealii::ParameterHandler &prm)
  {
    // The constructor validates; assigning only afterwards leaves *this
    // untouched when an entry is rejected.
    *this = SanoWadaRibbon(parse_ribbon_constants(prm));
  }


  std::optional<CrossSection>
  SanoWadaRibbon::cross_section() const
  {
    return rectangle_section(given.width, given.thickness);
  }


  const RibbonConstants &
  SanoWadaRibbon::constants() const
  {
    return given;
  }


  const RibbonModuli &
  SanoWadaRibbon::moduli() const
  {
    return derived;
  }
} // namespace rodnet
