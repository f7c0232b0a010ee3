#ifndef RODNET_MATERIALS_DEVELOPABLE_RIBBON_LAW_H
#define RODNET_MATERIALS_DEVELOPABLE_RIBBON_LAW_H

#include <Eigen/Core>

namespace rodnet
{
  /**
   * The strain energy of an inextensible (developable) ribbon at one hinge
   * as a function of the three variables z = (kappa_1, eta, eta'): the
   * integrated bending strain about the width direction d1, the slope
   * eta = tan(gamma) of the generatrix (pi/2 - gamma is its angle to the
   * tangent) and its derivative along the centerline (Korner et al.
   * section 4(b)). A rod material that is such a ribbon returns its law
   * from RodMaterial::developable_ribbon(); the model then gives its rods
   * an eta DoF per hinge, imposes the developability constraints
   * kappa_2 = 0, kappa_3 = eta kappa_1 (eq. 4.6) and the centerline's
   * inextensibility (families/developable_ribbon_family.h). The law knows
   * nothing of meshes: the hinge's Voronoi length is passed in.
   */
  class DevelopableRibbonLaw
  {
  public:
    /// Energy with its gradient and Hessian in z.
    struct Response
    {
      double          energy = 0.0;
      Eigen::Vector3d gradient;
      Eigen::Matrix3d hessian;
    };

    /// The energy of a hinge of undeformed Voronoi length @p voronoi_length.
    /// Throws std::runtime_error outside the law's domain.
    virtual Response
    energy(double kappa_1,
           double eta,
           double eta_prime,
           double voronoi_length) const = 0;

    /// The bending modulus of the ribbon about d1 (N m^2), for scales.
    virtual double
    bending_modulus() const = 0;

  protected:
    ~DevelopableRibbonLaw() = default;
  };
} // namespace rodnet

#endif
