// The reaction of the inertia of tensor bodies at held junction rotations
// (solvers/time/tensor_body_support_work.h).
#include <solvers/time/body_rotation_inertia.h>
#include <solvers/time/tensor_body_support_work.h>

namespace rodnet
{
  std::vector<std::pair<global_dof_index, double>>
  tensor_body_reaction(const SolvableModel           &model,
                       const std::vector<TensorBody> &bodies,
                       const std::vector<bool>       &fixed,
                       const VectorType              &u0,
                       const VectorType              &u1,
                       const VectorType              &v0,
                       const VectorType              &mass_change,
                       const double                   h)
  {
    std::vector<std::pair<global_dof_index, double>> reaction;
    for (const TensorBody &body : bodies)
      {
        if (!fixed[body.dofs[0]] && !fixed[body.dofs[1]] &&
            !fixed[body.dofs[2]])
          continue;
        // The step's increment and the angular velocity 2 adot at its
        // start (a = 0), as the scheme's step took them.
        Vector3 v, omega;
        for (unsigned int c = 0; c < 3; ++c)
          {
            v[c]     = u1[body.dofs[c]] - u0[body.dofs[c]];
            omega[c] = 2 * v0[body.dofs[c]];
          }
        const Matrix3 J_n = spatial_inertia(model, body, u0);
        const Vector3 force =
          BodyRotationInertia::step_force(J_n, J_n * omega, v, h).force;
        for (unsigned int c = 0; c < 3; ++c)
          if (fixed[body.dofs[c]])
            reaction.emplace_back(body.dofs[c],
                                  force[c] - mass_change[body.dofs[c]] / h);
      }
    return reaction;
  }
} // namespace rodnet
