#ifndef RODNET_SOLVERS_BODY_ROTATION_INERTIA_H
#define RODNET_SOLVERS_BODY_ROTATION_INERTIA_H

#include <core/tensor_body_spin.h>
#include <solvers/integration_scheme.h>

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
   * The step starts from an increment q = (1, 0), as TimeIntegrator leaves
   * it (RodModel::reset_reference()).
   */
  class BodyRotationInertia
  {
  public:
    /// @p model must be finalized and outlive this object.
    explicit BodyRotationInertia(const RodModel &model);

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
    /// The BodyStep of @p body over @p step to @p y.
    BodyStep
    body_step(const TensorBody &body,
              const StepStart  &step,
              const VectorType &y) const;

    const RodModel         &model;
    std::vector<TensorBody> bodies;
  };

  /**
   * Throws std::invalid_argument naming the first body of @p model with an
   * inertia tensor if @p scheme is dynamic and cannot carry it (it is not
   * the midpoint rule).
   */
  void
  check_tensor_bodies(const RodModel &model, const IntegrationScheme &scheme);
} // namespace rodnet

#endif
