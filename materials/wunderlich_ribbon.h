#ifndef RODNET_MATERIALS_WUNDERLICH_RIBBON_H
#define RODNET_MATERIALS_WUNDERLICH_RIBBON_H

#include <materials/developable_ribbon_law.h>
#include <materials/ribbon_constants.h>
#include <materials/rod_material.h>

namespace rodnet
{
  /**
   * g(x) = atanh(x) / x for |x| < 1 with its first and second derivatives:
   * the factor (1 / (w eta')) ln((1 + eta' w / 2) / (1 - eta' w / 2)) of
   * Korner et al. eq. 4.7 at x = eta' w / 2, which is 1 at x = 0. Near 0
   * it sums its series sum_n x^(2n) / (2n + 1), where the closed form
   * loses its digits. Throws std::runtime_error unless |x| < 1.
   */
  Eigen::Vector3d
  wunderlich_width_factor(double x);

  /**
   * The inextensible ribbon of Wunderlich (1962) in the discrete form of
   * Korner, Audoly & Bhattacharya eq. 4.7: a hinge of Voronoi length l with
   * bending strain kappa_1 about the width direction d1, generatrix slope
   * eta and its central difference eta' stores
   *   E = D w / (2 l) kappa_1^2 (1 + eta^2)^2 g(eta' w / 2),
   *   g(x) = atanh(x) / x = (1 / (w eta')) ln((1 + eta' w/2) / (1 - eta' w/2)),
   * with the plate's bending modulus D = Y h^3 / (12 (1 - nu^2)) and the
   * full width w (Starostin & van der Heijden write w for the half-width:
   * doc/ribbons.md). The energy is finite only for |eta' w| < 2, where no
   * two generatrices cross within the strip.
   *
   * As a RodMaterial it prices neither hinges nor segments by itself (its
   * hinge_energy() and segment_energy() are zero): its rods are
   * inextensible and developable, and the DevelopableRibbonFamily, which
   * the model adds for every rod whose material returns a
   * developable_ribbon(), carries the energy above with the constraints
   * kappa_2 = 0, kappa_3 = eta kappa_1 (eq. 4.6). The width lies along d1,
   * as for the Sano-Wada ribbon; the natural shape is the flat straight
   * strip.
   *
   * Selected in a scene as "wunderlich ribbon".
   */
  class WunderlichRibbon : public RodMaterial, public DevelopableRibbonLaw
  {
  public:
    /// Constants unset (NaN) until parse_parameters().
    WunderlichRibbon();

    /// A ribbon of the given constants; throws a message naming the entry
    /// unless Y, w, h are positive, nu lies in (-1, 0.5], h < w and D w is
    /// positive and at most 1e100.
    explicit WunderlichRibbon(const RibbonConstants &constants);

    /// Zero: the developable ribbon family carries the hinge energy.
    MaterialResponse<3>
    hinge_energy(const Eigen::Vector3d &kappa,
                 double                 voronoi_length) const override;

    /// Zero: the segments are inextensible.
    MaterialResponse<1>
    segment_energy(double strain, double rest_length) const override;

    const DevelopableRibbonLaw *
    developable_ribbon() const override
    {
      return this;
    }

    /// Eq. 4.7 with its exact gradient and Hessian in (kappa_1, eta, eta').
    Response
    energy(double kappa_1,
           double eta,
           double eta_prime,
           double voronoi_length) const override;

    /// D w.
    double
    bending_modulus() const override;

    /// Declares "Young's modulus", "Poisson's ratio", "Width", "Thickness".
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// The rectangle Width x Thickness (Width along d1).
    std::optional<CrossSection>
    cross_section() const override;

  private:
    RibbonConstants given;
    /// D = Y h^3 / (12 (1 - nu^2)).
    double plate_modulus;
  };
} // namespace rodnet

#endif
