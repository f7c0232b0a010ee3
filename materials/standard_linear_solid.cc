#include <deal.II/base/exceptions.h>
#include <deal.II/base/signaling_nan.h>

#include <materials/input_limits.h>
#include <materials/standard_linear_solid.h>
#include <materials/stiffness_input.h>

#include <cmath>

namespace rodnet
{
  RODNET_REGISTER_MATERIAL(StandardLinearSolid,
                           "standard linear solid",
                           "Viscoelastic rod of standard linear solid "
                           "(spring E1 parallel to spring E2 in series with "
                           "a dashpot) in bending, torsion and stretching, "
                           "with one viscous strain per mode "
                           "(Lestringant & Kochmann eq. 14).")

  namespace
  {
    // Prefix of every message, so a user sees which subsection is at fault.
    constexpr char standard_linear_solid_context[] = "standard linear solid";

    /**
     * The condensed incremental response of independent SLS modes per unit
     * length, with respect to the strain densities @p density: relaxed
     * rigidities @p relaxed, Maxwell rigidities @p ratio times those,
     * committed viscous strains @p previous, step @p time_step over
     * relaxation time @p relaxation_time. Writes the minimizing viscous
     * strains to @p updated unless it is null.
     */
    template <int n_modes>
    MaterialResponse<n_modes>
    condensed_density(const Eigen::Matrix<double, n_modes, 1> &density,
                      const Eigen::Matrix<double, n_modes, 1> &relaxed,
                      const double                             ratio,
                      const Eigen::Matrix<double, n_modes, 1> &previous,
                      const double                             time_step,
                      const double                             relaxation_time,
                      double                                  *updated)
    {
      // The minimizer alpha = w alpha_prev + (1 - w) e, w = t_r/(t_r + dt),
      // turns the Maxwell branch's stored and dissipated energies into
      // w r k (e - alpha_prev)^2 / 2 (doc/viscoelasticity.md). Both weights
      // are formed directly: 1 - w would lose digits for dt << t_r.
      const double retention = relaxation_time / (relaxation_time + time_step);
      const double flow      = time_step / (relaxation_time + time_step);

      const Eigen::Matrix<double, n_modes, 1> maxwell =
        retention * ratio * relaxed;
      const Eigen::Matrix<double, n_modes, 1> branch = density - previous;

      MaterialResponse<n_modes> response;
      response.energy = 0.5 * (relaxed.dot(density.cwiseProduct(density)) +
                               maxwell.dot(branch.cwiseProduct(branch)));
      // Envelope theorem: d/de of the minimum is the partial derivative at
      // the minimizer, r k (e - alpha) = w r k (e - alpha_prev).
      response.stress =
        relaxed.cwiseProduct(density) + maxwell.cwiseProduct(branch);
      response.tangent = (relaxed + maxwell).asDiagonal();

      if (updated != nullptr)
        {
          Eigen::Map<Eigen::Matrix<double, n_modes, 1>> minimizer(updated);
          minimizer = retention * previous + flow * density;
        }
      return response;
    }


    /**
     * Condensed response of a hinge of @p material (see condensed_density).
     * As in LinearElasticRod, kappa / l is the strain density (Korner et
     * al. eq. 4.2): the energy's factor l cancels one 1/l of each
     * derivative of kappa / l, so the stress keeps no factor of l and the
     * tangent keeps 1/l.
     */
    MaterialResponse<3>
    hinge_response(const StandardLinearSolid &material,
                   const Eigen::Vector3d     &kappa,
                   const double               voronoi_length,
                   const Eigen::Vector3d     &previous,
                   const double               time_step,
                   double                    *updated)
    {
      Assert(!std::isnan(material.modulus_ratio()),
             dealii::ExcMessage("StandardLinearSolid used before its "
                                "constants were set by parse_parameters()"));
      Assert(voronoi_length > 0., dealii::ExcMessage("Voronoi length <= 0"));

      const RodStiffness &k = material.relaxed_stiffness();
      MaterialResponse<3> response =
        condensed_density<3>(kappa / voronoi_length,
                             Eigen::Vector3d(k.EI1, k.EI2, k.GJ),
                             material.modulus_ratio(),
                             previous,
                             time_step,
                             material.relaxation_time(),
                             updated);
      response.energy *= voronoi_length;
      response.tangent /= voronoi_length;
      return response;
    }


