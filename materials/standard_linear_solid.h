#ifndef RODNET_MATERIALS_STANDARD_LINEAR_SOLID_H
#define RODNET_MATERIALS_STANDARD_LINEAR_SOLID_H

#include <materials/linear_elastic_rod.h>
#include <materials/rod_material.h>

namespace rodnet
{
  /**
   * A rod of standard linear viscoelastic solid (Zener model): a spring E1
   * in parallel with a Maxwell branch, a spring E2 in series with a dashpot
   * eta, in bending about d1 and d2, in torsion and in stretching
   * (Lestringant & Kochmann eq. 14, extended from bending about d1 to all
   * four modes).
   *
   * Every mode m has a strain density e_m (kappa_1/l, kappa_2/l, kappa_3/l
   * at a hinge of Voronoi length l; the axial strain eps at a segment), a
   * viscous strain alpha_m (the internal variable, same unit as e_m), and
   * three constants: the relaxed rigidity k_m (E1 A, E1 I1, E1 I2, G1 J),
   * the Maxwell rigidity r k_m with r = E2/E1, and the dashpot constant
   * t_r r k_m with the relaxation time t_r = eta/E2. Splitting every mode in
   * the same ratio E1 : E2 and with the same t_r is the isotropic solid
   * with a time-independent Poisson's ratio (G_i = E_i / (2 (1 + nu)) for
   * both springs and the dashpot). With the Voronoi convention of
   * LinearElasticRod, a hinge (segment) of length l stores and dissipates
   *   W   = l/2 sum_m [k_m e_m^2 + r k_m (e_m - alpha_m)^2],
   *   Psi = l/2 sum_m t_r r k_m alpha_dot_m^2.
   * (L&K's eq. 14 writes Psi with 1/l^3 instead of l; that is not an energy
   * rate per element, and l Psi(alpha_dot/l) in integrated strains, the
   * analogue of W = l E(kappa/l), gives the form above.)
   *
   * A time step dt from the committed alpha_prev minimizes
   * W + dt Psi((alpha - alpha_prev)/dt) over alpha in closed form
   * (a backward-Euler step of t_r alpha_dot = e - alpha):
   *   alpha_m = (dt e_m + t_r alpha_prev_m) / (dt + t_r),
   * and the condensed energy, its stress and tangent are
   *   W_inc = l/2 sum_m [k_m e_m^2 + w r k_m (e_m - alpha_prev_m)^2],
   *   s_m   = k_m e_m + w r k_m (e_m - alpha_prev_m)   (times l at segments),
   *   C_mm  = (k_m + w r k_m) / l                     (times l at segments),
   * with w = t_r / (t_r + dt): the instantaneous rigidity (1 + r) k_m as
   * dt -> 0, the relaxed k_m as dt -> infinity.
   *
   * Internal variables, all zero in the virgin state: per hinge the viscous
   * curvatures about d1 and d2 (1/m) and the viscous twist rate (rad/m), per
   * segment the viscous axial strain (-). hinge_energy() and
   * segment_energy() are W at zero viscous strain, the instantaneous
   * response (E1 + E2) of a virgin rod.
   *
   * Selected in a scene as "standard linear solid". Built by the registry,
   * the constants are NaN until parse_parameters() has read them.
   */
  class StandardLinearSolid : public RodMaterial
  {
  public:
    /// Constants unset (NaN) until parse_parameters().
    StandardLinearSolid();

    /**
     * A rod with relaxed rigidities @p relaxed (those of the spring E1),
     * modulus ratio @p modulus_ratio = E2/E1 and relaxation time
     * @p relaxation_time = eta/E2 (s). Throws unless all are positive and
     * finite.
     */
    StandardLinearSolid(const RodStiffness &relaxed,
                        double              modulus_ratio,
                        double              relaxation_time);

    MaterialResponse<3>
    hinge_energy(const Eigen::Vector3d &kappa,
                 double                 voronoi_length) const override;

    MaterialResponse<1>
    segment_energy(double strain, double rest_length) const override;

    /// Three: viscous curvatures 1 and 2 and viscous twist rate.
    unsigned int
    n_hinge_internal_variables() const override;

    /// One: viscous axial strain.
    unsigned int
    n_segment_internal_variables() const override;

    std::vector<std::string>
    hinge_internal_variable_names() const override;

    std::vector<std::string>
    segment_internal_variable_names() const override;

    MaterialResponse<3>
    hinge_increment(const Eigen::Vector3d &kappa,
                    double                 voronoi_length,
                    const double          *previous,
                    double                 time_step,
                    double                *updated) const override;

    MaterialResponse<1>
    segment_increment(double        strain,
                      double        rest_length,
                      const double *previous,
                      double        time_step,
                      double       *updated) const override;

    /**
     * Declares "Stiffness input" (section | direct) for the relaxed
     * spring: for "section", "Young's modulus E1", "Poisson's ratio" and
     * the entries of CrossSectionParameters; for "direct", "EA", "EI1",
     * "EI2", "GJ"; always "Modulus ratio E2/E1" and "Relaxation time".
     */
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// The section of "Stiffness input = section", else empty.
    std::optional<CrossSection>
    cross_section() const override;

    /// Rigidities of the relaxed spring E1.
    const RodStiffness &
    relaxed_stiffness() const;

    /// E2 / E1.
    double
    modulus_ratio() const;

    /// t_r = eta / E2 (s).
    double
    relaxation_time() const;

    /// Creep time t_c = t_r (E1 + E2) / E1 (s), the time constant of the
    /// strain under constant stress.
    double
    creep_time() const;

  private:
    RodStiffness relaxed;
    /// The section the rigidities come from, if any.
    std::optional<CrossSection> given_section;
    double       ratio;
    double       t_relax;
  };
} // namespace rodnet

#endif
