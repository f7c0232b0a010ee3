#include <solvers/dof_roles.h>
#include <solvers/free_motions.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace rodnet
{
  namespace
  {
    using Kind = DofRoles::Kind;
    using Row  = Eigen::Matrix<double, 1, 6>;

    /// Connected parts: the rods joined through junctions, by union-find.
    std::vector<unsigned int>
    rod_parts(const RodNetwork &network)
    {
      std::vector<unsigned int> parent(network.rods().size());
      std::iota(parent.begin(), parent.end(), 0);
      const auto root = [&](unsigned int r) {
        while (parent[r] != r)
          r = parent[r] = parent[parent[r]];
        return r;
      };
      for (const Junction &j : network.junctions())
        for (const RodEnd &end : j.ends)
          parent[root(end.rod)] = root(j.ends.front().rod);
      std::vector<unsigned int> part(parent.size());
      for (unsigned int r = 0; r < parent.size(); ++r)
        part[r] = root(r);
      return part;
    }

    /// The upper triangle R of a QR factorization of the stacked rows,
    /// kept 6 x 6 however many rows come in, so that the small singular
    /// values of the constraint matrix stay accurate (A^T A would square
    /// them into rounding).
    class StackedRows
    {
    public:
      void
      add(const Row &row)
      {
        pending.push_back(row);
        if (pending.size() == 600)
          reduce();
      }

      /// Singular value decomposition of everything added.
      Eigen::JacobiSVD<Eigen::MatrixXd>
      svd()
      {
        reduce();
        return Eigen::JacobiSVD<Eigen::MatrixXd>(r, Eigen::ComputeFullV);
      }

    private:
      void
      reduce()
      {
        if (pending.empty())
          return;
        Eigen::MatrixXd stack(6 + pending.size(), 6);
        stack.topRows(6) = r;
        for (unsigned int k = 0; k < pending.size(); ++k)
          stack.row(6 + k) = pending[k];
        pending.clear();
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stack);
        r = qr.matrixQR().topRows(6).triangularView<Eigen::Upper>();
      }

      /// Zero rows until the first reduction: they change nothing.
      Eigen::MatrixXd  r = Eigen::MatrixXd::Zero(6, 6);
      std::vector<Row> pending;
    };

    std::string
    vector_text(Vector3 v)
    {
      // Directions read better with rounding noise and -0 cleaned up.
      for (unsigned int c = 0; c < 3; ++c)
        if (std::abs(v[c]) < 1e-9 * v.norm())
          v[c] = 0;
      char text[80];
      std::snprintf(text,
                    sizeof(text),
                    "(%.3g, %.3g, %.3g)",
                    v[0] + 0.0,
                    v[1] + 0.0,
                    v[2] + 0.0);
      return text;
    }

    std::string
    join_motions(const std::vector<std::string> &motions)
    {
      std::string text;
      for (unsigned int k = 0; k < motions.size(); ++k)
        text += (k == 0                  ? "" :
                 k + 1 == motions.size() ? " and " :
                                           ", ") +
                motions[k];
      return text;
    }

    /// "rod 0", "rods 0, 1 and 2", "rods 0, 1, 2, ... (40 rods)".
    std::string
    rods_text(const std::vector<unsigned int> &rods)
    {
      if (rods.size() == 1)
        return "rod " + std::to_string(rods[0]);
      std::vector<std::string> names;
      for (unsigned int k = 0; k < std::min<std::size_t>(rods.size(), 3); ++k)
        names.push_back(std::to_string(rods[k]));
      if (rods.size() > 3)
        return "rods " + names[0] + ", " + names[1] + ", " + names[2] +
               ", ... (" + std::to_string(rods.size()) + " rods)";
      return "rods " + join_motions(names);
    }

    /// Describes the free motions of one part from the null space
    /// (columns of @p basis: translation, then rotation times @p length)
    /// of its constraints, with @p center the centroid and @p held the
    /// positions of its fixed vertices (to name a point on an axis).
    std::vector<std::string>
    describe_motions(const Eigen::MatrixXd                              &basis,
                     const Vector3                                      &center,
                     const double                                        length,
                     const std::vector<std::pair<Vector3, std::string>> &held)
    {
      std::vector<std::string>                motions;
      const Eigen::MatrixXd                   t = basis.topRows(3);
      const Eigen::MatrixXd                   w = basis.bottomRows(3) / length;
      const Eigen::JacobiSVD<Eigen::MatrixXd> rotations(w,
                                                        Eigen::ComputeFullU |
                                                          Eigen::ComputeFullV);
      const double                            tolerance = 1e-8 / length;
      const unsigned int                      n_rotations =
        (rotations.singularValues().array() > tolerance).count();

      // Pure translations: the null space of w within the basis.
      const Eigen::MatrixXd translations =
        t * rotations.matrixV().rightCols(basis.cols() - n_rotations);
      if (translations.cols() == 3)
        motions.push_back("translate in any direction");
      else if (translations.cols() == 2)
        motions.push_back("translate in the plane normal to " +
                          vector_text(Vector3(translations.col(0))
                                        .cross(Vector3(translations.col(1)))
                                        .normalized()));
      else if (translations.cols() == 1)
        motions.push_back("translate along " +
                          vector_text(translations.col(0).normalized()));

      // Rotations: each axis through the point that the motion leaves in
      // place, p = c + w x t / |w|^2, named after a support there if any.
      for (unsigned int k = 0; k < n_rotations; ++k)
        {
          const Eigen::VectorXd coefficients =
            rotations.matrixV().col(k) / rotations.singularValues()[k];
          const Vector3 omega = rotations.matrixU().col(k);
          Vector3       shift = t * coefficients;
          if (translations.cols() > 0)
            {
              // Translations along the way do not change the axis.
              const Eigen::MatrixXd q =
                translations.householderQr().householderQ() *
                Eigen::MatrixXd::Identity(3, translations.cols());
              shift -= q * (q.transpose() * shift);
            }
          const Vector3 point   = center + omega.cross(shift);
          std::string   through = vector_text(point);
          for (const auto &[position, name] : held)
            if ((position - point).cross(omega).norm() < 1e-9 * length)
              {
                through = "vertex " + name;
                break;
              }
          motions.push_back(n_rotations == 3 && k == 0 ?
                              "rotate about any axis through " + through :
                              "rotate about the axis through " + through +
                                " along " + vector_text(omega));
          if (n_rotations == 3)
            break;
        }
      return motions;
    }

    /// The rows of the fixed DoFs of the rods marked in @p in_part: each
    /// DoF's change under a rigid motion (t, w L) about @p center, with
    /// @p length the part's size; the position of every held vertex and
    /// its name are added to @p held.
    StackedRows
    fixed_dof_rows(const RodModel                               &model,
                   const DofRoles                               &roles,
                   const VectorType                             &u,
                   const std::vector<bool>                      &in_part,
                   const Vector3                                &center,
                   const double                                  length,
                   std::vector<std::pair<Vector3, std::string>> &held)
    {
      const RodNetwork &network = model.network();
      StackedRows       rows;
      for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
        {
          if (roles.kind(d) == Kind::inert ||
              !model.constraints().is_constrained(d))
            continue;
          Row row = Row::Zero();
          switch (roles.kind(d))
            {
              case Kind::position:
                {
                  const unsigned int v = roles.owner(d);
                  if (!in_part[roles.vertex_place(v).first])
                    continue;
                  const Vector3 x = model.configuration().position(u, v);
                  const Vector3 e = Vector3::Unit(roles.component(d));
                  row.head<3>()   = e.transpose();
                  row.tail<3>()   = (x - center).cross(e).transpose() / length;
                  held.emplace_back(x, roles.vertex_name(v));
                  break;
                }
              case Kind::twist:
                {
                  const auto [r, k] = roles.cell_place(roles.owner(d));
                  if (!in_part[r])
                    continue;
                  const std::vector<unsigned int> &chain =
                    network.rods()[r].vertices;
                  const Vector3 tangent =
                    model.configuration()
                      .position(u, chain[(k + 1) % chain.size()]) -
                    model.configuration().position(u, chain[k]);
                  row.tail<3>() = tangent.normalized().transpose();
                  break;
                }
              default:
                {
                  const Junction &j = network.junctions()[roles.owner(d)];
                  if (!in_part[j.ends.front().rod])
                    continue;
                  row[2 + roles.component(d)] = 1;
                  break;
                }
            }
          rows.add(row);
        }
      return rows;
    }
  } // namespace

  std::string
  describe_free_motions(const RodModel &model, const VectorType &u)
  {
    const RodNetwork               &network = model.network();
    const DofRoles                  roles(model);
    const std::vector<unsigned int> part = rod_parts(network);

    std::vector<std::string> free_parts;
    for (unsigned int p = 0; p < part.size(); ++p)
      {
        if (part[p] != p)
          continue;
        std::vector<unsigned int> rods;
        Vector3                   center  = Vector3::Zero();
        unsigned int              n_nodes = 0;
        Vector3 low = Vector3::Constant(INFINITY), high = -low;
        for (unsigned int r = 0; r < part.size(); ++r)
          if (part[r] == p)
            {
              rods.push_back(r);
              for (const unsigned int v : network.rods()[r].vertices)
                {
                  const Vector3 x = model.configuration().position(u, v);
                  center += x;
                  low  = low.cwiseMin(x);
                  high = high.cwiseMax(x);
                  ++n_nodes;
                }
            }
        center /= n_nodes;
        const double length = (high - low).norm();

        // One row per fixed DoF of the part: its change under the motion
        // (t, w L), which must vanish.
        std::vector<bool> in_part(network.rods().size(), false);
        for (const unsigned int r : rods)
          in_part[r] = true;
        std::vector<std::pair<Vector3, std::string>> held;
        StackedRows                                  rows =
          fixed_dof_rows(model, roles, u, in_part, center, length, held);

        const Eigen::JacobiSVD<Eigen::MatrixXd> svd   = rows.svd();
        const Eigen::VectorXd                  &sigma = svd.singularValues();
        unsigned int                            rank  = 0;
        for (int k = 0; k < sigma.size(); ++k)
          if (sigma[k] > 1e-9 * std::max(sigma[0], 1.0))
            ++rank;
        if (rank == 6)
          continue;
        const std::vector<std::string> motions =
          describe_motions(svd.matrixV().rightCols(6 - rank),
                           center,
                           length,
                           held);
        free_parts.push_back(rods_text(rods) + " can " + join_motions(motions));
      }
    if (free_parts.empty())
      return "";
    return "the structure is not held: " + join_motions(free_parts) +
           "; add supports (Supports/Clamped ends, Pinned vertices or Fixed "
           "components) that stop these motions";
  }
} // namespace rodnet
