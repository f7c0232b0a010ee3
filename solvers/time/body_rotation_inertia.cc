// The inertia of rigid bodies that turn with their junction under the
// midpoint rule (solvers/time/body_rotation_inertia.h).
#include <core/every_entry.h>
#include <core/mass_matrix.h>
#include <elements/quaternion.h>
#include <solvers/time/body_rotation_inertia.h>

#include <stdexcept>
#include <string>

namespace rodnet
{
  namespace
  {
    /// How many of the position DoFs of @p body's vertex @p constraints
    /// hold.
    unsigned int
    n_held_positions(const dealii::AffineConstraints<double> &constraints,
                     const TensorBody                        &body)
    {
      unsigned int n = 0;
      for (const global_dof_index dof : body.position)
        n += constraints.is_constrained(dof);
      return n;
    }

    /// A body's rows: x_j, then the vector part of q.
    std::array<global_dof_index, 6>
    body_rows(const TensorBody &body)
    {
      return {{body.position[0],
               body.position[1],
               body.position[2],
               body.dofs[0],
               body.dofs[1],
               body.dofs[2]}};
    }

    /// Entries of the rows of a set of bodies, for a vector's add() or
    /// set(), which send those of other processes' rows to their owners.
    struct BodyRowEntries
    {
      std::vector<global_dof_index> rows;
      std::vector<double>           values;

      /// Appends @p entries on the rows of @p body (body_rows()).
      void
      append(const TensorBody &body, const Eigen::Matrix<double, 6, 1> &entries)
      {
        const std::array<global_dof_index, 6> body_row = body_rows(body);
        rows.insert(rows.end(), body_row.begin(), body_row.end());
        values.insert(values.end(), entries.data(), entries.data() + 6);
      }
    };

    /// The rates of a body's rows at the start of a step, (base - u_n) / h,
    /// and their increments to y.
    struct RowMotion
    {
      Vector3 x_rate, a_rate, dx, v;
    };

    RowMotion
    row_motion(const TensorBody &body,
               const StepStart  &step,
               const VectorType &y)
    {
      RowMotion m;
      for (unsigned int c = 0; c < 3; ++c)
        {
          const global_dof_index x = body.position[c], a = body.dofs[c];
          m.x_rate[c] = (step.base[x] - step.u[x]) / step.h;
          m.a_rate[c] = (step.base[a] - step.u[a]) / step.h;
          m.dx[c]     = y[x] - step.u[x];
          m.v[c]      = y[a] - step.u[a];
        }
      return m;
    }

    /// C = cay(2 v), the rotation of q = (1, v).
    Matrix3
    cayley(const Vector3 &v)
    {
      return Quaternion(1, v[0], v[1], v[2]).normalized().toRotationMatrix();
    }
  } // namespace

  BodyRotationInertia::BodyRotationInertia(const SolvableModel &model,
                                           const MatrixType    &mass)
      : model(model)
      , mass(mass)
      , bodies(tensor_bodies(model))
  {
    for (const TensorBody &body : bodies)
      turns_about_vertex.push_back(
        body.offset != Vector3::Zero() &&
        n_held_positions(model.constraints(), body) == 3);
  }

