// The inertia of rigid bodies with a general inertia tensor under the
// midpoint rule (solvers/body_rotation_inertia.h).
#include <elements/quaternion.h>
#include <solvers/body_rotation_inertia.h>

#include <Eigen/Dense>
#include <stdexcept>

namespace rodnet
{
  BodyRotationInertia::BodyRotationInertia(const RodModel &model)
      : model(model)
      , bodies(tensor_bodies(model))
  {
  }

  BodyRotationInertia::BodyStep
  BodyRotationInertia::step_force(const Matrix3 &J_n,
                                  const Vector3 &pi_n,
                                  const Vector3 &v,
                                  const double   h)
  {
    // C = cay(2 v), the rotation of q = (1, v); pi_{n+1} = C p.
    const Matrix3 C =
      Quaternion(1, v[0], v[1], v[2]).normalized().toRotationMatrix();
    const Vector3 p    = 4 / h * J_n * v - pi_n;
    const Vector3 next = C * p;
    const Vector3 D    = next - pi_n;
    const Matrix3 turn = Matrix3::Identity() - cross_matrix(v / 2);
    // d(C p)/dv at fixed p: from (I - [v]_x) C p = (I + [v]_x) p,
    // (I - [v]_x) d(C p) = -[p + C p]_x dv.
    const Matrix3 dD = -(Matrix3::Identity() - cross_matrix(v)).inverse() *
                         cross_matrix(p + next) +
                       4 / h * C * J_n;
    return {2 / h * turn * D, 2 / h * (turn * dD + cross_matrix(D) / 2)};
  }

  BodyRotationInertia::BodyStep
  BodyRotationInertia::body_step(const TensorBody &body,
                                 const StepStart  &step,
                                 const VectorType &y) const
  {
    // The rate of v at the start, (base - u_n) / h, and the increment.
    Vector3 rate, v;
    for (unsigned int c = 0; c < 3; ++c)
      {
        rate[c] = (step.base[body.dofs[c]] - step.u[body.dofs[c]]) / step.h;
        v[c]    = y[body.dofs[c]] - step.u[body.dofs[c]];
      }
    const Matrix3 J_n   = spatial_inertia(model, body, step.u);
    const Vector3 omega = 2 * rate;
    BodyStep      s     = step_force(J_n, J_n * omega, v, step.h);
    // Less the isotropic part that M carries, (2 / h^2) 4 j (v - h rate).
    const double h = step.h;
    s.force -= 8 * body.isotropic / (h * h) * (v - h * rate);
    s.jacobian -= 8 * body.isotropic / (h * h) * Matrix3::Identity();
    return s;
  }

  void
  BodyRotationInertia::add_force(const StepStart  &step,
                                 const VectorType &y,
                                 VectorType       &r) const
  {
    for (const TensorBody &body : bodies)
      {
        const Vector3 f = body_step(body, step, y).force;
        for (unsigned int c = 0; c < 3; ++c)
          r[body.dofs[c]] += f[c];
      }
    r.compress(dealii::VectorOperation::add);
  }

  void
  BodyRotationInertia::add_jacobian(const StepStart  &step,
                                    const VectorType &y,
                                    MatrixType       &k) const
  {
    const dealii::AffineConstraints<double> &constraints = model.constraints();
    for (const TensorBody &body : bodies)
      {
        const Matrix3 jacobian = body_step(body, step, y).jacobian;
        for (unsigned int row = 0; row < 3; ++row)
          {
            if (constraints.is_constrained(body.dofs[row]))
              continue;
            std::array<global_dof_index, 3> columns;
            std::array<double, 3>           values;
            unsigned int                    n_values = 0;
            for (unsigned int col = 0; col < 3; ++col)
              if (!constraints.is_constrained(body.dofs[col]))
                {
                  columns[n_values]  = body.dofs[col];
                  values[n_values++] = jacobian(row, col);
                }
            k.add(body.dofs[row], n_values, columns.data(), values.data());
          }
      }
    k.compress(dealii::VectorOperation::add);
  }

  void
  BodyRotationInertia::turn_velocities(const StepStart  &step,
                                       const VectorType &x,
                                       VectorType       &v) const
  {
    for (const TensorBody &body : bodies)
      {
        Vector3 rate, a;
        for (unsigned int c = 0; c < 3; ++c)
          {
            rate[c] = v[body.dofs[c]];
            a[c]    = x[body.dofs[c]] - step.u[body.dofs[c]];
          }
        rate = Quaternion(1, a[0], a[1], a[2]).normalized() * rate;
        for (unsigned int c = 0; c < 3; ++c)
          v[body.dofs[c]] = rate[c];
      }
    v.compress(dealii::VectorOperation::insert);
  }

  void
  check_tensor_bodies(const RodModel &model, const IntegrationScheme &scheme)
  {
    if (!scheme.dynamic() || scheme.carries_inertia_tensors())
      return;
    for (const RigidBody &body : model.rigid_bodies())
      if (body.has_inertia_tensor())
        throw std::invalid_argument(
          body.where +
          ": a general inertia tensor turns with the body, and only the "
          "midpoint rule carries it (its force depends on the orientation, "
          "not on the constant mass matrix); the " +
          scheme.name() + " integrator does not: use Integrator = midpoint");
  }
} // namespace rodnet
