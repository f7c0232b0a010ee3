#ifndef RODNET_MATERIALS_ROD_MATERIAL_H
#define RODNET_MATERIALS_ROD_MATERIAL_H

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rodnet
{
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
   */
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

    /// Declares the material's entries in the current subsection.
    virtual void
    declare_parameters(dealii::ParameterHandler &prm) const = 0;

    /// Reads the material's entries from the current subsection; throws
    /// with a message naming the entry for inadmissible values.
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;
  };

  /// Name-keyed factory of rod materials (ASPECT-style plugin registry).
  class MaterialRegistry
  {
  public:
    using Factory = std::function<std::unique_ptr<RodMaterial>()>;

    /// The process-wide registry.
    static MaterialRegistry &
    instance();

    /// Registers @p factory under @p name with a one-line @p description.
    void
    add(const std::string &name,
        const std::string &description,
        Factory            factory);

    /// Creates the material registered as @p name; throws
    /// std::invalid_argument listing the known names otherwise.
    std::unique_ptr<RodMaterial>
    create(const std::string &name) const;

    /// Registered names, sorted.
    std::vector<std::string>
    names() const;

    /// Description given at registration.
    std::string
    description(const std::string &name) const;

  private:
    struct Entry
    {
      std::string description;
      Factory     factory;
    };
    std::map<std::string, Entry> entries;
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
