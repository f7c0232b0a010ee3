#ifndef RODNET_ELEMENTS_DR_BEAM_KERNEL_H
#define RODNET_ELEMENTS_DR_BEAM_KERNEL_H

#include <elements/quaternion.h>

#include <array>

namespace rodnet
{
  /**
   * @name The bending-active beam element of dynamic relaxation
   *
   * After Sakai, Ohsaki & Adriaenssens (2020) as written out in the
   * bending-active supplement (eqs. 1-50). Every node j carries its position
   * X_j, the x and y components of a unit normal n_j (n_z reconstructed,
   * eqs. 12-13) and a rotation n_{j,r} about n_j. An element k from node a
   * to node b is a straight chord t1 = (X_b - X_a)/L with a frame (t1, t2,
   * t3) built on the mean normal of its ends (eqs. 3-6). Its strains are
   * the change of length, the twist of the end normals about t1, the tilt
   * of each end normal towards t1 (out-of-plane end rotations) and the
   * in-plane end rotation of the chord about each end normal, measured from
   * the node's reference direction: the projection of the node's reference
   * element onto the node's plane, turned by n_{j,r} + alpha (eqs. 32-39).
   *
   * All angles are the supplement's sine-like measures (dot products of
   * unit vectors), not angles in radians; they agree with the angles to
   * second order. doc/dynamic_relaxation.md states every definition and
   * which of them are ours where the supplement only cites SOA20.
   *
   * Kinematics only: the energy of these strains is in
   * materials/dr_beam_energy.h.
   * @{
   */

  /// DoFs of one node: X (3), n_x, n_y, n_r.
  constexpr unsigned int n_dr_node_dofs = 6;

  /**
   * Local DoFs of an element: node a (6), node b (6), then the position of
   * the far node c_a of node a's reference element (3) and of c_b of node
   * b's (3). When the element is its node's own reference element the far
   * node is the element's other end (c_a = b, c_b = a) and the assembly
   * adds those entries of the gradient to that node.
   */
  constexpr unsigned int n_dr_element_dofs = 18;

  using DrElementVector = Eigen::Matrix<double, n_dr_element_dofs, 1>;

  /// Offsets of the parts of a DrElementVector.
  namespace dr_dof
  {
    constexpr unsigned int node_a = 0;  ///< X_a, n_ax, n_ay, n_ar
    constexpr unsigned int node_b = 6;  ///< X_b, n_bx, n_by, n_br
    constexpr unsigned int far_a  = 12; ///< X of c_a
    constexpr unsigned int far_b  = 15; ///< X of c_b

    /// Offsets within the block of one node (node_a or node_b).
    constexpr unsigned int position = 0; ///< X (3)
    constexpr unsigned int normal_x = 3; ///< n_x
    constexpr unsigned int normal_y = 4; ///< n_y
    constexpr unsigned int rotation = 5; ///< n_r (rad)
  }                                      // namespace dr_dof

  /**
   * Unit normal from its stored components: (n_x, n_y, sqrt(1 - n_x^2 -
   * n_y^2)) where n_x^2 + n_y^2 <= 1, else (n_x, n_y, 0) / |(n_x, n_y)|
   * (supplement eqs. 12-13). The normal's z component is never negative.
   */
  Vector3
  dr_normal(double n_x, double n_y);

  /// Columns: derivatives of dr_normal() with respect to n_x and n_y
  /// (eqs. 12-13, both branches). Singular on the unit circle
  /// n_x^2 + n_y^2 = 1 approached from inside, where dn_z/dn_x is unbounded.
  Eigen::Matrix<double, 3, 2>
  dr_normal_jacobian(double n_x, double n_y);

