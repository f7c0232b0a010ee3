#ifndef RODNET_SOLVERS_TIME_NEWMARK_SCHEME_H
#define RODNET_SOLVERS_TIME_NEWMARK_SCHEME_H

#include <solvers/time/integration_scheme.h>

namespace rodnet
{
  /**
   * Newmark's average acceleration (beta = 1/4, gamma = 1/2) in trapezoidal
   * form, second order without numerical dissipation, with the inertial
   * force p = M a carried from step to step:
   *   4 M (u - u_n - h v_n) / h^2 - p_n + C v_{n+1}
   *     + grad Pi(u, lambda_{n+1}) = 0,
   *   p_{n+1} = 4 M (u - u_n - h v_n) / h^2 - p_n,
   *   v_{n+1} = 2 (u - u_n) / h - v_n.
   */
  class NewmarkScheme : public IntegrationScheme
  {
  public:
    explicit NewmarkScheme(const StepSystem &system);

    std::string
    name() const override
    {
      return "newmark";
    }

    std::string
    instability_advice() const override
    {
      return " or the midpoint rule, which conserves energy";
    }

    double
    mass_coefficient(const double h) const override
    {
      return 4 / (h * h);
    }

    /// Damping at the end of the step: C v_{n+1}, v_{n+1} = 2 (u - u_n)/h
    /// - v_n, as the trapezoidal rule's equation of motion at t_{n+1}.
    DampingVelocity
    damping_velocity(const double h) const override
    {
      return {2 / h, 1};
    }

    /// p_0 = M a_0 = lambda f - grad W - C v_0: the out-of-balance force
    /// of the start, on the rows that carry mass.
    void
    start(const VectorType &u,
          const VectorType &v,
          double            load_factor) override;

    void
    finish(const StepStart &step, const VectorType &x, VectorType &v) override;

  protected:
    const VectorType *
    extra_inertial_force() const override
    {
      return &inertial_force;
    }

  private:
    /// p_n, with its sign in the residual reversed (subtracted).
    VectorType inertial_force;
  };
} // namespace rodnet

#endif
