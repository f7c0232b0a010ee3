#ifndef RODNET_SOLVERS_TIME_MIDPOINT_SCHEME_H
#define RODNET_SOLVERS_TIME_MIDPOINT_SCHEME_H

#include <solvers/time/body_rotation_inertia.h>
#include <solvers/time/gyroscopic_coupling.h>
#include <solvers/time/integration_scheme.h>
#include <solvers/time/rigid_motion_split.h>

#include <limits>
#include <utility>

namespace rodnet
{
  /**
   * The implicit midpoint rule with Gonzalez's discrete gradient, second
   * order, conserving 1/2 v.Mv + Pi of elastic rods to the Newton
   * tolerance:
   *   2 M (u - u_n - h v_n) / h^2 + C (u - u_n) / h
   *     + gradbar Pi(u_n, u; lambda_{n+1/2}) = 0,
   *   gradbar = grad Pi(m) + (Pi(u) - Pi(u_n) - grad Pi(m).d) w / w.d,
   *   m = (u_n + u) / 2, d = u - u_n (free DoFs), v_{n+1} = 2 d / h - v_n,
   * w = M d_def, d_def the part of d M-orthogonal to the rigid motions of
   * the unsupported parts at m (RigidMotionSplit), so that the correction
   * has no resultant or moment: a free body keeps its linear momentum to
   * round-off (doc/dynamics.md). A nearly rigid step takes w = M d.
   * The residual also has the gyroscopic force of the sections' spin
   * (GyroscopicCoupling), which does no work and turns the spin with the
   * tangents, so that the angular momentum is kept with stocky sections,
   * and the inertia of rigid bodies with an inertia tensor
   * (BodyRotationInertia).
   * Its tangent has a dense rank-one part, which NewtonSolver handles by
   * Sherman-Morrison. Needs a stored energy. The damping acts at the
   * midpoint velocity (u - u_n)/h: the energy falls by exactly h vbar.C vbar
   * per step, the work of the damping force.
   */
  class MidpointScheme : public IntegrationScheme
  {
  public:
    explicit MidpointScheme(const StepSystem &system);

    std::string
    name() const override
    {
      return "midpoint";
    }

    bool
    carries_inertia_tensors() const override
    {
      return true;
    }

    /// The midpoint step's Jacobian is not symmetric (its rank-one part):
    /// no potential.
    bool
    has_incremental_potential() const override
    {
      return false;
    }

    /// grad Pi at the midpoint (the discrete gradient's correction has no
    /// fixed rows).
    std::vector<ForcePoint>
    force_points() const override
    {
      return {{0.5, 1}};
    }

    double
    load_time(const double start, const double end) const override
    {
      return start + (end - start) / 2;
    }

    double
    mass_coefficient(const double h) const override
    {
      return 2 / (h * h);
    }

    void
    set_up(const StepStart &step, NewtonSolver::Problem &problem) override;

    void
    finish(const StepStart &step, const VectorType &x, VectorType &v) override
    {
      second_order_velocity(step, x, v);
      body_rotation.turn_velocities(step, x, v);
    }

    double
    energy_at(const VectorType &x) const override
    {
      return residual_known && x == residual_point ?
               residual_energy :
               std::numeric_limits<double>::quiet_NaN();
    }

    /// grad Pi(@p x), which the tangent at @p x needs (Newton's first
    /// iterate, where the tolerance's scale is taken: modified Newton asks
    /// for no other tangent).
    const VectorType *
    shared_gradient(const VectorType &x) override;

  private:
    /// The discrete-gradient residual at @p y.
    void
    residual(const StepStart &step, const VectorType &y, VectorType &r);

    /// Its exact Jacobian at @p y into @p k, and the rank-one part.
    void
    tangent(const StepStart &step, const VectorType &y, MatrixType &k);

    /// m = (u_n + y) / 2 into point.
    void
    set_midpoint(const StepStart &step, const VectorType &y);

    /// Keeps grad Pi(m) of the residual at m = point for the tangent
    /// there, which then does not assemble it again.
    void
    keep_gradient(const VectorType &gradient);

    /// grad Pi and Pi at @p y into gradient_y and end_energy (one
    /// assembly), unless they are there for @p y already.
    void
    assemble_end(const StepStart &step, const VectorType &y);

    /// The correction coefficient and w.d at @p y, from the @p gradient at
    /// the midpoint and the @p energy at @p y; leaves d_f in difference,
    /// M d_f in mass_difference and the correction's direction w in
    /// direction.
    std::pair<double, double>
    correction_terms(const StepStart  &step,
                     const VectorType &y,
                     const VectorType &gradient,
                     double            energy);

    /**
     * w = M d_def is used where w.d = |d_def|_M^2 exceeds this fraction of
     * d_f.M d_f, else w = M d_f: a step that is a rigid motion but for
     * rounding (a free translation: 1e-32) has no deformation to carry
     * the correction, and c = change / (w.d) would divide rounding by
     * rounding.
     */
    static constexpr double rigid_step_limit = 1e-12;

    /// K(m) d_h / 2 on the free rows into held_product, d_h the step of
    /// the held DoFs (zero unless a support moves), with the unconstrained
    /// tangent at m = point assembled into @p k for it.
    void
    held_columns_product(const StepStart  &step,
                         const VectorType &y,
                         MatrixType       &k);

    /// Pi(u_n) of the step.
    double           start_energy = 0;
    RigidMotionSplit rigid_split;
    /// The spin's force on the centreline (the twist rows' inertia).
    GyroscopicCoupling gyroscopic;
    /// The inertia of rigid bodies with an inertia tensor.
    BodyRotationInertia body_rotation;
    VectorType point, gradient_m, gradient_y, mass_difference, direction;
    VectorType rank_one_a, rank_one_b;
    /// d_h and K(m) d_h / 2 (held_columns_product()).
    VectorType held_difference, held_product;
    /// The midpoint of gradient_m, where gradient_known (this step's).
    VectorType gradient_point;
    bool       gradient_known = false;
    /// The iterate of gradient_y and of Pi there, end_energy, where
    /// end_known (this step's).
    VectorType end_point;
    double     end_energy = 0;
    bool       end_known  = false;
    /// The iterate of the last residual and Pi there, where
    /// residual_known (this step's).
    VectorType residual_point;
    double     residual_energy = 0;
    bool       residual_known  = false;
    /// The step of the last set_up().
    const StepStart *current_step = nullptr;
  };
} // namespace rodnet

#endif
