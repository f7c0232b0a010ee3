// The gyroscopic force of the sections' spin on the centreline under the
// midpoint rule (solvers/gyroscopic_coupling.h).
#include <elements/quaternion.h>
#include <solvers/gyroscopic_coupling.h>

#include <Eigen/Dense>
#include <array>

namespace rodnet
{
  namespace
  {
    /// q = (e_m x dt) / |e_m|^2, g = -J twist / h^2 q.
    Vector3
    turn_direction(const GyroscopicCoupling::SegmentStep &s)
    {
      const Vector3 em = (s.e0 + s.e1) / 2;
      const Vector3 dt = s.e1.normalized() - s.e0.normalized();
      return em.cross(dt) / em.squaredNorm();
    }

    /// dq/de1: with a = e_m, b = dt, s = |a|^2,
    /// d(a x b) = -[b]_x da + [a]_x db, da = de1 / 2,
    /// db = (I - t t^T) de1 / |e1|, ds = a . de1.
    Eigen::Matrix3d
    turn_direction_derivative(const GyroscopicCoupling::SegmentStep &s)
    {
      const Vector3         a = (s.e0 + s.e1) / 2;
      const Vector3         t = s.e1.normalized();
      const Vector3         b = t - s.e0.normalized();
      const double          n = a.squaredNorm();
      const Eigen::Matrix3d projection =
        (Eigen::Matrix3d::Identity() - t * t.transpose()) / s.e1.norm();
      const Eigen::Matrix3d cross =
        -cross_matrix(b) / 2 + cross_matrix(a) * projection;
      return cross / n - a.cross(b) * a.transpose() / (n * n);
    }
  } // namespace

  GyroscopicCoupling::GyroscopicCoupling(const RodModel   &model,
                                         const MatrixType &mass)
      : model(model)
      , mass(mass)
  {
  }

  void
  GyroscopicCoupling::collect_segments()
  {
    if (collected)
      return;
    collected = true;
    for (const SegmentStencil &stencil : model.layout().segments())
      {
        Segment s;
        for (unsigned int i = 0; i < 6; ++i)
          s.dofs[i] = stencil.dofs[i];
        s.dofs[6]  = model.layout().twist_dof(stencil.cell);
        s.vertices = stencil.vertices;
        s.inertia  = mass.el(s.dofs[6], s.dofs[6]);
        if (s.inertia != 0)
          segments.push_back(s);
      }
  }

  GyroscopicCoupling::SegmentStep
  GyroscopicCoupling::step_of(const Segment    &s,
                              const VectorType &u_n,
                              const VectorType &y) const
  {
    const auto chord = [&](const VectorType &x) {
      return Vector3(model.position(x, s.vertices[1]) -
                     model.position(x, s.vertices[0]));
    };
    return {chord(u_n), chord(y), y[s.dofs[6]] - u_n[s.dofs[6]]};
  }

  void
  GyroscopicCoupling::add_force(const VectorType &u_n,
                                const VectorType &y,
                                const double      h,
                                VectorType       &r)
  {
    collect_segments();
    for (const Segment &s : segments)
      {
        const SegmentStep step = step_of(s, u_n, y);
        const Vector3     g =
          -s.inertia * step.twist / (h * h) * turn_direction(step);
        for (unsigned int c = 0; c < 3; ++c)
          {
            r[s.dofs[c]] -= g[c];
            r[s.dofs[3 + c]] += g[c];
          }
      }
    r.compress(dealii::VectorOperation::add);
  }

  void
  GyroscopicCoupling::add_jacobian(const VectorType &u_n,
                                   const VectorType &y,
                                   const double      h,
                                   MatrixType       &k)
  {
    collect_segments();
    const dealii::AffineConstraints<double> &constraints = model.constraints();
    for (const Segment &s : segments)
      {
        const SegmentStep step  = step_of(s, u_n, y);
        const double      scale = -s.inertia / (h * h);
        // dg/de1 and dg/dtwist; e1 = x_end - x_start, and the rows of the
        // start vertex carry -g.
        const Eigen::Matrix3d chord_block =
          scale * step.twist * turn_direction_derivative(step);
        const Vector3 twist_column = scale * turn_direction(step);
        // One row at a time (Trilinos adds a row's entries together),
        // the free columns only.
        std::array<global_dof_index, 7> columns;
        std::array<double, 7>           values;
        for (unsigned int row = 0; row < 6; ++row)
          {
            if (constraints.is_constrained(s.dofs[row]))
              continue;
            const double sign     = row < 3 ? -1.0 : 1.0;
            unsigned int n_values = 0;
            for (unsigned int col = 0; col < 7; ++col)
              if (!constraints.is_constrained(s.dofs[col]))
                {
                  columns[n_values] = s.dofs[col];
                  values[n_values++] =
                    sign * (col == 6 ? twist_column[row % 3] :
                                       (col < 3 ? -1.0 : 1.0) *
                                         chord_block(row % 3, col % 3));
                }
            k.add(s.dofs[row], n_values, columns.data(), values.data());
          }
      }
    k.compress(dealii::VectorOperation::add);
  }
} // namespace rodnet