  /// Strains of one element; the angles are those of the supplement minus
  /// their values in the reference (rest) configuration.
  struct DrBeamStrains
  {
    double stretch; ///< L - L0 (m)
    /// (theta_1b - theta_1a) - rest, theta_1j = t2 . n_j. A right-handed
    /// rotation of n_b relative to n_a about t1 by phi gives
    /// -2 sin(phi / 2).
    double twist;
    /// theta_2 at a and b: tilt of the end normal towards the chord,
    /// n_j . t1 (bending about t3 = t1 x t2, towards the normal).
    std::array<double, 2> tilt;
    /// theta_3 at a and b: in-plane end rotation about the normal,
    /// (t1 x f2_j) . n_j (bending about the normal).
    std::array<double, 2> turn;
  };

  /// Derivatives of the element energy with respect to its strains, in the
  /// layout of DrBeamStrains.
  struct DrBeamStress
  {
    double                stretch;
    double                twist;
    std::array<double, 2> tilt;
    std::array<double, 2> turn;
  };

  /// What an element remembers of its rest configuration.
  struct DrBeamReference
  {
    double rest_length = 0;
    /// alpha_j: the angle about n_j from the projected reference direction
    /// f1hat_j to the projection of this element's chord t1, minus n_{j,r},
    /// all at rest, so that f2_j is along that projection and turn = 0 at
    /// rest. Where the element is its node's own reference the angle is 0
    /// at end a and pi at end b (the reference direction points from b to
    /// a, t1 from a to b).
    std::array<double, 2> alpha = {{0, 0}};
    /// Rest values subtracted from the supplement's angles.
    double                rest_twist = 0;
    std::array<double, 2> rest_tilt  = {{0, 0}};
    std::array<double, 2> rest_turn  = {{0, 0}};
  };

  /**
   * Rest data of an element from its local DoFs in the rest configuration:
   * rest length, offsets alpha (so that the in-plane end rotations vanish
   * there) and the rest angles. Throws std::invalid_argument if a DoF is
   * not finite, the element or a reference element has zero length, an end
   * normal or the mean normal is parallel to the chord, the end normals
   * are opposite, or a reference direction is parallel to its node's
   * normal.
   */
  DrBeamReference
  dr_beam_reference(const DrElementVector &rest_dofs);

  /**
   * Kinematics of one element at one state: the constructor evaluates the
   * frame, the angles and every intermediate the derivatives need;
   * pull_back() then turns dU/dstrains into the gradient with respect to the
   * local DoFs, (d strains / d dofs)^T stress, a reverse-mode pass through
   * the supplement's chain of eqs. 14-50. Usage per element and step:
   * construct, read strains(), evaluate the stress from the material,
   * pull_back().
   *
   * No checks in this hot path: the states where the element is undefined
   * are those dr_beam_reference() refuses, and give non-finite strains.
   */
  class DrBeamKinematics
  {
  public:
    DrBeamKinematics(const DrElementVector &dofs, const DrBeamReference &ref);

    const DrBeamStrains &
    strains() const
    {
      return current;
    }

    /// @p gradient = (d strains / d dofs)^T @p stress (overwritten).
    void
    pull_back(const DrBeamStress &stress, DrElementVector &gradient) const;

  private:
    /// The in-plane rotation at one end (eqs. 32-39).
    struct EndFrame
    {
      Vector3 r; ///< unit direction from X_j to X_{c_j}
      Vector3 g; ///< f1hat, r projected onto the plane normal to n_j
      Vector3 h; ///< n_j x f1hat
      double  inverse_reference_length; ///< 1 / |X_{c_j} - X_j|
      double  inverse_f1_norm;          ///< 1 / |f1|
      double  r_dot_n;
      double  cosine; ///< cos(n_{j,r} + alpha_j)
      double  sine;   ///< sin(n_{j,r} + alpha_j)
    };

    DrBeamStrains                              current;
    Vector3                                    t1;
    double                                     inverse_length;
    std::array<Vector3, 2>                     normal;
    std::array<Eigen::Matrix<double, 3, 2>, 2> normal_jacobian;
    Vector3                                    mean_normal; ///< n^k
    double                                     inverse_normal_sum_norm;
    Vector3                                    t2;
    double                                     inverse_t2_norm;
    std::array<EndFrame, 2>                    end;
  };
  /// @}
} // namespace rodnet

#endif
