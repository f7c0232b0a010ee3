#ifndef RODNET_MATERIALS_LINEAR_ELASTIC_ROD_H
#define RODNET_MATERIALS_LINEAR_ELASTIC_ROD_H

#include <materials/cross_section.h>
#include <materials/rod_material.h>

#include <string>

namespace rodnet
{
  /**
   * Stress-free shape of a rod: natural curvatures about d1 and d2 (1/m),
   * natural twist rate (rad/m) and axial eigenstrain (-), e.g. from a
   * programmed shape-memory state or thermal swelling (Lestringant &
   * Kochmann eqs. 16-17).
   */
  struct RodNaturalShape
  {
    double curvature1        = 0.;
    double curvature2        = 0.;
    double twist             = 0.;
    double axial_eigenstrain = 0.;
  };

  /**
   * Rigidities of a homogeneous isotropic rod with Young's modulus @p E (Pa),
   * shear modulus @p G (Pa) and cross-section @p section:
   * (E A, E I1, E I2, G J). Throws unless E and G are positive and finite.
   */
  RodStiffness
  stiffness_from_section(double E, double G, const CrossSection &section);

  /**
   * Shear modulus E / (2 (1 + nu)) of an isotropic material with Young's
   * modulus @p E and the entry "Poisson's ratio" @p nu; throws a message
   * starting with @p context unless nu lies in (-1, 0.5].
   */
  double
  isotropic_shear_modulus(const std::string &context, double E, double nu);

  /**
   * Declares the entries EA, EI1, EI2 and GJ of the "direct" stiffness
   * input in the current subsection; @p qualifier starts their help texts
   * (e.g. "Relaxed " for a viscoelastic law's long-time rigidities).
   */
  void
  declare_direct_rigidities(dealii::ParameterHandler &prm,
                            const std::string        &qualifier);

  /// Reads the entries of declare_direct_rigidities() (unchecked: the
  /// material's constructor validates them, naming the entry).
  RodStiffness
  parse_direct_rigidities(dealii::ParameterHandler &prm);

  /**
   * The linear elastic (Kirchhoff) rod with natural curvature, twist and
   * axial eigenstrain. A hinge with integrated strains kappa and Voronoi
   * length l stores (Korner et al. eq. 4.2 applied to eq. 4.1; Lestringant
   * & Kochmann eq. 16)
   *   W = l/2 [EI1 (kappa_1/l - k1)^2 + EI2 (kappa_2/l - k2)^2
   *            + GJ (kappa_3/l - tau)^2],
   * and a segment of rest length l0 and axial strain eps stores
   * (Lestringant & Kochmann eq. 17)
   *   W = l0/2 EA (eps - eps0)^2.
   *
   * Selected in a scene as "linear elastic". Built by the registry, the
   * constants are NaN until parse_parameters() has read them.
   */
  class LinearElasticRod : public RodMaterial
  {
  public:
    /// Constants unset (NaN) until parse_parameters().
    LinearElasticRod();

    /// A rod with the given rigidities and natural shape; throws unless the
    /// rigidities are positive and finite.
    explicit LinearElasticRod(const RodStiffness    &stiffness,
                              const RodNaturalShape &natural_shape = {});

    MaterialResponse<3>
    hinge_energy(const Eigen::Vector3d &kappa,
                 double                 voronoi_length) const override;

    MaterialResponse<1>
    segment_energy(double strain, double rest_length) const override;

    /**
     * Declares "Stiffness input" (section | direct); for "section":
     * "Young's modulus", "Poisson's ratio", "Shear modulus" and the entries
     * of CrossSectionParameters; for "direct": "EA", "EI1", "EI2", "GJ";
     * always: "Natural curvature 1", "Natural curvature 2", "Natural twist",
     * "Axial eigenstrain".
     */
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// The section of "Stiffness input = section", else empty.
    std::optional<CrossSection>
    cross_section() const override;

    /// The rigidities unless a natural curvature, twist or eigenstrain is
    /// set.
    std::optional<RodStiffness>
    straight_linear_elastic_stiffness() const override;

    /// A copy whose natural shape has the parts @p parts times @p factor.
    std::shared_ptr<const RodMaterial>
    with_natural_shape_scaled(const NaturalShapeParts &parts,
                              double                   factor) const override;

    /// The rigidities in use.
    const RodStiffness &
    stiffness() const;

    /// The natural shape in use.
    const RodNaturalShape &
    natural_shape() const;

  private:
    RodStiffness    rigidities;
    RodNaturalShape rest_shape;
    /// The section the rigidities come from, if any.
    std::optional<CrossSection> given_section;
  };
} // namespace rodnet

#endif
