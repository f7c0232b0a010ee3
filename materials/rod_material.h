#ifndef RODNET_MATERIALS_ROD_MATERIAL_H
#define RODNET_MATERIALS_ROD_MATERIAL_H

#include <deal.II/base/parameter_handler.h>

#include <base/registry.h>
#include <materials/cross_section.h>
#include <materials/rod_stiffness.h>

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  class DevelopableRibbonLaw;

  /// Energy of one stencil and its first and second derivatives with respect
  /// to the stencil's strain vector.
  template <int n_strains>
  struct MaterialResponse
  {
    double                                      energy = 0.0;
    Eigen::Matrix<double, n_strains, 1>         stress;
    Eigen::Matrix<double, n_strains, n_strains> tangent;
  };

  /**
   * Constitutive law of a rod: energy of a hinge as a function of its
   * integrated bending/twisting strains kappa = (kappa_1, kappa_2, kappa_3)
   * and of a segment as a function of its axial strain. It knows nothing of
   * kinematics or meshes: the strains come from any element kernel, and the
   * lengths that turn integrated strains into densities are passed in.
   *
   * Implementations register themselves under a name with
   * RODNET_REGISTER_MATERIAL and read their constants from a scene
   * subsection of that name.
   *
   * <h3>History-dependent materials</h3>
   *
   * A material may carry internal variables per hinge and per segment
   * (e.g. viscous strains). Its constitutive update is variational
   * (Lestringant & Kochmann section 2.4, variational constitutive updates):
   * with a free energy W(kappa, alpha) and a dissipation potential
   * Psi(alpha_dot), a step of length dt from the committed variables
   * alpha_prev minimizes the incremental potential
   *   W_inc(kappa) = min_alpha [W(kappa, alpha)
   *                             + dt Psi((alpha - alpha_prev) / dt)],
   * and the element sees W_inc with its consistent first and second
   * derivatives (hinge_increment(), segment_increment()). The material
   * stays a pure function of its arguments; the caller owns the storage:
   *
   * - the assembly keeps, per hinge (segment), an array of
   *   n_hinge_internal_variables() (n_segment_internal_variables())
   *   committed values, zero in the undeformed, unloaded state;
   * - every evaluation within a step passes the committed values as
   *   @p previous, the step's time step, and a scratch array @p updated,
   *   into which the material writes the minimizing variables for the
   *   strains it was given;
   * - only once the step has converged does the assembly copy the
   *   @p updated of the converged strains into the committed values; a
   *   failed or cut step leaves them untouched.
   *
   * A step of zero length lets no variable flow: the increment functions
   * then return the stored energy W(kappa, previous) with its derivatives,
   * the instantaneous response at the committed variables. A time stepper
   * evaluates converged states that way (stresses, energies and reactions
   * at the end of a step, after the commit).
   *
   * Materials without internal variables (the default) ignore the time step
   * and the arrays and return hinge_energy() / segment_energy(), so a static
   * solve may call the increment functions with any time step.
   */
  /// Parts of a rod's natural shape (LinearElasticRod's RodNaturalShape)
  /// that RodMaterial::with_natural_shape_scaled() scales.
  struct NaturalShapeParts
  {
    bool curvature   = false; ///< both natural curvatures
    bool twist       = false; ///< the natural twist rate
    bool eigenstrain = false; ///< the axial eigenstrain
  };

  class RodMaterial
  {
  public:
    virtual ~RodMaterial() = default;

    /**
     * Energy of a hinge with integrated strains @p kappa and undeformed
     * Voronoi length @p voronoi_length (Korner et al. eq. 4.2,
     * Lestringant & Kochmann eq. 13: W = l E(kappa / l)).
     */
    virtual MaterialResponse<3>
    hinge_energy(const Eigen::Vector3d &kappa, double voronoi_length) const = 0;

    /// Energy of a segment of undeformed length @p rest_length and axial
    /// (engineering) strain @p strain.
    virtual MaterialResponse<1>
    segment_energy(double strain, double rest_length) const = 0;

    /// Number of internal variables each hinge stores (default: none).
    virtual unsigned int
    n_hinge_internal_variables() const
    {
      return 0;
    }

    /// Number of internal variables each segment stores (default: none).
    virtual unsigned int
    n_segment_internal_variables() const
    {
      return 0;
    }

    /// One name (with unit) per hinge internal variable, for output.
    virtual std::vector<std::string>
    hinge_internal_variable_names() const
    {
      return {};
    }

    /// One name (with unit) per segment internal variable, for output.
    virtual std::vector<std::string>
    segment_internal_variable_names() const
    {
      return {};
    }

    /**
     * Condensed incremental energy of a hinge over one time step (see the
     * class documentation): min over alpha of
     * W(kappa, alpha) + time_step Psi((alpha - previous) / time_step), its
     * gradient (by the envelope theorem, dW/dkappa at the minimizer) and
     * its consistent Hessian with respect to @p kappa (which includes the
     * dependence of the minimizer on kappa).
     *
     * @p previous holds the n_hinge_internal_variables() committed values,
     * @p updated receives as many minimizing values, or is null when the
     * caller needs none (an energy-only evaluation); both may be null when
     * there are no variables, and they must not overlap. Materials with
     * internal variables throw std::invalid_argument (check_time_step()) unless
     * @p time_step is finite and not negative (0: no flow, see above).
     *
     * The default, for materials without internal variables, returns
     * hinge_energy(kappa, voronoi_length) and touches neither array.
     */
    virtual MaterialResponse<3>
    hinge_increment(const Eigen::Vector3d &kappa,
                    double                 voronoi_length,
                    const double          *previous,
                    double                 time_step,
                    double                *updated) const
    {
      (void)previous;
      (void)time_step;
      (void)updated;
      return hinge_energy(kappa, voronoi_length);
    }

    /**
     * Condensed incremental energy of a segment over one time step, with
     * the contract of hinge_increment() for n_segment_internal_variables()
     * values. The default returns segment_energy(strain, rest_length).
     */
    virtual MaterialResponse<1>
    segment_increment(double        strain,
                      double        rest_length,
                      const double *previous,
                      double        time_step,
                      double       *updated) const
    {
      (void)previous;
      (void)time_step;
      (void)updated;
      return segment_energy(strain, rest_length);
    }

    /**
     * Throws std::invalid_argument unless @p time_step is finite and not
     * negative: time runs forward in a history-dependent update. Called by
     * materials with internal variables; a time stepper may call it to
     * reject a bad step before assembling.
     */
    static void
    check_time_step(const double time_step)
    {
      if (!(time_step >= 0. && std::isfinite(time_step)))
        {
          std::ostringstream message;
          message << "rod material with internal variables: the time step "
                     "must be finite and not negative, got "
                  << time_step;
          throw std::invalid_argument(message.str());
        }
    }

    /**
     * The cross-section the rigidities were computed from, where the
     * material was given one (its "Stiffness input = section"); empty (the
     * default) where they were given directly. Time stepping takes the
     * inertia of a rod from it.
     */
    virtual std::optional<CrossSection>
    cross_section() const
    {
      return std::nullopt;
    }

    /**
     * The rigidities if the material is a linear elastic rod that is stress
     * free when straight and unstretched (no natural curvature, twist or
     * eigenstrain), as the bending-active element of dynamic relaxation
     * takes; empty (the default) for every other material.
     */
    virtual std::optional<RodStiffness>
    straight_linear_elastic_stiffness() const
    {
      return std::nullopt;
    }

    /**
     * The energy law of an inextensible developable ribbon if the material
     * is one (materials/developable_ribbon_law.h): its rods are then
     * inextensible and get the ribbon's DoFs and constraints
     * (families/developable_ribbon_family.h); null (the default) for a rod.
     */
    virtual const DevelopableRibbonLaw *
    developable_ribbon() const
    {
      return nullptr;
    }

    /**
     * This material with the parts @p parts of its natural shape multiplied
     * by @p factor: a natural shape ramped with the load factor
     * (RodModel::ramp_natural_shape()). The default, for a material
     * without a natural shape, throws std::invalid_argument.
     */
    virtual std::shared_ptr<const RodMaterial>
    with_natural_shape_scaled(const NaturalShapeParts &parts,
                              double                   factor) const;

    /// Declares the material's entries in the current subsection.
    virtual void
    declare_parameters(dealii::ParameterHandler &prm) const = 0;

    /// Reads the material's entries from the current subsection; throws
    /// with a message naming the entry for inadmissible values.
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;
  };

  /// Name-keyed factory of rod materials (base/registry.h): every material
  /// registers itself with RODNET_REGISTER_MATERIAL in its own .cc file.
  class MaterialRegistry : public Registry<RodMaterial>
  {
  public:
    /// The process-wide registry.
    static MaterialRegistry &
    instance();

  private:
    MaterialRegistry()
        : Registry<RodMaterial>("material", "materials")
    {
    }
  };
} // namespace rodnet

/// Registers material class @p classname under @p name.
#define RODNET_REGISTER_MATERIAL(classname, name, description)         \
  namespace                                                            \
  {                                                                    \
    const bool rodnet_registered_##classname = [] {                    \
      rodnet::MaterialRegistry::instance().add(name, description, [] { \
        return std::unique_ptr<rodnet::RodMaterial>(new classname());  \
      });                                                              \
      return true;                                                     \
    }();                                                               \
  }

#endif
