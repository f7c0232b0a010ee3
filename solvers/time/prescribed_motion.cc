#include <solvers/time/prescribed_motion.h>

namespace rodnet
{
  void
  set_prescribed_velocity(const SolvableModel                 &model,
                          const std::function<double(double)> &load_factor,
                          const double                         time,
                          const double                         time_scale,
                          const VectorType                    &u,
                          VectorType                          &v)
  {
    const double e = 1e-4 * time_scale;
    // u at t, t + e, t + 2 e: the free rows are those of u in all three.
    std::array<VectorType, 3> at;
    for (unsigned int k = 0; k < 3; ++k)
      {
        at[k] = u;
        model.apply_boundary_values(at[k],
                                    load_factor(time + k * e),
                                    time + k * e);
      }
    const dealii::AffineConstraints<double> &constraints = model.constraints();
    for (const auto i : v.locally_owned_elements())
      if (constraints.is_constrained(i))
        v[i] = (-3 * at[0][i] + 4 * at[1][i] - at[2][i]) / (2 * e);
    v.compress(dealii::VectorOperation::insert);
  }
} // namespace rodnet
