#ifndef RODNET_CORE_RIGID_BODY_H
#define RODNET_CORE_RIGID_BODY_H

#include <core/rod_network.h>

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rodnet
{
  /**
   * A rigid body attached to a rod network: a hub, an end mass, a
   * connector. The time integrators keep the mass matrix M constant, so a
   * body is represented only where its kinetic energy is a constant
   * quadratic form of the DoF velocities (doc/dynamics.md, "Rigid
   * bodies"; doc/theory.md, "Rigid bodies"):
   *
   * - at a vertex (attachment: the vertex): a point mass m on its position
   *   DoFs. An isotropic rotary inertia j (the tensor j I) needs a junction
   *   with a rotation at the vertex (a network junction or a rotation
   *   handle): its quaternion increment q = (1, v) turns with
   *   omega = 2 vdot at v = 0, so 1/2 j |omega|^2 = 1/2 (4 j) |vdot|^2, the
   *   block 4 j I_3 on v;
   * - welded to a free rod end (attachment: the RodEnd): its centre on the
   *   end tangent t at @p offset c beyond the end vertex x_e, x_c = x_e +
   *   c t, t the end segment's (EndKinematics); an
   *   inertia axisymmetric about the tangent, J_t on the spin rate about
   *   it and J_p on the rate of the tangent, |tdot|^2. Both are exact
   *   while the end segments keep their lengths.
   *
   * - at a junction with a rotation, with a general inertia tensor J_0
   *   (@p inertia_tensor, in global axes at the undeformed configuration):
   *   a point mass m on the position, and the kinetic energy
   *   1/2 omega . R J_0 R^T omega of the junction's rotation R (from the
   *   undeformed configuration), which depends on R: the constant M
   *   carries its isotropic part j = trace(J_0) / 3 as above, and the
   *   midpoint rule the rest (BodyRotationInertia,
   *   solvers/time/body_rotation_inertia.h); the other integrators refuse it.
   *
   * - at a junction with a rotation, with its centre off the vertex:
   *   x_c = x_j + R r_0 (@p centre_offset r_0, in global axes at the
   *   undeformed configuration), the inertia J_c (isotropic or a tensor)
   *   about the centre: the kinetic energy 1/2 m |xdot_c|^2 +
   *   1/2 omega . R J_c R^T omega, xdot_c = xdot_j + omega x R r_0,
   *   depends on R; the constant M carries m on x_j and the isotropic part
   *   of the inertia about the vertex, J_c + m (|r_0|^2 I - r_0 r_0^T), and
   *   the midpoint rule the rest (BodyRotationInertia); the weight acts at
   *   the centre (BodyWeightFamily).
   */
  struct RigidBody
  {
    /// What messages call the body, e.g. "rigid body \"hub\"" or, from a
    /// scene, "entry \"Loads/Rigid bodies\": \"end\"".
    std::string where;
    /// The free rod end it is welded to, or the vertex it sits at.
    std::variant<RodEnd, unsigned int> attachment;
    /// m (kg).
    double mass = 0;
    /// J_t (kg m^2), about the end tangent; at a vertex, the isotropic j.
    double axial_inertia = 0;
    /// J_p (kg m^2), about the axes normal to the end tangent; at a vertex
    /// the isotropic j again (it must equal axial_inertia).
    double transverse_inertia = 0;
    /// c (m), the distance of the centre beyond the rod end along its
    /// tangent; zero at a vertex.
    double offset = 0;
    /// J_0 (kg m^2), a general inertia tensor in global axes at the
    /// undeformed configuration, at a vertex with a junction that turns;
    /// zero for none (then axial_inertia and transverse_inertia are zero).
    Matrix3 inertia_tensor = Matrix3::Zero();
    /// r_0 (m), the centre's offset from the vertex in global axes at the
    /// undeformed configuration, at a vertex with a junction that turns;
    /// zero for a centre at the vertex (and at a rod end).
    Vector3 centre_offset = Vector3::Zero();

    /// Whether the body has a general inertia tensor.
    bool
    has_inertia_tensor() const
    {
      return inertia_tensor != Matrix3::Zero();
    }

    /// Whether the centre is off the vertex (centre_offset).
    bool
    has_centre_offset() const
    {
      return centre_offset != Vector3::Zero();
    }

    /// Whether the body's kinetic energy depends on the rotation of its
    /// junction (an inertia tensor or a centre off the vertex), which only
    /// the midpoint rule carries (BodyRotationInertia).
    bool
    turns_with_junction() const
    {
      return has_inertia_tensor() || has_centre_offset();
    }

    /// J_c, the inertia about the centre in global axes at the undeformed
    /// configuration: the tensor, or j I.
    Matrix3
    centre_inertia() const
    {
      return has_inertia_tensor() ?
               inertia_tensor :
               Matrix3(axial_inertia * Matrix3::Identity());
    }

    /// The inertia about the vertex, J_c + m (|r_0|^2 I - r_0 r_0^T)
    /// (parallel axes).
    Matrix3
    vertex_inertia() const
    {
      const Vector3 &r = centre_offset;
      return centre_inertia() +
             mass * (r.squaredNorm() * Matrix3::Identity() - r * r.transpose());
    }

    /// The isotropic rotary inertia that the mass matrix carries at a
    /// vertex: j, or for a body that turns with its junction the mean
    /// moment about the vertex, trace(vertex_inertia()) / 3, the rest
    /// being BodyRotationInertia's. About the vertex rather than the
    /// centre: a point mass off the vertex (J_c = 0) still gives the
    /// rotation rows a positive mass, and M's block is then the inertia
    /// that the rows have while the vertex is held.
    double
    isotropic_inertia() const
    {
      return turns_with_junction() ? vertex_inertia().trace() / 3 :
                                     axial_inertia;
    }
  };

  /**
   * Throws std::invalid_argument naming @p body's @p where for what
   * @p network cannot carry: a mass, inertia or offset that is negative or
   * not finite, a body with neither mass nor inertia, a vertex or rod that
   * does not exist, a rotary inertia at a vertex without a junction that
   * turns (a pinned junction, a plain vertex), an anisotropic inertia or an
   * offset at a vertex (no axis), an end of a closed rod; an inertia tensor
   * that is not finite, symmetric and positive definite, or that comes
   * with another inertia, an offset or a rod end; a centre offset that is
   * not finite, at a rod end, or at a vertex without a junction that
   * turns.
   */
  void
  check_rigid_body(const RodNetwork &network, const RigidBody &body);

  /**
   * How a body welded to the free rod end @p end moves with the DoFs, all
   * linear in them: its centre x_c = sum_i centre_i x_i at @p offset beyond
   * the end on the end segment's tangent t = sum_i tangent_i x_i =
   * (x_e - x_p) / l, and its spin about t, sum_k spin_k phidot_k: the end
   * segment's twist rate. The end segment's tangent and twist belong to
   * its midpoint, l/2 inside the end: the rotary inertia and the offset
   * converge at first order in l (doc/dynamics.md, "Rigid bodies").
   */
  struct EndKinematics
  {
    /// The end vertex and the one before it.
    std::vector<unsigned int> vertices;
    std::vector<double>       centre, tangent;
    /// The active cell of the end segment.
    std::vector<unsigned int> segments;
    std::vector<double>       spin;
  };

  /// The EndKinematics of the free rod end @p end of @p network with the
  /// centre at @p offset beyond it.
  EndKinematics
  end_kinematics(const RodNetwork &network, const RodEnd &end, double offset);

  /**
   * The weight m g of @p body under the gravitational acceleration
   * @p gravity, acting at its centre, as point forces (vertex, force): at
   * its vertex, or at a rod end split as x_c is (EndKinematics::centre:
   * the same moment about the end while the end segments keep their
   * lengths). At a vertex with a centre offset, the force m g at the
   * vertex: the weight's moment about it, which turns with the junction,
   * is BodyWeightFamily's.
   */
  std::vector<std::pair<unsigned int, Vector3>>
  rigid_body_weight(const RodNetwork &network,
                    const RigidBody  &body,
                    const Vector3    &gravity);
} // namespace rodnet

#endif
