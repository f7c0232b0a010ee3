#ifndef RODNET_ELEMENTS_SIMPLE_HINGE_H
#define RODNET_ELEMENTS_SIMPLE_HINGE_H

#include <elements/reduced_hinge.h>

namespace rodnet
{
  /**
   * The bending and twisting measures of Korner, Audoly and Bhattacharya
   * (2021): with the segment frames d^j = p_{T^j}^{t^j} r_{T^j}(phi^j) D^j
   * (eq. 2.8), the Lagrangian rotation gradient q_i = conj(d^{i-1}) d^i
   * (eq. 2.11) gives kappa_i = 2 Im(q_i) (eq. 2.13), whose Cartesian
   * components are the bending strains about d_1, d_2 and the twist.
   *
   * The rotation gradient is taken in the hemisphere Re(q_i) >= 0, i.e.
   * kappa_i = 2 sin(theta_i / 2) n_i with 0 <= theta_i <= pi (section 2h), so
   * that the strains depend on the director frames only and not on the sign
   * chosen for the reference quaternions.
   *
   * Gradient and Hessians are the closed forms of section 3 (eqs. 3.1-3.7).
   */
  namespace reduced
  {
    struct SimpleHingeKinematics;
  }

  class SimpleHinge : public ReducedHinge<reduced::SimpleHingeKinematics>
  {
  public:
    std::string
    name() const override;

    Vector3
    strains(const HingeVector    &dofs,
            const HingeReference &reference) const override;
  };
} // namespace rodnet

#endif
