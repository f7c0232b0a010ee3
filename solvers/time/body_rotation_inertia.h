#ifndef RODNET_SOLVERS_TIME_BODY_ROTATION_INERTIA_H
#define RODNET_SOLVERS_TIME_BODY_ROTATION_INERTIA_H

#include <core/tensor_body_spin.h>
#include <solvers/time/integration_scheme.h>

#include <Eigen/Dense>
#include <vector>

namespace rodnet
{
  /**
   * The inertia of rigid bodies with a general inertia tensor at junctions
   * (RigidBody::inertia_tensor) for the midpoint rule (doc/dynamics.md,
   * "Rigid bodies"). Their kinetic energy 1/2 omega . J omega, J = R J_0
   * R^T, depends on the orientation R: the constant mass matrix carries
   * its isotropic part j = trace(J_0) / 3 (the block 4 j I_3, which also
   * gives the rows their velocity and the discrete gradient's correction
   * its metric there), and this class adds the rest of the inertial force
   * of the body, f below less (2 / h^2) 4 j (v - h vdot_n), to the rows of
   * the vector part v of the junction's quaternion increment q = (1, v),
   * which turns the body by the Cayley rotation C = cay(2 v) (exactly the
   * rotation of q: R_{n+1} = C R_n).
   *
   * The scheme is the Lie-Poisson midpoint rule of the free rigid body
   * (Austin, Krishnaprasad & Wang 1993; the Cayley form of Simo & Wong
   * 1991's energy-momentum algorithm): the body's mean angular velocity
   * over the step is omega_m = 2 v / h, in body axes W_m = R_n^T omega_m,
   * its body momentum Pi_{n+1} = 2 J_0 W_m - Pi_n, so that in space, with
   * J_n = R_n J_0 R_n^T and pi_n = J_n omega_n,
   *   pi_{n+1} = C p,   p = (4 / h) J_n v - pi_n,
   * and the force on the rows of v is
   *   f = (2 / h) (I - [v / 2]_x) (pi_{n+1} - pi_n).
   * Then f . v = K_{n+1} - K_n exactly (C^T v = v), so the midpoint rule's
   * energy balance holds; a torque-free body keeps pi to the Newton
   * tolerance (f = 0); and under the torque tau that the rest of the model
   * puts on the junction at the midpoint, pi_{n+1} - pi_n = h tau /
   * (1 + |v|^2 / 4), a relative error of order (omega h)^2 per step. At
   * the end of the step omega_{n+1} = C (4 v / h - omega_n): the midpoint
   * rule's velocity 2 v / h - vdot_n turned by C (turn_velocities()).
   *
   * A centre off the vertex, x_c = x_j + R r_0 (RigidBody::centre_offset),
   * with a free vertex: the centre moves by Delta x_c = Delta x_j +
   * (C - I) r_n, r_n = R_n r_0, at the midpoint velocity vc_{n+1} =
   * 2 Delta x_c / h - vc_n, and the force F_c = m (vc_{n+1} - vc_n) / h
   * acts on the rows of x_j and, as its moment about the vertex at the
   * midpoint arm r_m mapped to the rows of v as a gradient at the
   * midpoint increment v / 2 is (B^T, omega = B qdot),
   *   g = 2 (I - [v / 2]_x) (r_m x F_c) / (1 + |v|^2 / 4),
   *   r_m = (1 + |v|^2 / 4) (r_n + v x r_n) / (1 + |v|^2),
   * on the rows of v; since (C - I) r_n = 2 (I - [v]_x)^{-1} (v x r_n) =
   * 2 v x (r_n + v x r_n) / (1 + |v|^2), g . v = F_c . (C - I) r_n, so
   * that F_c . Delta x_j + g . v = Delta (1/2 m |vc|^2) exactly. A force at
   * the centre (the weight, BodyWeightFamily, whose gradient the midpoint
   * rule takes at v / 2) then has its moment about the centre cancelled to
   * second order, r_m = C(v / 2) r_n + O(|v|^2) (the moment of the simpler
   * r_n x (I + C^T) F_c, also exact in energy, differs at first order); J above
   * is then J_c about the centre, and M's m (2 / h^2)(Delta x_j - h xdot_{j,n})
   * on x_j is taken off. A free body keeps m vc and pi to the Newton tolerance.
   * At the end of the step the rows of x_j take xdot_j = vc_{n+1} - omega_{n+1}
   * x C r_n, where the rods' mass at the vertex would take the midpoint rule's
   * velocity: the rows get the velocity that keeps the sum of the momenta, the
   * rods' and the body's (momentum_weights below): the choice changes no
   * linear momentum, and the energy can only lose the (rods' mass)
   * |difference|^2 / 2 of merging the two. With its
   * vertex held the body turns about it: J is the inertia about the
   * vertex, J_c + m (|r_0|^2 I - r_0 r_0^T), and the rows of x_j are the
   * support's (check_tensor_bodies() refuses a vertex held in part or
   * moving in time).
   *
   * The step starts from an increment q = (1, 0), as TimeIntegrator leaves
   * it (SolvableModel::reset_reference()).
   *
   * On several processes each body is computed once, by the owner of its
   * rotation's first DoF, from replicas of the states (EveryEntry: its
   * rows and its junction may be other processes'); its forces, Jacobian
   * entries and turned velocities reach the rows of other processes
   * through the vector's and the matrix's buffers.
   */
  class BodyRotationInertia
  {
  public:
    /// @p model must be finalized and, with the unconstrained mass matrix
    /// @p mass (assembled before the first step), outlive this object.
    BodyRotationInertia(const SolvableModel &model, const MatrixType &mass);