    /// Condensed response of a segment of @p material, with the scaling of
    /// LinearElasticRod::segment_energy, W = l0 E(eps).
    MaterialResponse<1>
    segment_response(const StandardLinearSolid &material,
                     const double               strain,
                     const double               rest_length,
                     const double               previous,
                     const double               time_step,
                     double                    *updated)
    {
      Assert(!std::isnan(material.modulus_ratio()),
             dealii::ExcMessage("StandardLinearSolid used before its "
                                "constants were set by parse_parameters()"));
      Assert(rest_length > 0., dealii::ExcMessage("rest length <= 0"));

      using Scalar = Eigen::Matrix<double, 1, 1>;
      MaterialResponse<1> response =
        condensed_density<1>(Scalar(strain),
                             Scalar(material.relaxed_stiffness().EA),
                             material.modulus_ratio(),
                             Scalar(previous),
                             time_step,
                             material.relaxation_time(),
                             updated);
      response.energy *= rest_length;
      response.stress *= rest_length;
      response.tangent *= rest_length;
      return response;
    }
  } // namespace


  StandardLinearSolid::StandardLinearSolid()
      : relaxed{dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>(),
                dealii::numbers::signaling_nan<double>()}
      , ratio(dealii::numbers::signaling_nan<double>())
      , t_relax(dealii::numbers::signaling_nan<double>())
  {
  }


  StandardLinearSolid::StandardLinearSolid(const RodStiffness &relaxed,
                                           const double        modulus_ratio,
                                           const double        relaxation_time)
      : relaxed(relaxed)
      , ratio(modulus_ratio)
      , t_relax(relaxation_time)
  {
    internal::check_positive_entry(standard_linear_solid_context,
                                   "EA",
                                   relaxed.EA);
    internal::check_positive_entry(standard_linear_solid_context,
                                   "EI1",
                                   relaxed.EI1);
    internal::check_positive_entry(standard_linear_solid_context,
                                   "EI2",
                                   relaxed.EI2);
    internal::check_positive_entry(standard_linear_solid_context,
                                   "GJ",
                                   relaxed.GJ);

    // Either degenerate Maxwell branch is an elastic rod that would carry
    // internal variables doing nothing; more likely an entry was forgotten
    // (they default to 0), so both are refused with the alternative named.
    AssertThrow(
      modulus_ratio > 0. && modulus_ratio <= max_input_magnitude,
      dealii::ExcMessage(internal::entry_message(
        standard_linear_solid_context,
        "Modulus ratio E2/E1",
        "must be positive and at most 1e100 (without the spring E2 the "
        "dashpot carries no stress: use \"linear elastic\" with "
        "E1)",
        modulus_ratio)));
    AssertThrow(relaxation_time > 0. && relaxation_time <= max_input_magnitude,
                dealii::ExcMessage(internal::entry_message(
                  standard_linear_solid_context,
                  "Relaxation time",
                  "must be positive and at most 1e100 (t_r = eta/E2 = 0 is a "
                  "dashpot without viscosity, the \"linear elastic\" rod "
                  "with E1; an infinite t_r is the one with E1 + E2)",
                  relaxation_time)));
  }


  MaterialResponse<3>
  StandardLinearSolid::hinge_energy(const Eigen::Vector3d &kappa,
                                    const double           voronoi_length) const
  {
    // W at zero viscous strain; a zero step keeps it there.
    return hinge_response(*this,
                          kappa,
                          voronoi_length,
                          Eigen::Vector3d::Zero(),
                          0.,
                          nullptr);
  }


  MaterialResponse<1>
  StandardLinearSolid::segment_energy(const double strain,
                                      const double rest_length) const
  {
    return segment_response(*this, strain, rest_length, 0., 0., nullptr);
  }


  unsigned int
  StandardLinearSolid::n_hinge_internal_variables() const
  {
    return 3;
  }


  unsigned int
  StandardLinearSolid::n_segment_internal_variables() const
  {
    return 1;
  }


  std::vector<std::string>
  StandardLinearSolid::hinge_internal_variable_names() const
  {
    return {"viscous curvature 1 (1/m)",
            "viscous curvature 2 (1/m)",
            "viscous twist rate (rad/m)"};
  }


