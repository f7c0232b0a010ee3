// The spin of rigid bodies with a general inertia tensor at junctions
// (core/tensor_body_spin.h).
#include <core/tensor_body_spin.h>

namespace rodnet
{
  std::vector<TensorBody>
  tensor_bodies(const RodModel &model)
  {
    std::vector<TensorBody> found;
    for (const RigidBody &body : model.rigid_bodies())
      if (body.has_inertia_tensor())
        {
          // check_rigid_body() put the body on a junction with a rotation.
          const unsigned int v = std::get<unsigned int>(body.attachment);
          const unsigned int j = *model.network().junction_at(v);
          TensorBody b{j, {}, body.inertia_tensor, body.isotropic_inertia()};
          for (unsigned int c = 0; c < 3; ++c)
            b.dofs[c] = model.layout().rotation_dof(j, c + 1);
          found.push_back(b);
        }
    return found;
  }

  Matrix3
  spatial_inertia(const RodModel   &model,
                  const TensorBody &body,
                  const VectorType &u)
  {
    const Matrix3 R =
      model.junction_rotation(u, body.junction).toRotationMatrix();
    return R * body.inertia * R.transpose();
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
  tensor_body_spin(const RodModel   &model,
                   const VectorType &u,
                   const VectorType &v)
  {
    BodySpin spin;
    for (const TensorBody &body : tensor_bodies(model))
      {
        const Vector3 omega = angular_velocity(body, u, v);
        const Vector3 pi =
          spatial_inertia(model, body, u) * omega - body.isotropic * omega;
        spin.kinetic_energy += omega.dot(pi) / 2;
        spin.angular_momentum += pi;
      }
    return spin;
  }
} // namespace rodnet