    /// Adds the force of the step @p step to @p y to @p r (fixed rows too:
    /// the caller zeroes them).
    void
    add_force(const StepStart &step, const VectorType &y, VectorType &r) const;

    /// Adds its Jacobian with respect to @p y to @p k, leaving the rows
    /// and columns of fixed DoFs alone.
    void
    add_jacobian(const StepStart  &step,
                 const VectorType &y,
                 MatrixType       &k) const;

    /// Turns the velocity of the bodies' rows of @p v, the midpoint rule's
    /// 2 (x - u_n) / h - v_n, by the step's rotation C to @p x.
    void
    turn_velocities(const StepStart  &step,
                    const VectorType &x,
                    VectorType       &v) const;

    /// The force and its Jacobian of one body's step.
    struct BodyStep
    {
      Vector3 force;
      Matrix3 jacobian;
    };

    /// A force on the rows of x_j and v, and its Jacobian with respect to
    /// (Delta x_j, v).
    struct CentreStep
    {
      Eigen::Matrix<double, 6, 1> force;
      Eigen::Matrix<double, 6, 6> jacobian;
    };

    /**
     * (F_c, g) and its Jacobian for a centre of mass @p m at @p r_n from
     * the vertex, moving at @p vc_n at the start of the step of length
     * @p h, with the vertex's increment @p dx and the rotation's @p v.
     */
    static CentreStep
    centre_force(double         m,
                 const Vector3 &r_n,
                 const Vector3 &vc_n,
                 const Vector3 &dx,
                 const Vector3 &v,
                 double         h);

    /**
     * f(v) and df/dv of the step with increment @p v of length @p h from
     * the inertia @p J_n and the angular momentum @p pi_n at its start.
     */
    static BodyStep
    step_force(const Matrix3 &J_n,
               const Vector3 &pi_n,
               const Vector3 &v,
               double         h);

  private:
    /// The force of body number @p b over @p step to @p y, less what M
    /// carries, on its rows (x_j, v).
    CentreStep
    body_step(unsigned int b, const StepStart &step, const VectorType &y) const;

    /// The centre's velocity at the end of the step to @p x of body @p b
    /// with a free vertex, from @p v, the midpoint rule's velocity.
    Vector3
    centre_velocity(unsigned int      b,
                    const StepStart  &step,
                    const VectorType &x,
                    const VectorType &v) const;

    /// Per body: whether this process computes it (each body on one
    /// process: the owner of its rotation's first DoF).
    const std::vector<bool> &
    bodies_here() const;

    /// The velocity of body @p b's rows (x_j, v) at the end of the step
    /// to @p x, from the midpoint rule's @p v (turn_velocities()).
    Eigen::Matrix<double, 6, 1>
    turned_velocity(unsigned int      b,
                    const StepStart  &step,
                    const VectorType &x,
                    const VectorType &v) const;

    /// W of every body: W(c, k) = (M e_c) at component k of x_j, e_c one
    /// on the position DoFs along c, the weight of the row velocity in the
    /// linear momentum sum over the rows of M v (m I + the rods' mass at
    /// the vertex). Collective; computed at the first call.
    void
    compute_momentum_weights() const;

    const SolvableModel         &model;
    const MatrixType            &mass;
    std::vector<TensorBody>      bodies;
    mutable std::vector<Matrix3> weights;
    mutable std::vector<bool>    here;
    /// Per body: whether its centre is off the vertex and the vertex held,
    /// so that it turns about the vertex.
    std::vector<bool> turns_about_vertex;
  };

  /**
   * Throws std::invalid_argument naming the first body of @p model that
   * turns with its junction (an inertia tensor, a centre off the vertex)
   * if @p scheme is dynamic and cannot carry it (it is not the midpoint
   * rule), or whose centre is off a vertex held in part or moving in time.
   */
  void
  check_tensor_bodies(const SolvableModel     &model,
                      const IntegrationScheme &scheme);
} // namespace rodnet

#endif