  BodyRotationInertia::BodyStep
  BodyRotationInertia::step_force(const Matrix3 &J_n,
                                  const Vector3 &pi_n,
                                  const Vector3 &v,
                                  const double   h)
  {
    // C = cay(2 v), the rotation of q = (1, v); pi_{n+1} = C p.
    const Matrix3 C    = cayley(v);
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

  BodyRotationInertia::CentreStep
  BodyRotationInertia::centre_force(const double   m,
                                    const Vector3 &r_n,
                                    const Vector3 &vc_n,
                                    const Vector3 &dx,
                                    const Vector3 &v,
                                    const double   h)
  {
    const Matrix3 I = Matrix3::Identity(), C = cayley(v);
    const double  k = 2 * m / (h * h), n = 1 + v.squaredNorm();
    // F_c = m (vc_{n+1} - vc_n) / h, vc_{n+1} = 2 Delta x_c / h - vc_n.
    const Vector3 F = k * (dx + C * r_n - r_n - h * vc_n);
    // d(C r)/dv = -(I + C) / 2 [r + C r]_x: (I - [v]_x)^{-1} = (I + C) / 2.
    const Matrix3 dF_dv = -k * (I + C) / 2 * cross_matrix(r_n + C * r_n);
    // g = B^T (r_m x F): the moment of F_c about the vertex at the
    // midpoint arm r_m = (1 + |v|^2 / 4) (r_n + v x r_n) / (1 + |v|^2),
    // mapped to the rows of v as the midpoint's gradients are, B^T =
    // 2 (I - [v / 2]_x) / (1 + |v|^2 / 4); then g . v = F . (C - I) r_n.
    const Matrix3 P   = I - cross_matrix(v / 2);
    const Vector3 arm = r_n + v.cross(r_n), s = arm.cross(F);
    const Matrix3 L = 2 / n * P * cross_matrix(arm);
    const Matrix3 dg_dv_at_F =
      2 / n * (cross_matrix(s) / 2 + P * cross_matrix(F) * cross_matrix(r_n)) -
      4 / (n * n) * P * s * v.transpose();
    CentreStep step;
    step.force << F, 2 / n * P * s;
    step.jacobian << k * I, dF_dv, L * k, L * dF_dv + dg_dv_at_F;
    return step;
  }

  BodyRotationInertia::CentreStep
  BodyRotationInertia::body_step(const unsigned int b,
                                 const StepStart   &step,
                                 const VectorType  &y) const
  {
    const TensorBody &body = bodies[b];
    const RowMotion   m    = row_motion(body, step, y);
    const double      h    = step.h;
    const Matrix3     R =
      model.junction_rotation(step.u, body.junction).toRotationMatrix();
    // About the centre, or about the held vertex the body turns about.
    const Matrix3 J_n =
      R * (turns_about_vertex[b] ? body.vertex_inertia : body.inertia) *
      R.transpose();
    const Vector3  omega = 2 * m.a_rate;
    const BodyStep turn  = step_force(J_n, J_n * omega, m.v, h);
    CentreStep     s;
    s.force.setZero();
    s.jacobian.setZero();
    // Less the isotropic part that M carries, (2 / h^2) 4 j (v - h rate).
    const double k    = 8 * body.isotropic / (h * h);
    s.force.tail<3>() = turn.force - k * (m.v - h * m.a_rate);
    s.jacobian.bottomRightCorner<3, 3>() =
      turn.jacobian - k * Matrix3::Identity();
    if (turns_about_vertex[b])
      return s;
    const Vector3    r_n = R * body.offset;
    const CentreStep centre =
      centre_force(body.mass, r_n, m.x_rate + omega.cross(r_n), m.dx, m.v, h);
    // Less M's m (2 / h^2)(Delta x_j - h xdot_{j,n}) on x_j.
    const double k_x = 2 * body.mass / (h * h);
    s.force += centre.force;
    s.force.head<3>() -= k_x * (m.dx - h * m.x_rate);
    s.jacobian += centre.jacobian;
    s.jacobian.topLeftCorner<3, 3>() -= k_x * Matrix3::Identity();
    return s;
  }

  const std::vector<bool> &
  BodyRotationInertia::bodies_here() const
  {
    // On several processes each body once: by the owner of its rotation's
    // first DoF (the mass matrix's rows are laid out by then).
    if (here.size() != bodies.size())
      for (const TensorBody &body : bodies)
        here.push_back(adds_here(mass, body.dofs[0]));
    return here;
  }

  void
  BodyRotationInertia::add_force(const StepStart  &step,
                                 const VectorType &y,
                                 VectorType       &r) const
  {
    if (bodies.empty())
      {
        r.compress(dealii::VectorOperation::add);
        return;
      }
    // A body's rows and its junction's rotation may be other processes':
    // read from replicas, added through the vector's buffer of other rows.
    const EveryEntry start(step.u), base(step.base), end(y);
    const StepStart  every{*start, *base, step.h, step.load_factor};
    BodyRowEntries   forces;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies_here()[b])
        forces.append(bodies[b], body_step(b, every, *end).force);
    r.add(forces.rows, forces.values);
    r.compress(dealii::VectorOperation::add);
  }

