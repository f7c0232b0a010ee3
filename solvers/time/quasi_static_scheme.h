#ifndef RODNET_SOLVERS_TIME_QUASI_STATIC_SCHEME_H
#define RODNET_SOLVERS_TIME_QUASI_STATIC_SCHEME_H

#include <solvers/time/integration_scheme.h>

namespace rodnet
{
  /// No inertia: grad Pi(u, lambda_{n+1}) = 0 at every time (creep,
  /// relaxation); v_{n+1} = (u - u_n) / h is reported.
  class QuasiStaticScheme : public IntegrationScheme
  {
  public:
    using IntegrationScheme::IntegrationScheme;

    std::string
    name() const override
    {
      return "quasi-static";
    }

    double
    mass_coefficient(double) const override
    {
      return 0;
    }

    void
    finish(const StepStart &step, const VectorType &x, VectorType &v) override
    {
      first_order_velocity(step, x, v);
    }
  };
} // namespace rodnet

#endif
