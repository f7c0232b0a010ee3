#ifndef RODNET_SOLVERS_TIME_GENERALIZED_ALPHA_SCHEME_H
#define RODNET_SOLVERS_TIME_GENERALIZED_ALPHA_SCHEME_H

#include <solvers/time/integration_scheme.h>

namespace rodnet
{
  /**
   * Chung & Hulbert's generalized-alpha method (J. Appl. Mech. 60, 1993),
   * second order with a numerical dissipation of the high frequencies set
   * by the spectral radius rho_inf of the step at omega h -> infinity
   * (StepSystem::spectral_radius_at_infinity, in [0, 1]):
   *   alpha_m = (2 rho_inf - 1) / (rho_inf + 1),
   *   alpha_f = rho_inf / (rho_inf + 1),
   *   gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2 / 4.
   * In the form of Arnold & Bruls (Multibody Syst. Dyn. 18, 2007), whose
   * equation of motion holds at the end of the step, with the inertial
   * force p = M qddot carried as Newmark carries it (so that the massless
   * rows of junction quaternions never need an acceleration) and a
   * pseudo-acceleration a per DoF:
   *   u = u_n + h v_n + h^2 ((1/2 - beta) a_n + beta a),
   *   v = v_n + h ((1 - gamma) a_n + gamma a),
   *   (1 - alpha_m) M a + alpha_m M a_n = (1 - alpha_f) p + alpha_f p_n,
   *   p + C v + grad Pi(u, lambda_{n+1}) = 0.
   * Eliminating a, v and p gives the step's equation
   *   c M (u - u_n - h v_n) - e_n + C v + grad Pi(u, lambda_{n+1}) = 0,
   *   c = (1 - alpha_m) / ((1 - alpha_f) beta h^2),
   *   e_n = [((1 - alpha_m)(1/2 - beta)/beta - alpha_m) M a_n
   *          + alpha_f p_n] / (1 - alpha_f),
   * the minimum of an incremental potential as Newmark's (history
   * materials are allowed). For linear systems it is Chung & Hulbert's
   * method with averaged forces. rho_inf = 1 gives alpha_m = alpha_f = 1/2,
   * gamma = 1/2, beta = 1/4: c = 4/h^2, e_n = p_n, exactly NewmarkScheme.
   */
  class GeneralizedAlphaScheme : public IntegrationScheme
  {
  public:
    /// Throws std::invalid_argument for a spectral radius of @p system
    /// outside [0, 1].
    explicit GeneralizedAlphaScheme(const StepSystem &system);

    std::string
    name() const override
    {
      return "generalized alpha";
    }

    /**
     * No: the method overshoots in velocity: the energy of a displaced
     * stiff mode grows for a few steps before it decays by rho_inf^2 per
     * step (x4.9 over 4 steps at omega h = 100, x420 at 1000, rho_inf =
     * 0.8, from rest with a_0 = -omega^2 q_0; doc/dynamics.md), which the
     * energy watch
     * would stop as an instability. A run that diverges still stops, at a
     * failed Newton solve or a state that is not finite.
     */
    bool
    energy_never_grows() const override
    {
      return false;
    }

    double
    mass_coefficient(const double h) const override
    {
      return (1 - alpha_m) / ((1 - alpha_f) * beta * h * h);
    }

    /// C v at v = v_n + h ((1 - gamma) a_n + gamma a) with a from u:
    /// v = gamma/(beta h) (u - u_n) + (1 - gamma/beta) v_n
    ///     + h (1 - gamma/(2 beta)) a_n; the last term is a constant force
    /// that set_up() adds to e_n.
    DampingVelocity
    damping_velocity(const double h) const override
    {
      return {gamma / (beta * h), gamma / beta - 1};
    }

    /// p_0 = lambda f - grad W - C v_0 on the rows that carry mass, as
    /// Newmark's, and a_0 the acceleration M a_0 = p_0 (zero on the held
    /// and massless rows).
    void
    start(const VectorType &u,
          const VectorType &v,
          double            load_factor) override;

    /// e_n with the damping's constant force for the step's length, then
    /// IntegrationScheme::set_up().
    void
    set_up(const StepStart &step, NewtonSolver::Problem &problem) override;

    void
    finish(const StepStart &step, const VectorType &x, VectorType &v) override;

  protected:
    const VectorType *
    extra_inertial_force() const override
    {
      return &extra_force;
    }

  private:
    /// The inertial part of e_n from a_n and p_n.
    void
    update_inertial_extra();

    /// Solves M a = @p force over the free rows that carry mass.
    void
    solve_acceleration(const VectorType &force, VectorType &a) const;

    double alpha_m, alpha_f, gamma, beta;
    /// p_n = M qddot_n and the pseudo-acceleration a_n.
    VectorType inertial_force, acceleration;
    /// The inertial part of e_n, and e_n with the damping's constant force.
    VectorType inertial_extra, extra_force;
  };
} // namespace rodnet

#endif