  void
  BodyRotationInertia::add_jacobian(const StepStart  &step,
                                    const VectorType &y,
                                    MatrixType       &k) const
  {
    if (bodies.empty())
      {
        k.compress(dealii::VectorOperation::add);
        return;
      }
    // Replicas as in add_force(); the matrix sends the rows of other
    // processes to their owners when compressed.
    const dealii::AffineConstraints<double> &constraints = model.constraints();
    const EveryEntry start(step.u), base(step.base), end(y);
    const StepStart  every{*start, *base, step.h, step.load_factor};
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        if (!bodies_here()[b])
          continue;
        const auto jacobian = body_step(b, every, *end).jacobian;
        const std::array<global_dof_index, 6> rows = body_rows(bodies[b]);
        for (unsigned int row = 0; row < 6; ++row)
          {
            if (constraints.is_constrained(rows[row]))
              continue;
            std::array<global_dof_index, 6> columns;
            std::array<double, 6>           values;
            unsigned int                    n_values = 0;
            for (unsigned int col = 0; col < 6; ++col)
              if (!constraints.is_constrained(rows[col]) &&
                  jacobian(row, col) != 0)
                {
                  columns[n_values]  = rows[col];
                  values[n_values++] = jacobian(row, col);
                }
            k.add(rows[row], n_values, columns.data(), values.data());
          }
      }
    k.compress(dealii::VectorOperation::add);
  }

  Vector3
  BodyRotationInertia::centre_velocity(const unsigned int b,
                                       const StepStart   &step,
                                       const VectorType  &x,
                                       const VectorType  &v) const
  {
    // vc_{n+1} = 2 (Delta x_j + (C - I) r_n) / h - vc_n, and v's rows of
    // x_j hold 2 Delta x_j / h - xdot_{j,n}.
    const TensorBody &body = bodies[b];
    const RowMotion   m    = row_motion(body, step, x);
    const Vector3     r_n =
      model.junction_rotation(step.u, body.junction) * body.offset;
    Vector3 midpoint;
    for (unsigned int c = 0; c < 3; ++c)
      midpoint[c] = v[body.position[c]];
    return midpoint + 2 * (cayley(m.v) * r_n - r_n) / step.h -
           (2 * m.a_rate).cross(r_n);
  }

  void
  BodyRotationInertia::turn_velocities(const StepStart  &step,
                                       const VectorType &x,
                                       VectorType       &v) const
  {
    if (bodies.empty())
      {
        v.compress(dealii::VectorOperation::insert);
        return;
      }
    compute_momentum_weights();
    // Read from replicas, the rows of other processes set through the
    // vector's buffer.
    const EveryEntry start(step.u), base(step.base), end(x), rates(v);
    const StepStart  every{*start, *base, step.h, step.load_factor};
    BodyRowEntries   turned;
    for (unsigned int b = 0; b < bodies.size(); ++b)
      if (bodies_here()[b])
        turned.append(bodies[b], turned_velocity(b, every, *end, *rates));
    v.set(turned.rows, turned.values);
    v.compress(dealii::VectorOperation::insert);
  }

  Eigen::Matrix<double, 6, 1>
  BodyRotationInertia::turned_velocity(const unsigned int b,
                                       const StepStart   &step,
                                       const VectorType  &x,
                                       const VectorType  &v) const
  {
    const TensorBody           &body = bodies[b];
    const RowMotion             m    = row_motion(body, step, x);
    const Matrix3               C    = cayley(m.v);
    Eigen::Matrix<double, 6, 1> turned;
    Vector3                     rate, midpoint;
    for (unsigned int c = 0; c < 3; ++c)
      {
        rate[c]     = v[body.dofs[c]];
        midpoint[c] = v[body.position[c]];
      }
    rate = C * rate;
    turned << midpoint, rate;
    if (!turns_about_vertex[b] && body.offset != Vector3::Zero())
      {
        // The body's xdot_j = vc_{n+1} - omega_{n+1} x r_{n+1}, omega =
        // 2 rate, against the midpoint rule's of the rows: W (w -
        // midpoint) = m (xdot_j - midpoint) keeps the momentum.
        const Vector3 r_next =
          C * (model.junction_rotation(step.u, body.junction) * body.offset);
        const Vector3 x_rate =
          centre_velocity(b, step, x, v) - (2 * rate).cross(r_next);
        turned.head<3>() =
          midpoint + weights[b].inverse() * body.mass * (x_rate - midpoint);
      }
    return turned;
  }

  void
  BodyRotationInertia::compute_momentum_weights() const
  {
    // Collective (a product with the distributed mass matrix), on every
    // process alike: at the first turn, when M is assembled.
    if (!weights.empty())
      return;
    weights.assign(bodies.size(), Matrix3::Zero());
    VectorType along = model.create_vector(), product = along;
    for (unsigned int c = 0; c < 3; ++c)
      {
        along = 0;
        for (unsigned int i = 0; i < model.network().n_vertices(); ++i)
          if (const global_dof_index d = model.layout().vertex_dof(i, c);
              along.in_local_range(d))
            along[d] = 1;
        mass.vmult(product, along);
        const EveryEntry every(product);
        for (unsigned int k = 0; k < bodies.size(); ++k)
          for (unsigned int d = 0; d < 3; ++d)
            weights[k](c, d) = (*every)[bodies[k].position[d]];
      }
  }

  void
  check_tensor_bodies(const SolvableModel     &model,
                      const IntegrationScheme &scheme)
  {
    if (!scheme.dynamic())
      return;
    const std::vector<TensorBody> bodies = tensor_bodies(model);
    for (const RigidBody &body : model.rigid_bodies())
      if (body.turns_with_junction() && !scheme.carries_inertia_tensors())
        throw std::invalid_argument(
          body.where + ": " +
          (body.has_inertia_tensor() ? "a general inertia tensor" :
                                       "a centre off the vertex") +
          " turns with the body, and only the midpoint rule carries it (its "
          "force depends on the orientation, not on the constant mass "
          "matrix); the " +
          scheme.name() + " integrator does not: use Integrator = midpoint");
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const unsigned int held =
          n_held_positions(model.constraints(), bodies[b]);
        if (bodies[b].offset == Vector3::Zero() ||
            (held == 0 || (held == 3 && !model.moves_supports_in_time())))
          continue;
        throw std::invalid_argument(
          model.rigid_bodies()[bodies[b].index].where + ": its centre is off " +
          model.network().describe_vertex(bodies[b].vertex) +
          (held == 3 ? ", which is held while supports move in time" :
                       ", which is held in part") +
          "; a centre off the vertex is represented at a free vertex or at "
          "one held fixed");
      }
  }

} // namespace rodnet
