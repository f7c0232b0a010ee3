#include <core/every_entry.h>
#include <solvers/checks/constraint_rows.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/checks/free_motions.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace rodnet
{
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

  unsigned int
  rod_of(const RodNetwork      &network,
         const DofRoles        &roles,
         const global_dof_index d)
  {
    switch (roles.kind(d))
      {
        case DofRoles::Kind::position:
          return roles.vertex_place(roles.owner(d)).first;
        case DofRoles::Kind::twist:
          return roles.cell_place(roles.owner(d)).first;
        default:
          {
            // A handle inside a rod has no ends: the rod it sits in.
            const Junction &junction = network.junctions()[roles.owner(d)];
            return junction.ends.empty() ? junction.interior->rod :
                                           junction.ends.front().rod;
          }
      }
  }

  namespace
  {
    using Kind = DofRoles::Kind;
    using Row  = Eigen::RowVectorXd;
    /// Candidates of a rigid motion: translation t, rotation w L.
    constexpr int rigid_columns = 6;
    /// With the turn of every material frame of a rod about its tangents
    /// (its twists all change alike), a symmetry of an isotropic rod.
    constexpr int turn_columns = 7;

    /// Largest energy (whitened: against each family's own stiffness along
    /// the motion) of a motion that counts as free: at an unstressed state
    /// a rigid motion meets rounding, 1e-17 in tests/solvers/free_motions;
    /// one that a family resists meets 0.36 to 0.5.
    constexpr double free_tolerance = 1e-10;
    /// Largest second variation of the potential along a symmetry, per
    /// unit angle of the motion squared, against twice the stored energy
    /// of its part (symmetries_of()). The turned buckled column with
    /// EI1 = EI2, a continuum symmetry that the discretization breaks,
    /// meets at most 4.6e-6, 2e-10, 1e-8, 1.3e-8 and 3.8e-8 of it at N = 5,
    /// 10, 20, 40 and 100 segments; a motion that the material or the
    /// loads resist meets their energy scale: turned, a section with EI2 =
    /// 1.01 EI1 meets 0.02 to 0.24, about 2 (EI2 - EI1) / EI1; a pendulum
    /// turned against gravity its weight times its length against the
    /// strain energy of its tension.
    constexpr double symmetry_tolerance = 1e-4;

    /// The upper triangle R of a QR factorization of the stacked rows,
    /// kept width x width however many rows come in, so that the small
    /// singular values of the constraint matrix stay accurate (A^T A would
    /// square them into rounding).
    class StackedRows
    {
    public:
      explicit StackedRows(const int width)
          : r(Eigen::MatrixXd::Zero(width, width))
      {
      }

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
        const int       width = r.cols();
        Eigen::MatrixXd stack(width + pending.size(), width);
        stack.topRows(width) = r;
        for (unsigned int k = 0; k < pending.size(); ++k)
          stack.row(width + k) = pending[k];
        pending.clear();
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stack);
        r = qr.matrixQR().topRows(width).triangularView<Eigen::Upper>();
      }

      /// Zero rows until the first reduction: they change nothing.
      Eigen::MatrixXd  r;
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

    /// The direction of a line: @p v or -v, whichever has its first
    /// component that is not rounding noise positive (the sign of a
    /// singular vector is arbitrary).
    std::string
    direction_text(const Vector3 &v)
    {
      for (unsigned int c = 0; c < 3; ++c)
        if (std::abs(v[c]) >= 1e-9 * v.norm())
          return vector_text(v[c] > 0 ? v : Vector3(-v));
      return vector_text(v);
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
                          direction_text(Vector3(translations.col(0))
                                           .cross(Vector3(translations.col(1)))
                                           .normalized()));
      else if (translations.cols() == 1)
        motions.push_back("translate along " +
                          direction_text(translations.col(0).normalized()));

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
                                " along " + direction_text(omega));
          if (n_rotations == 3)
            break;
        }
      return motions;
    }

    /// A connected part of the network and the rigid motions left to it.
    struct Part
    {
      std::vector<unsigned int> rods;
      /// Centroid of its vertices and the diagonal of their bounding box.
      Vector3 center = Vector3::Zero();
      double  length = 0;
      /// Position and name of each held vertex (to name a point on an
      /// axis).
      std::vector<std::pair<Vector3, std::string>> held;
      /// The free motions: orthonormal columns (t, w length[, turn
      /// length]).
      Eigen::MatrixXd motions;
      /// Whether its candidates include the turn of the material frames:
      /// a single rod without junctions, when symmetries are sought.
      bool turns = false;
    };

    /// Whether DoFs of @p kind change under a rigid motion: not the inert
    /// ones, nor the multipliers of inextensible segments (their lengths do
    /// not change), nor a ribbon's generatrix slopes (shape DoFs).
    bool
    moves_rigidly(const Kind kind)
    {
      return kind != Kind::inert && kind != Kind::multiplier &&
             kind != Kind::shape;
    }

    /// @p root (rod_parts()) with the parts joined that a constraint couples
    /// (a bond between vertices of two parts): roots stay where nothing is
    /// joined.
    std::vector<unsigned int>
    join_constrained_parts(std::vector<unsigned int>         root,
                           const RodNetwork                 &network,
                           const DofRoles                   &roles,
                           const std::vector<ConstraintRow> &rows)
    {
      const auto find = [&](unsigned int r) {
        while (root[r] != r)
          r = root[r] = root[root[r]];
        return r;
      };
      for (const ConstraintRow &row : rows)
        {
          unsigned int first = root.size();
          for (unsigned int b = 0; b < row.dofs.size(); ++b)
            if (moves_rigidly(roles.kind(row.dofs[b])) && row.gradient[b] != 0)
              {
                const unsigned int r =
                  find(rod_of(network, roles, row.dofs[b]));
                if (first == root.size())
                  first = r;
                else if (r != first)
                  root[std::max(r, first)] = first = std::min(r, first);
              }
        }
      for (unsigned int r = 0; r < root.size(); ++r)
        root[r] = find(r);
      return root;
    }

    /// The parts of the network at @p u (rods joined by junctions or by
    /// @p constraints), in the order of their union-find roots;
    /// @p part_of_rod receives the part of every rod.
    std::vector<Part>
    parts_at(const SolvableModel              &model,
             const DofRoles                   &roles,
             const std::vector<ConstraintRow> &constraints,
             const VectorType                 &u,
             std::vector<unsigned int>        &part_of_rod)
    {
      const RodNetwork               &network = model.network();
      const std::vector<unsigned int> root =
        join_constrained_parts(rod_parts(network), network, roles, constraints);
      std::vector<Part>         parts;
      std::vector<unsigned int> part_of_root(root.size());
      for (unsigned int r = 0; r < root.size(); ++r)
        if (root[r] == r)
          {
            part_of_root[r] = parts.size();
            parts.emplace_back();
          }
      part_of_rod.resize(root.size());
      for (unsigned int r = 0; r < root.size(); ++r)
        {
          part_of_rod[r] = part_of_root[root[r]];
          parts[part_of_rod[r]].rods.push_back(r);
        }
      for (Part &part : parts)
        {
          unsigned int n_nodes = 0;
          Vector3      low = Vector3::Constant(INFINITY), high = -low;
          for (const unsigned int r : part.rods)
            for (const unsigned int v : network.rods()[r].vertices)
              {
                const Vector3 x = model.configuration().position(u, v);
                part.center += x;
                low  = low.cwiseMin(x);
                high = high.cwiseMax(x);
                ++n_nodes;
              }
          part.center /= n_nodes;
          part.length = (high - low).norm();
        }
      return parts;
    }

    /// The factor between the row of DoF @p d (rigid_change()) and its
    /// change: 1 for a position; @p length for a twist, whose row measures
    /// the angle by the arc it sweeps at that distance, so that every row
    /// is of unit size; twice that for a quaternion component, which turns
    /// by half the angle.
    double
    change_unit(const DofRoles        &roles,
                const global_dof_index d,
                const double           length)
    {
      switch (roles.kind(d))
        {
          case Kind::position:
            return 1;
          case Kind::twist:
            return length;
          default:
            return 2 * length;
        }
    }

    /**
     * The change of DoF @p d (not inert) under the rigid motion (t, w L)
     * of its part about @p center, L = @p length, in change_unit(): the
     * row r with change = r . (t, w L) / change_unit(). A vertex x moves by
     * t + w x (x - c); the twist of a segment of unit tangent e by w . e;
     * the vector part v of a junction's quaternion increment q = (1, v),
     * which the motion turns on the left (w/2 * q, real part kept 1), by
     * (w - v x w + (v . w) v) / 2, which is w / 2 at the reference.
     */
    Row
    rigid_change(const SolvableModel   &model,
                 const DofRoles        &roles,
                 const VectorType      &u,
                 const global_dof_index d,
                 const Vector3         &center,
                 const double           length)
    {
      Row row = Row::Zero(rigid_columns);
      switch (roles.kind(d))
        {
          case Kind::position:
            {
              const Vector3 x =
                model.configuration().position(u, roles.owner(d));
              const Vector3 e   = Vector3::Unit(roles.component(d));
              row.head<3>()     = e.transpose();
              row.segment<3>(3) = (x - center).cross(e).transpose() / length;
              break;
            }
          case Kind::twist:
            {
              const auto [r, k] = roles.cell_place(roles.owner(d));
              const std::vector<unsigned int> &chain =
                model.network().rods()[r].vertices;
              const Vector3 tangent =
                model.configuration().position(u,
                                               chain[(k + 1) % chain.size()]) -
                model.configuration().position(u, chain[k]);
              row.segment<3>(3) = tangent.normalized().transpose();
              break;
            }
          default:
            {
              const unsigned int j = roles.owner(d);
              Vector3            v;
              for (unsigned int c = 0; c < 3; ++c)
                v[c] = u[model.layout().rotation_dof(j, c + 1)];
              const Eigen::Matrix3d turn = Eigen::Matrix3d::Identity() -
                                           cross_matrix(v) + v * v.transpose();
              row.segment<3>(3) = turn.row(roles.component(d) - 1);
              break;
            }
        }
      return row;
    }

    /// The row of DoF @p d of part @p part (rigid_change()), with the turn
    /// column where the part turns: a twist changes by the turn itself.
    Row
    candidate_change(const SolvableModel   &model,
                     const DofRoles        &roles,
                     const VectorType      &u,
                     const global_dof_index d,
                     const Part            &part)
    {
      const Row rigid =
        rigid_change(model, roles, u, d, part.center, part.length);
      if (!part.turns)
        return rigid;
      Row row                 = Row::Zero(turn_columns);
      row.head(rigid_columns) = rigid;
      if (roles.kind(d) == Kind::twist)
        row[rigid_columns] = 1;
      return row;
    }

    /**
     * Adds to @p rows the change of each of the @p constraints on part
     * @p p along its candidate motions, in units of the change its DoFs
     * would make one by one; leaves out a constraint that the motions keep
     * to rounding (the length of an inextensible segment, a ribbon's
     * developability), which stops none of them.
     */
    void
    add_constraint_changes(const SolvableModel              &model,
                           const DofRoles                   &roles,
                           const VectorType                 &u,
                           const std::vector<unsigned int>  &part_of_rod,
                           const unsigned int                p,
                           const Part                       &part,
                           const std::vector<ConstraintRow> &constraints,
                           StackedRows                      &rows)
    {
      const int width = part.turns ? turn_columns : rigid_columns;
      for (const ConstraintRow &constraint : constraints)
        {
          Row    change = Row::Zero(width);
          double size   = 0;
          for (unsigned int b = 0; b < constraint.dofs.size(); ++b)
            {
              const global_dof_index d = constraint.dofs[b];
              if (!moves_rigidly(roles.kind(d)) ||
                  constraint.gradient[b] == 0 ||
                  part_of_rod[rod_of(model.network(), roles, d)] != p)
                continue;
              const Row dof_change =
                candidate_change(model, roles, u, d, part) /
                change_unit(roles, d, part.length);
              change += constraint.gradient[b] * dof_change;
              size += std::abs(constraint.gradient[b]) * dof_change.norm();
            }
          if (change.norm() > 1e-9 * size)
            rows.add(change / size);
        }
    }

    /// The rigid motions of part @p p that no fixed DoF and none of the
    /// @p constraints stops: the null space of the rows of its fixed DoFs
    /// (their change must vanish) and of the constraints it changes, as
    /// orthonormal columns (t, w L). Adds its held vertices to part.held.
    Eigen::MatrixXd
    motions_the_supports_leave(const SolvableModel              &model,
                               const DofRoles                   &roles,
                               const std::vector<ConstraintRow> &constraints,
                               const VectorType                 &u,
                               const std::vector<unsigned int>  &part_of_rod,
                               const unsigned int                p,
                               Part                             &part)
    {
      const int   width = part.turns ? turn_columns : rigid_columns;
      StackedRows rows(width);
      add_constraint_changes(model,
                             roles,
                             u,
                             part_of_rod,
                             p,
                             part,
                             constraints,
                             rows);
      for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
        {
          if (!moves_rigidly(roles.kind(d)) ||
              !model.constraints().is_constrained(d) ||
              part_of_rod[rod_of(model.network(), roles, d)] != p)
            continue;
          if (roles.kind(d) == Kind::position)
            part.held.emplace_back(
              model.configuration().position(u, roles.owner(d)),
              roles.vertex_name(roles.owner(d)));
          rows.add(candidate_change(model, roles, u, d, part));
        }

      const Eigen::JacobiSVD<Eigen::MatrixXd> svd   = rows.svd();
      const Eigen::VectorXd                  &sigma = svd.singularValues();
      unsigned int                            rank  = 0;
      for (int k = 0; k < sigma.size(); ++k)
        if (sigma[k] > 1e-9 * std::max(sigma[0], 1.0))
          ++rank;
      return svd.matrixV().rightCols(width - rank);
    }

    /**
     * Of the motions (columns of @p motions, DoF vectors M), those along
     * which the tangent is singular to @p tolerance: the null space of
     * @p energy, the sum
     * of the families' M^T K_f M, measured against @p weight, the sum of
     * their M^T |diag K_f| M (the energy the motion would meet if each of
     * its DoFs moved alone), each family's pair in units of its own
     * largest weight along the motions. Motions that move only DoFs which
     * no stencil sees (weight 0) are free outright. Returns orthonormal
     * columns; @p motions itself if nothing holds them.
     */
    Eigen::MatrixXd
    null_motions(const Eigen::MatrixXd &motions,
                 const Eigen::MatrixXd &energy,
                 const Eigen::MatrixXd &weight,
                 const double           tolerance)
    {
      // An energy that does not resist a rigid motion m (one invariant
      // under it, at an unstressed state) has K m = 0 but for the rounding
      // of the Hessian entries that cancel along m: 1e-17 of its weight in
      // tests/solvers/free_motions. One that resists m does so with a fair
      // part of its own weight (0.36 to 0.5 there and in
      // validation/elastic_foundation), however soft it is against the
      // rest, since every family is measured in its own units.
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> weights(weight);
      const double    heaviest = weights.eigenvalues().maxCoeff();
      Eigen::MatrixXd unheld(motions.cols(), 0), whitened(motions.cols(), 0);
      const auto append = [](Eigen::MatrixXd &to, const Eigen::VectorXd &c) {
        to.conservativeResize(Eigen::NoChange, to.cols() + 1);
        to.col(to.cols() - 1) = c;
      };
      for (int k = 0; k < motions.cols(); ++k)
        {
          const double w = weights.eigenvalues()[k];
          if (w <= 1e-14 * heaviest)
            append(unheld, weights.eigenvectors().col(k));
          else
            append(whitened, weights.eigenvectors().col(k) / std::sqrt(w));
        }
      if (whitened.cols() > 0)
        {
          const Eigen::MatrixXd symmetric = (energy + energy.transpose()) / 2;
          const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> cost(
            whitened.transpose() * symmetric * whitened);
          for (int k = 0; k < whitened.cols(); ++k)
            if (std::abs(cost.eigenvalues()[k]) <= tolerance)
              append(unheld, whitened * cost.eigenvectors().col(k));
        }
      if (unheld.cols() == motions.cols())
        return motions;
      if (unheld.cols() == 0)
        return Eigen::MatrixXd(motions.rows(), 0);
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(motions * unheld);
      return qr.householderQ() *
             Eigen::MatrixXd::Identity(motions.rows(), unheld.cols());
    }

    /// The DoF vectors of the parts' motions: column j holds the j-th
    /// motion of every part (parts share no DoF); @p part_of_dof receives
    /// the part of every DoF that moves, @p parts.size() for the others.
    Eigen::MatrixXd
    motion_vectors(const SolvableModel             &model,
                   const DofRoles                  &roles,
                   const VectorType                &u,
                   const std::vector<unsigned int> &part_of_rod,
                   const std::vector<Part>         &parts,
                   std::vector<unsigned int>       &part_of_dof)
    {
      unsigned int n_slots = 0;
      for (const Part &part : parts)
        n_slots = std::max<unsigned int>(n_slots, part.motions.cols());
      Eigen::MatrixXd values = Eigen::MatrixXd::Zero(roles.n_dofs(), n_slots);
      part_of_dof.assign(roles.n_dofs(), parts.size());
      for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
        {
          if (!moves_rigidly(roles.kind(d)))
            continue;
          const unsigned int p = part_of_rod[rod_of(model.network(), roles, d)];
          const Part        &part = parts[p];
          if (part.motions.cols() == 0)
            continue;
          part_of_dof[d] = p;
          values.row(d).head(part.motions.cols()) =
            candidate_change(model, roles, u, d, part) * part.motions /
            change_unit(roles, d, part.length);
        }
      return values;
    }

    /// Adds, per part, M^T K_s M to @p energy and M^T |diag K_s| M to
    /// @p weight for every stencil s of @p family, its Hessian K_s at
    /// @p state and M the motions of the part (@p values) at its DoFs, and
    /// |E_s| to @p stored if given.
    void
    add_family_grams(const ElementFamily             &family,
                     const StencilState              &state,
                     const Eigen::MatrixXd           &values,
                     const std::vector<unsigned int> &part_of_dof,
                     std::vector<Eigen::MatrixXd>    &energy,
                     std::vector<Eigen::MatrixXd>    &weight,
                     std::vector<double>             *stored = nullptr)
    {
      const unsigned int            none = energy.size();
      std::vector<global_dof_index> dofs;
      LocalContribution             local;
      for (unsigned int s = 0; s < family.n_stencils(); ++s)
        {
          family.get_dofs(s, dofs);
          std::vector<unsigned int> stencil_parts;
          for (const global_dof_index d : dofs)
            if (part_of_dof[d] != none &&
                std::find(stencil_parts.begin(),
                          stencil_parts.end(),
                          part_of_dof[d]) == stencil_parts.end())
              stencil_parts.push_back(part_of_dof[d]);
          if (stencil_parts.empty())
            continue;
          local.dofs = dofs;
          family.evaluate(s, state, Derivatives::hessian, local);
          Eigen::MatrixXd hessian(dofs.size(), dofs.size());
          for (unsigned int a = 0; a < dofs.size(); ++a)
            for (unsigned int b = 0; b < dofs.size(); ++b)
              hessian(a, b) = local.matrix(a, b);
          for (const unsigned int p : stencil_parts)
            {
              // The part moves alone: the DoFs of other parts stay.
              Eigen::MatrixXd m =
                Eigen::MatrixXd::Zero(dofs.size(), energy[p].cols());
              for (unsigned int a = 0; a < dofs.size(); ++a)
                if (part_of_dof[dofs[a]] == p)
                  m.row(a) = values.row(dofs[a]).head(m.cols());
              energy[p] += m.transpose() * hessian * m;
              if (stored != nullptr)
                (*stored)[p] += std::abs(local.energy);
              weight[p] +=
                m.transpose() * hessian.diagonal().cwiseAbs().asDiagonal() * m;
            }
        }
    }

    /// A zero square matrix per part, of the size of its motions.
    std::vector<Eigen::MatrixXd>
    zero_grams(const std::vector<Part> &parts)
    {
      std::vector<Eigen::MatrixXd> grams;
      for (const Part &part : parts)
        grams.push_back(
          Eigen::MatrixXd::Zero(part.motions.cols(), part.motions.cols()));
      return grams;
    }

    /**
     * Keeps, of the motions the supports leave to each part, those that
     * the energy does not stop either (null_motions()), from the Hessians
     * of every family's stencils at @p u and @p load_factor (0 for rigid
     * motions: a load is no support), family by family, so that each is
     * measured against its own stiffness. Evaluates nothing if no part has
     * a motion left.
     */
    void
    keep_motions_the_energy_leaves(const SolvableModel             &model,
                                   const DofRoles                  &roles,
                                   const VectorType                &u,
                                   const std::vector<unsigned int> &part_of_rod,
                                   std::vector<Part>               &parts,
                                   const double load_factor = 0)
    {
      if (std::all_of(parts.begin(), parts.end(), [](const Part &part) {
            return part.motions.cols() == 0;
          }))
        return;
      std::vector<unsigned int> part_of_dof;
      const Eigen::MatrixXd     values =
        motion_vectors(model, roles, u, part_of_rod, parts, part_of_dof);
      const StencilState           state{u,
                               model.configuration(),
                               model.internal_variables(),
                               model.time_step(),
                               model.applied_load_factor(load_factor)};
      std::vector<Eigen::MatrixXd> energy = zero_grams(parts),
                                   weight = zero_grams(parts);
      for (const auto &family : model.element_families())
        {
          std::vector<Eigen::MatrixXd> family_energy = zero_grams(parts);
          std::vector<Eigen::MatrixXd> family_weight = zero_grams(parts);
          add_family_grams(*family,
                           state,
                           values,
                           part_of_dof,
                           family_energy,
                           family_weight);
          for (unsigned int p = 0; p < parts.size(); ++p)
            {
              const double unit = family_weight[p].size() > 0 ?
                                    family_weight[p].diagonal().maxCoeff() :
                                    0.0;
              if (unit > 0)
                {
                  energy[p] += family_energy[p] / unit;
                  weight[p] += family_weight[p] / unit;
                }
            }
        }
      for (unsigned int p = 0; p < parts.size(); ++p)
        if (parts[p].motions.cols() > 0)
          parts[p].motions = null_motions(parts[p].motions,
                                          energy[p],
                                          weight[p],
                                          free_tolerance);
    }

    /// Whether each rod is joined to a junction: by an end, or by a
    /// rotation handle inside it (a junction element holds the frame of
    /// the segment it joins).
    std::vector<bool>
    joined_rods(const RodNetwork &network)
    {
      std::vector<bool> joined(network.rods().size(), false);
      for (const Junction &j : network.junctions())
        {
          for (const RodEnd &end : j.ends)
            joined[end.rod] = true;
          if (j.ends.empty())
            joined[j.interior->rod] = true;
        }
      return joined;
    }

    /**
     * Per rod, its first twist DoF where the common turn of all its frames
     * is a candidate symmetry: the rod is not @p joined and none of its
     * twists is fixed; roles.n_dofs() otherwise.
     */
    std::vector<global_dof_index>
    turning_twists(const SolvableModel     &model,
                   const DofRoles          &roles,
                   const std::vector<bool> &joined)
    {
      const global_dof_index        none = roles.n_dofs();
      std::vector<global_dof_index> twist(joined.size(), none);
      std::vector<bool>             held = joined;
      for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
        if (roles.kind(d) == Kind::twist)
          {
            const unsigned int r = roles.cell_place(roles.owner(d)).first;
            if (model.constraints().is_constrained(d))
              held[r] = true;
            else if (twist[r] == none)
              twist[r] = d;
          }
      for (unsigned int r = 0; r < twist.size(); ++r)
        if (held[r])
          twist[r] = none;
      return twist;
    }

    /// The largest change of @p mode in angles: positions over
    /// @p length, twists in rad, quaternion components twice (they turn by
    /// half the angle).
    double
    amplitude(const DofRoles        &roles,
              const Eigen::VectorXd &mode,
              const double           length)
    {
      double largest = 0;
      for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
        largest = std::max(largest,
                           std::abs(mode[d]) * change_unit(roles, d, 1.0) /
                             (roles.kind(d) == Kind::position ? length : 1.0));
      return largest;
    }

    /**
     * Of the motions the supports leave to each part (part.motions), the
     * combinations along which the potential at (@p u, @p load_factor)
     * does not change: the eigenvectors c of A = sum_s M^T K_s M (every
     * stencil's Hessian) whose eigenvalue, per unit angle of the motion
     * squared, is at most symmetry_tolerance times twice the stored energy
     * of the part. As DoF vectors; those that move nothing are dropped.
     */
    std::vector<VectorType>
    symmetries_of(const SolvableModel             &model,
                  const DofRoles                  &roles,
                  const VectorType                &u,
                  const double                     load_factor,
                  const std::vector<unsigned int> &part_of_rod,
                  const std::vector<Part>         &parts)
    {
      std::vector<unsigned int> part_of_dof;
      const Eigen::MatrixXd     values =
        motion_vectors(model, roles, u, part_of_rod, parts, part_of_dof);
      const StencilState           state{u,
                               model.configuration(),
                               model.internal_variables(),
                               model.time_step(),
                               load_factor};
      std::vector<Eigen::MatrixXd> energy = zero_grams(parts),
                                   weight = zero_grams(parts);
      std::vector<double> stored(parts.size(), 0.0);
      for (const auto &family : model.element_families())
        add_family_grams(*family,
                         state,
                         values,
                         part_of_dof,
                         energy,
                         weight,
                         &stored);

      std::vector<VectorType> modes;
      for (unsigned int p = 0; p < parts.size(); ++p)
        {
          const int n = parts[p].motions.cols();
          if (n == 0)
            continue;
          const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(
            (energy[p] + energy[p].transpose()) / 2);
          for (int k = 0; k < n; ++k)
            {
              Eigen::VectorXd mode = Eigen::VectorXd::Zero(roles.n_dofs());
              for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
                if (part_of_dof[d] == p)
                  mode[d] = values.row(d).head(n) * eigen.eigenvectors().col(k);
              const double angle = amplitude(roles, mode, parts[p].length);
              if (angle < 1e-9 ||
                  std::abs(eigen.eigenvalues()[k]) >
                    symmetry_tolerance * 2 * stored[p] * angle * angle)
                continue;
              VectorType vector = model.create_vector();
              for (const global_dof_index d : vector.locally_owned_elements())
                if (mode[d] != 0)
                  vector[d] = mode[d];
              vector.compress(dealii::VectorOperation::insert);
              modes.push_back(std::move(vector));
            }
        }
      return modes;
    }
  } // namespace

  std::string
  describe_free_motions(const SolvableModel &model, const VectorType &state)
  {
    const EveryEntry                 every_entry(state);
    const VectorType                &u = *every_entry;
    const DofRoles                   roles(model);
    std::vector<unsigned int>        part_of_rod;
    const std::vector<ConstraintRow> constraints =
      constraint_rows(model, roles, u);
    std::vector<Part> parts =
      parts_at(model, roles, constraints, u, part_of_rod);
    for (unsigned int p = 0; p < parts.size(); ++p)
      parts[p].motions = motions_the_supports_leave(model,
                                                    roles,
                                                    constraints,
                                                    u,
                                                    part_of_rod,
                                                    p,
                                                    parts[p]);
    keep_motions_the_energy_leaves(model, roles, u, part_of_rod, parts);

    std::vector<std::string> free_parts;
    for (const Part &part : parts)
      if (part.motions.cols() > 0)
        free_parts.push_back(rods_text(part.rods) + " can " +
                             join_motions(describe_motions(part.motions,
                                                           part.center,
                                                           part.length,
                                                           part.held)));
    if (free_parts.empty())
      return "";
    return "the structure is not held: " + join_motions(free_parts) +
           "; add supports (Supports/Clamped ends, Pinned vertices or Fixed "
           "components) that stop these motions";
  }

  std::vector<VectorType>
  symmetry_modes(const SolvableModel &model,
                 const VectorType    &state,
                 const double         load_factor)
  {
    const EveryEntry                 every_entry(state);
    const VectorType                &u = *every_entry;
    const DofRoles                   roles(model);
    std::vector<unsigned int>        part_of_rod;
    const std::vector<ConstraintRow> constraints =
      constraint_rows(model, roles, u);
    std::vector<Part> parts =
      parts_at(model, roles, constraints, u, part_of_rod);
    std::vector<bool> at_junction(model.network().rods().size());
    for (const Junction &j : model.network().junctions())
      {
        // A rotation handle inside a rod (no rod end) belongs to no part
        // here; such models are not searched.
        if (j.ends.empty())
          return {};
        for (const RodEnd &end : j.ends)
          at_junction[end.rod] = true;
      }
    bool any = false;
    for (unsigned int p = 0; p < parts.size(); ++p)
      {
        parts[p].turns =
          parts[p].rods.size() == 1 && !at_junction[parts[p].rods[0]];
        parts[p].motions = motions_the_supports_leave(model,
                                                      roles,
                                                      constraints,
                                                      u,
                                                      part_of_rod,
                                                      p,
                                                      parts[p]);
        any              = any || parts[p].motions.cols() > 0;
      }
    if (!any)
      return {};
    return symmetries_of(model, roles, u, load_factor, part_of_rod, parts);
  }

  std::vector<global_dof_index>
  free_frame_turns(const SolvableModel &model,
                   const VectorType    &state,
                   const double         load_factor)
  {
    const EveryEntry  every_entry(state);
    const VectorType &u = *every_entry;
    // Where every rod is joined (a welded network), nothing to look at.
    const std::vector<bool> joined = joined_rods(model.network());
    if (std::all_of(joined.begin(), joined.end(), [](bool j) { return j; }))
      return {};
    const DofRoles                      roles(model);
    const std::vector<global_dof_index> twists =
      turning_twists(model, roles, joined);
    std::vector<unsigned int>        part_of_rod;
    const std::vector<ConstraintRow> constraints =
      constraint_rows(model, roles, u);
    std::vector<Part> parts =
      parts_at(model, roles, constraints, u, part_of_rod);
    for (Part &part : parts)
      if (part.rods.size() == 1 && twists[part.rods[0]] != roles.n_dofs())
        {
          // The turn column alone of the candidates.
          part.turns   = true;
          part.motions = Eigen::VectorXd::Unit(turn_columns, rigid_columns);
        }
    // At the load factor of the state: a ramped natural curvature breaks
    // the symmetry.
    keep_motions_the_energy_leaves(model,
                                   roles,
                                   u,
                                   part_of_rod,
                                   parts,
                                   load_factor);
    std::vector<global_dof_index> held;
    for (const Part &part : parts)
      if (part.turns && part.motions.cols() == 1)
        held.push_back(twists[part.rods[0]]);
    return held;
  }
} // namespace rodnet
