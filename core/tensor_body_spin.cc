// The spin of rigid bodies that turn with a junction (core/tensor_body_spin.h).
#include <core/every_entry.h>
#include <core/tensor_body_spin.h>

namespace rodnet
{
  std::vector<TensorBody>
  tensor_bodies(const SolvableModel &model)
  {
    std::vector<TensorBody>       found;
    const std::vector<RigidBody> &all = model.rigid_bodies();
    for (unsigned int i = 0; i < all.size(); ++i)
      if (const RigidBody &body = all[i]; body.turns_with_junction())
        {
          // check_rigid_body() put the body on a junction with a rotation.
          const unsigned int v = std::get<unsigned int>(body.attachment);
          const unsigned int j = *model.network().junction_at(v);
          TensorBody         b{i,
                       j,
                       v,
                       {},
                       {},
                       body.centre_inertia(),
                       body.vertex_inertia(),
                       body.mass,
                       body.centre_offset,
                       body.isotropic_inertia()};
          for (unsigned int c = 0; c < 3; ++c)
            {
              b.dofs[c]     = model.layout().rotation_dof(j, c + 1);
              b.position[c] = model.layout().vertex_dof(v, c);
            }
          found.push_back(b);
        }
    return found;
  }

  Matrix3
  spatial_inertia(const SolvableModel &model,
                  const TensorBody    &body,
                  const VectorType    &u)
  {
    const Matrix3 R =
      model.junction_rotation(u, body.junction).toRotationMatrix();
    return R * body.inertia * R.transpose();
  }

  Vector3
  centre_arm(const SolvableModel &model,
             const TensorBody    &body,
             const VectorType    &u)
  {
    return model.junction_rotation(u, body.junction) * body.offset;
  }

  Vector3
  angular_velocity(const TensorBody &body,
                   const VectorType &u,
                   const VectorType &v)
  {
    Vector3 a, rate;
    for (unsigned int c = 0; c < 3; ++c)
      {
        a[c]    = u[body.dofs[c]];
        rate[c] = v[body.dofs[c]];
      }
    return 2 * (rate + a.cross(rate)) / (1 + a.squaredNorm());
  }

  BodySpin
  tensor_body_spin(const SolvableModel &model,
                   const VectorType    &u_distributed,
                   const VectorType    &v_distributed)
  {
    BodySpin                      spin;
    const std::vector<TensorBody> bodies = tensor_bodies(model);
    if (bodies.empty())
      return spin;
    // A body's DoFs may be other processes': every process reads replicas
    // and sums over every body (the same sum on each).
    const EveryEntry  every_u(u_distributed), every_v(v_distributed);
    const VectorType &u = *every_u, &v = *every_v;
    for (const TensorBody &body : bodies)
      {
        const Vector3 omega = angular_velocity(body, u, v);
        const Vector3 pi =
          spatial_inertia(model, body, u) * omega - body.isotropic * omega;
        Vector3 x_j_rate;
        for (unsigned int c = 0; c < 3; ++c)
          x_j_rate[c] = v[body.position[c]];
        const Vector3 arm      = centre_arm(model, body, u);
        const Vector3 x_j      = model.position(u, body.vertex);
        const Vector3 x_c_rate = x_j_rate + omega.cross(arm);
        const Vector3 p_c = body.mass * x_c_rate, p_j = body.mass * x_j_rate;
        spin.kinetic_energy +=
          omega.dot(pi) / 2 +
          body.mass * (x_c_rate.squaredNorm() - x_j_rate.squaredNorm()) / 2;
        spin.linear_momentum += p_c - p_j;
        spin.angular_momentum += pi + (x_j + arm).cross(p_c) - x_j.cross(p_j);
      }
    return spin;
  }
} // namespace rodnet
