#ifndef RODNET_SOLVERS_TIME_BACKWARD_EULER_SCHEME_H
#define RODNET_SOLVERS_TIME_BACKWARD_EULER_SCHEME_H

#include <solvers/time/integration_scheme.h>

namespace rodnet
{
  /// Backward Euler, first order and dissipative:
  /// M (u - u_n - h v_n) / h^2 + C (u - u_n) / h + grad Pi(u, lambda_{n+1})
  /// = 0,
  /// v_{n+1} = (u - u_n) / h.
  class BackwardEulerScheme : public IntegrationScheme
  {
  public:
    using IntegrationScheme::IntegrationScheme;

    std::string
    name() const override
    {
      return "backward euler";
    }

    double
    mass_coefficient(const double h) const override
    {
      return 1 / (h * h);
    }

    /// grad Pi at the step's end.
    std::vector<ForcePoint>
    force_points() const override
    {
      return {{1, 1}};
    }

    void
    finish(const StepStart &step, const VectorType &x, VectorType &v) override
    {
      first_order_velocity(step, x, v);
    }
  };
} // namespace rodnet

#endif
