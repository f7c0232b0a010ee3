// The gyroscopic force of the sections' spin on the centreline under the
// midpoint rule (solvers/time/gyroscopic_coupling.h).
#include <core/every_entry.h>
#include <core/mass_matrix.h>
#include <elements/quaternion.h>
#include <solvers/time/gyroscopic_coupling.h>

#include <Eigen/Dense>
#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <array>
#include <stdexcept>

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

    /// The place of entry (@p row, @p column) in the values of the
    /// compressed rows @p rows of @p m.
    int
    place_of(const Epetra_CrsMatrix &m,
             const int              *offsets,
             const int              *columns,
             const global_dof_index  row,
             const global_dof_index  column)
    {
      using Index         = dealii::TrilinosWrappers::types::int_type;
      const int local_row = m.LRID(Index(row));
      const int local_col = m.LCID(Index(column));
      if (local_row >= 0 && local_col >= 0)
        {
          const int *begin = columns + offsets[local_row];
          const int *end   = columns + offsets[local_row + 1];
          const int *found = std::find(begin, end, local_col);
          if (found != end)
            return found - columns;
        }
      throw std::logic_error("GyroscopicCoupling: the tangent's pattern "
                             "lacks a segment's coupling");
    }

    /// The place of an entry in a row of another process, which the
    /// matrix's buffer sends to its owner when compressed.
    constexpr int other_process_row = -2;
  } // namespace

  GyroscopicCoupling::GyroscopicCoupling(const SolvableModel &model,
                                         const MatrixType    &mass)
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
        s.dofs[6] = model.layout().twist_dof(stencil.cell);
        // On several processes each segment once: by its twist's owner.
        if (!adds_here(mass, s.dofs[6]))
          continue;
        s.vertices = stencil.vertices;
        s.inertia  = mass.el(s.dofs[6], s.dofs[6]);
        if (s.inertia != 0)
          segments.push_back(s);
      }
  }

  GyroscopicCoupling::SegmentStep
  GyroscopicCoupling::step_of(const Segment   &s,
                              const DofValues &u_n,
                              const DofValues &y) const
  {
    // DofValues: read by global index without Trilinos' lookup of each.
    const Configuration &configuration = model.configuration();
    const auto           chord         = [&](const DofValues &x) {
      return Vector3(configuration.position(x, s.vertices[1]) -
                     configuration.position(x, s.vertices[0]));
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
    // The vertices of a segment may be another process's: read from
    // replicas, added through the vector's buffer of other rows.
    const EveryEntry              every_start(u_n), every_end(y);
    const DofValues               start(*every_start), end(*every_end);
    std::vector<global_dof_index> rows;
    std::vector<double>           forces;
    for (const Segment &s : segments)
      {
        const SegmentStep step = step_of(s, start, end);
        const Vector3     g =
          -s.inertia * step.twist / (h * h) * turn_direction(step);
        for (unsigned int i = 0; i < 6; ++i)
          {
            rows.push_back(s.dofs[i]);
            forces.push_back(i < 3 ? -g[i] : g[i - 3]);
          }
      }
    r.add(rows, forces);
    r.compress(dealii::VectorOperation::add);
  }

  void
  GyroscopicCoupling::place_entries(const Epetra_CrsMatrix &m)
  {
    CompressedRows rows;
    double        *values = nullptr;
    m.ExtractCrsDataPointers(rows.offsets, rows.columns, values);
    rows.matrix    = &m;
    rows.n_entries = m.NumMyNonzeros();
    if (rows == placed_rows)
      return;
    if (rows.offsets == nullptr)
      throw std::logic_error("GyroscopicCoupling: the tangent's storage is "
                             "not optimized (no compressed rows)");
    const dealii::AffineConstraints<double> &constraints = model.constraints();
    places.assign(segments.size(), {});
    for (std::size_t k = 0; k < segments.size(); ++k)
      for (unsigned int row = 0; row < 6; ++row)
        for (unsigned int col = 0; col < 7; ++col)
          {
            const global_dof_index r     = segments[k].dofs[row];
            const global_dof_index c     = segments[k].dofs[col];
            int                   &place = places[k][7 * row + col];
            place                        = -1;
            if (constraints.is_constrained(r) || constraints.is_constrained(c))
              continue;
            place = m.MyGRID(dealii::TrilinosWrappers::types::int_type(r)) ?
                      place_of(m, rows.offsets, rows.columns, r, c) :
                      other_process_row;
          }
    placed_rows = rows;
  }

  void
  GyroscopicCoupling::add_jacobian(const VectorType &u_n,
                                   const VectorType &y,
                                   const double      h,
                                   MatrixType       &k)
  {
    collect_segments();
    place_entries(k.trilinos_matrix());
    int             *offsets, *columns;
    double          *values;
    const EveryEntry every_start(u_n), every_end(y);
    const DofValues  start(*every_start), end(*every_end);
    k.trilinos_matrix().ExtractCrsDataPointers(offsets, columns, values);
    for (std::size_t n = 0; n < segments.size(); ++n)
      {
        const Segment    &s     = segments[n];
        const SegmentStep step  = step_of(s, start, end);
        const double      scale = -s.inertia / (h * h);
        // dg/de1 and dg/dtwist; e1 = x_end - x_start, and the rows of the
        // start vertex carry -g.
        const Eigen::Matrix3d chord_block =
          scale * step.twist * turn_direction_derivative(step);
        const Vector3 twist_column = scale * turn_direction(step);
        // Straight into the compressed rows, at the places found once per
        // pattern (free rows and columns only); zeros are not added, as
        // Trilinos' add() leaves them out.
        for (unsigned int row = 0; row < 6; ++row)
          {
            const double sign = row < 3 ? -1.0 : 1.0;
            for (unsigned int col = 0; col < 7; ++col)
              {
                const int    place = places[n][7 * row + col];
                const double value =
                  sign * (col == 6 ? twist_column[row % 3] :
                                     (col < 3 ? -1.0 : 1.0) *
                                       chord_block(row % 3, col % 3));
                if (place >= 0 && value != 0)
                  values[place] += value;
                else if (place == other_process_row && value != 0)
                  k.add(s.dofs[row], s.dofs[col], value);
              }
          }
      }
    k.compress(dealii::VectorOperation::add);
  }
} // namespace rodnet
