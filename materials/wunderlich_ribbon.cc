#include <deal.II/base/exceptions.h>
#include <deal.II/base/signaling_nan.h>

#include <materials/cross_section.h>
#include <materials/input_limits.h>
#include <materials/wunderlich_ribbon.h>

#include <cmath>
#include <sstream>

namespace rodnet
{
  RODNET_REGISTER_MATERIAL(WunderlichRibbon,
                           "wunderlich ribbon",
                           "Inextensible developable ribbon of Wunderlich "
                           "(Korner et al. eq. 4.7): width along d1, a "
                           "generatrix slope DoF per hinge, exact "
                           "constraints.")

  namespace
  {
    constexpr char wunderlich_context[] = "wunderlich ribbon";
  } // namespace


  Eigen::Vector3d
  wunderlich_width_factor(const double x)
  {
    if (!(std::abs(x) < 1))
      {
        std::ostringstream text;
        text << "Wunderlich ribbon: eta' w / 2 = " << x
             << " is outside (-1, 1): generatrices cross within the strip";
        throw std::runtime_error(text.str());
      }
    Eigen::Vector3d g;
    if (std::abs(x) < 0.25)
      {
        // g = sum_n x^(2n) / (2n + 1); x^2 < 1/16, so 14 terms reach
        // 1e-17.
        const double y = x * x;
        g.setZero();
        double power = 1; // x^(2n - 2)
        g[0]         = 1;
        for (int n = 1; n <= 14; ++n)
          {
            g[2] += 2. * n * (2. * n - 1.) * power / (2. * n + 1.);
            g[1] += 2. * n * power * x / (2. * n + 1.);
            power *= y;
            g[0] += power / (2. * n + 1.);
          }
        return g;
      }
    // x g = atanh(x): g + x g' = 1 / (1 - x^2), 2 g' + x g'' =
    // 2 x / (1 - x^2)^2.
    const double s = 1. / (1. - x * x);
    g[0]           = std::atanh(x) / x;
    g[1]           = (s - g[0]) / x;
    g[2]           = (2. * x * s * s - 2. * g[1]) / x;
    return g;
  }


  WunderlichRibbon::WunderlichRibbon()
      : given{dealii::numbers::signaling_nan<double>(),
              dealii::numbers::signaling_nan<double>(),
              dealii::numbers::signaling_nan<double>(),
              dealii::numbers::signaling_nan<double>()}
      , plate_modulus(dealii::numbers::signaling_nan<double>())
  {
  }


  WunderlichRibbon::WunderlichRibbon(const RibbonConstants &constants)
      : given(constants)
  {
    check_ribbon_constants(wunderlich_context, constants);
    const double nu = constants.poisson_ratio;
    const double h  = constants.thickness;
    plate_modulus = constants.young_modulus * h * h * h / (12. * (1 - nu * nu));
    const double       B = bending_modulus();
    std::ostringstream text;
    text << wunderlich_context << ": D w = " << B
         << " from \"Young's modulus\", \"Width\" and \"Thickness\" must be "
            "positive and at most 1e100; give them in SI units (Pa, m)";
    AssertThrow(B > 0. && B <= max_input_magnitude,
                dealii::ExcMessage(text.str()));
  }


  MaterialResponse<3>
  WunderlichRibbon::hinge_energy(const Eigen::Vector3d &, const double) const
  {
    MaterialResponse<3> response;
    response.stress.setZero();
    response.tangent.setZero();
    return response;
  }


  MaterialResponse<1>
  WunderlichRibbon::segment_energy(const double, const double) const
  {
    MaterialResponse<1> response;
    response.stress.setZero();
    response.tangent.setZero();
    return response;
  }


  DevelopableRibbonLaw::Response
  WunderlichRibbon::energy(const double kappa_1,
                           const double eta,
                           const double eta_prime,
                           const double voronoi_length) const
  {
    Assert(!std::isnan(plate_modulus),
           dealii::ExcMessage("WunderlichRibbon used before its constants "
                              "were set by parse_parameters()"));
    const double w = given.width;
    const double c = bending_modulus() / voronoi_length; // D w / l
    const double p = 1 + eta * eta;
    // g and its derivatives in eta' (dx / d eta' = w / 2).
    Eigen::Vector3d g = wunderlich_width_factor(eta_prime * w / 2);
    g[1] *= w / 2;
    g[2] *= w * w / 4;

    const double k2 = kappa_1 * kappa_1;
    Response     r;
    r.energy        = c / 2 * k2 * p * p * g[0];
    r.gradient[0]   = c * kappa_1 * p * p * g[0];
    r.gradient[1]   = 2 * c * k2 * p * eta * g[0];
    r.gradient[2]   = c / 2 * k2 * p * p * g[1];
    r.hessian(0, 0) = c * p * p * g[0];
    r.hessian(0, 1) = 4 * c * kappa_1 * p * eta * g[0];
    r.hessian(0, 2) = c * kappa_1 * p * p * g[1];
    r.hessian(1, 1) = 2 * c * k2 * (p + 2 * eta * eta) * g[0];
    r.hessian(1, 2) = 2 * c * k2 * p * eta * g[1];
    r.hessian(2, 2) = c / 2 * k2 * p * p * g[2];
    r.hessian(1, 0) = r.hessian(0, 1);
    r.hessian(2, 0) = r.hessian(0, 2);
    r.hessian(2, 1) = r.hessian(1, 2);
    return r;
  }


  double
  WunderlichRibbon::bending_modulus() const
  {
    return plate_modulus * given.width;
  }


  void
  WunderlichRibbon::declare_parameters(dealii::ParameterHandler &prm) const
  {
    declare_ribbon_constants(prm,
                             "plate modulus D = Y h^3 / (12 (1 - nu^2)).",
                             "Full width w along d1 (m); bending modulus D w.");
  }


  void
  WunderlichRibbon::parse_parameters(dealii::ParameterHandler &prm)
  {
    *this = WunderlichRibbon(parse_ribbon_constants(prm));
  }


  std::optional<CrossSection>
  WunderlichRibbon::cross_section() const
  {
    return rectangle_section(given.width, given.thickness);
  }
} // namespace rodnet