  std::vector<std::string>
  StandardLinearSolid::segment_internal_variable_names() const
  {
    return {"viscous axial strain (-)"};
  }


  MaterialResponse<3>
  StandardLinearSolid::hinge_increment(const Eigen::Vector3d &kappa,
                                       const double           voronoi_length,
                                       const double          *previous,
                                       const double           time_step,
                                       double                *updated) const
  {
    Assert(previous != nullptr, dealii::ExcMessage("no committed variables"));
    check_time_step(time_step);
    return hinge_response(*this,
                          kappa,
                          voronoi_length,
                          Eigen::Map<const Eigen::Vector3d>(previous),
                          time_step,
                          updated);
  }


  MaterialResponse<1>
  StandardLinearSolid::segment_increment(const double  strain,
                                         const double  rest_length,
                                         const double *previous,
                                         const double  time_step,
                                         double       *updated) const
  {
    Assert(previous != nullptr, dealii::ExcMessage("no committed variables"));
    check_time_step(time_step);
    return segment_response(*this,
                            strain,
                            rest_length,
                            *previous,
                            time_step,
                            updated);
  }


  void
  StandardLinearSolid::declare_parameters(dealii::ParameterHandler &prm) const
  {
    using dealii::Patterns::Double;

    declare_stiffness_input(
      prm,
      "How the rigidities of the relaxed spring E1 are given: \"section\" "
      "from \"Young's modulus E1\", Poisson's ratio and a cross-section; "
      "\"direct\" as EA, EI1, EI2, GJ. The Maxwell spring's rigidities are "
      "these times \"Modulus ratio E2/E1\".");

    prm.declare_entry("Young's modulus E1",
                      "0",
                      Double(0),
                      "Modulus of the relaxed spring E1 (Pa), the long-time "
                      "Young's modulus. Required for \"section\"; 0 means "
                      "unset and is rejected.");
    prm.declare_entry("Poisson's ratio",
                      "0.5",
                      Double(-1, 0.5),
                      "Poisson's ratio nu (-), in (-1, 0.5], the same for "
                      "both springs and the dashpot: G1 = E1 / (2 (1 + nu)) "
                      "for torsion. Used for \"section\".");
    CrossSectionParameters::declare_parameters(prm);

    declare_direct_rigidities(prm, "Relaxed ");

    prm.declare_entry("Modulus ratio E2/E1",
                      "0",
                      Double(0),
                      "Stiffness of the Maxwell spring over the relaxed one "
                      "(-), positive; the instantaneous rigidities are "
                      "(1 + E2/E1) times the relaxed ones. 0 means unset "
                      "and is rejected.");
    prm.declare_entry("Relaxation time",
                      "0",
                      Double(0),
                      "Relaxation time t_r = eta / E2 of the Maxwell branch "
                      "(s), positive; creep under constant load has the time "
                      "constant t_r (1 + E2/E1). 0 means unset and is "
                      "rejected.");
  }


  void
  StandardLinearSolid::parse_parameters(dealii::ParameterHandler &prm)
  {
    // Without a "Shear modulus" entry: both springs share nu.
    const StiffnessInput input =
      parse_stiffness_input(prm,
                            standard_linear_solid_context,
                            "Young's modulus E1",
                            false);

    // The constructor validates; assigning only afterwards leaves *this
    // untouched when an entry is rejected.
    *this         = StandardLinearSolid(input.stiffness,
                                prm.get_double("Modulus ratio E2/E1"),
                                prm.get_double("Relaxation time"));
    given_section = input.section;
  }


  std::optional<CrossSection>
  StandardLinearSolid::cross_section() const
  {
    return given_section;
  }


  const RodStiffness &
  StandardLinearSolid::relaxed_stiffness() const
  {
    return relaxed;
  }


  double
  StandardLinearSolid::modulus_ratio() const
  {
    return ratio;
  }


  double
  StandardLinearSolid::relaxation_time() const
  {
    return t_relax;
  }


  double
  StandardLinearSolid::creep_time() const
  {
    // Under constant stress both springs share the load at first and the
    // dashpot sees E1 E2 / (E1 + E2) in series: t_c = eta (E1 + E2)/(E1 E2).
    return t_relax * (1. + ratio);
  }
} // namespace rodnet
