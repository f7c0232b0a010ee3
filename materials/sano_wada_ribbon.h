#ifndef RODNET_MATERIALS_SANO_WADA_RIBBON_H
#define RODNET_MATERIALS_SANO_WADA_RIBBON_H

#include <materials/ribbon_constants.h>
#include <materials/rod_material.h>

namespace rodnet
{
  /// Moduli of a Sano-Wada ribbon derived from its RibbonConstants.
  struct RibbonModuli
  {
    double soft_bending;  ///< Y h^3 w / 12, about d1 (N m^2)
    double stiff_bending; ///< Y h w^3 / 12, about d2 (N m^2)
    double twisting;      ///< Y h^3 w / (6 (1 + nu)) (N m^2)
    double xi_squared;    ///< (1 - nu^2) w^4 / (60 h^2) (m^2)
    double axial;         ///< EA = Y w h (N)
  };

  /**
   * The extensible ribbon of Sano & Wada (2019) as a rod material, in the
   * discrete form of Korner, Audoly & Bhattacharya eq. 5.5: a hinge with
   * integrated strains kappa and Voronoi length l stores
   *   W = 1/(2 l) [A2 (kappa_1^2 + kappa_3^4 / (l^2/xi^2 + kappa_1^2))
   *                + A1 kappa_2^2 + A3 kappa_3^2],
   * with A1 = Y h w^3/12, A2 = Y h^3 w/12, A3 = Y h^3 w/(6 (1 + nu)) and
   * xi^2 = (1 - nu^2) w^4/(60 h^2). The quartic term is the stretching of
   * the mid-surface that twisting a bent ribbon costs: it stiffens twist
   * beyond |kappa_3 / l| ~ 1/xi, and bending the ribbon in its soft
   * direction relaxes it.
   *
   * Convention. Korner et al. write eq. 5.5 with their d1 the ribbon's
   * normal (A1 multiplies their kappa_1). Here, as in rodnet's rectangle
   * section (materials/cross_section.h), the width w lies along d1 and the
   * thickness h along d2, so kappa_1, the bending about d1, is the soft
   * one (A2 = Y h^3 w / 12, rodnet's EI1 = Y Width Thickness^3 / 12) and
   * couples with the twist in the quartic term; kappa_2, the bending about
   * d2 (in the ribbon's plane), is the stiff one (A1). Eq. 5.5 is this
   * energy with the paper's (kappa_1, kappa_2) = rodnet's (kappa_2,
   * kappa_1). For strains far below l/xi it is the linear elastic rod with
   * EI1 = A2, EI2 = A1, GJ = A3.
   *
   * The strains the material sees are those in excess of the rod's natural
   * shape (Geometry/Natural shape): a ribbon built curved and stress free
   * applies eq. 5.5 to the change of its strains, an extension that Sano &
   * Wada do not discuss; "Natural shape = straight" is their ribbon. The
   * ribbon has no natural curvature or twist of its own
   * (with_natural_shape_scaled() refuses).
   *
   * A segment of rest length l0 and axial strain eps stores
   * W = l0/2 EA eps^2 with EA = Y w h, the membrane stiffness of the strip.
   *
   * Selected in a scene as "sano-wada ribbon". Built by the registry, the
   * constants are NaN until parse_parameters() has read them.
   */
  class SanoWadaRibbon : public RodMaterial
  {
  public:
    /// Constants unset (NaN) until parse_parameters().
    SanoWadaRibbon();

    /// A ribbon of the given constants; throws a message naming the entry
    /// unless Y, w, h are positive and at most 1e100, nu lies in
    /// (-1, 0.5], h < w, and the derived moduli are positive and at most
    /// 1e100.
    explicit SanoWadaRibbon(const RibbonConstants &constants);

    /// Eq. 5.5 in rodnet's convention (class documentation), with its
    /// exact gradient and Hessian in kappa.
    MaterialResponse<3>
    hinge_energy(const Eigen::Vector3d &kappa,
                 double                 voronoi_length) const override;

    /// l0/2 EA eps^2 with EA = Y w h.
    MaterialResponse<1>
    segment_energy(double strain, double rest_length) const override;

    /// Declares "Young's modulus", "Poisson's ratio", "Width", "Thickness".
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// The rectangle Width x Thickness (Width along d1), for inertia.
    std::optional<CrossSection>
    cross_section() const override;

    /// The constants in use.
    const RibbonConstants &
    constants() const;

    /// The moduli derived from them.
    const RibbonModuli &
    moduli() const;

  private:
    RibbonConstants given;
    RibbonModuli    derived;
  };
} // namespace rodnet

#endif
