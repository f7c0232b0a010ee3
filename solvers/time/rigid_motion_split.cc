#include <deal.II/base/mpi.h>

#include <core/every_entry.h>
#include <elements/quaternion.h>
#include <solvers/checks/dof_roles.h>
#include <solvers/checks/free_motions.h>
#include <solvers/time/rigid_motion_split.h>

#include <Eigen/Dense>
#include <limits>

namespace rodnet
{
  namespace
  {
    using Matrix6 = Eigen::Matrix<double, 6, 6>;
    using Vector6 = Eigen::Matrix<double, 6, 1>;

    /// Rotation directions whose scaled Gram eigenvalue is below this
    /// fraction of the largest are left out: they are no motion of the
    /// part (the rotation of a straight part about its line), and solving
    /// for them would only amplify rounding.
    constexpr double dropped_rotation = 1e-12;

    /**
     * alpha = G^+ b, G scaled to unit diagonal first (the centreline
     * rotations and the frame turns have masses of very different size).
     * A column whose diagonal is below dropped_rotation of the trace of its
     * block (rotations, turns) is no motion but rounding (the rotation of
     * a straight rod about its line, 1e-36 of it in
     * tests/validation/free_flight.cc): scaled up it would be an arbitrary
     * direction, and removing f along it would remove a share of the
     * translation too.
     */
    Vector6
    scaled_pseudo_solve(const Matrix6 &gram, const Vector6 &b)
    {
      const double traces[2] = {gram.diagonal().head<3>().sum(),
                                gram.diagonal().tail<3>().sum()};
      Vector6      scale;
      for (int i = 0; i < 6; ++i)
        scale[i] = gram(i, i) > dropped_rotation * traces[i / 3] ?
                     1 / std::sqrt(gram(i, i)) :
                     0.0;
      const Matrix6 scaled = scale.asDiagonal() * gram * scale.asDiagonal();
      const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(scaled);
      const double largest = eigen.eigenvalues().maxCoeff();
      Vector6      inverse = Vector6::Zero();
      for (int i = 0; i < 6; ++i)
        if (eigen.eigenvalues()[i] > dropped_rotation * largest)
          inverse[i] = 1 / eigen.eigenvalues()[i];
      const Matrix6 &v = eigen.eigenvectors();
      return scale.asDiagonal() * (v * inverse.asDiagonal() *
                                   (v.transpose() * (scale.asDiagonal() * b)));
    }

    /// Replaces each of the @p n doubles at @p values by its sum over the
    /// processes of @p communicator (each added the rows of its DoFs).
    void
    sum_over_processes(double           *values,
                       const std::size_t n,
                       MPI_Comm          communicator)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(communicator) == 1)
        return;
      const std::vector<double> own(values, values + n);
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(own),
                                  communicator,
                                  dealii::ArrayView<double>(values, n));
    }

    /// Whether a rigid motion of a part moves DoFs of kind @p kind.
    bool
    moves_with_part(const DofRoles::Kind kind)
    {
      using Kind = DofRoles::Kind;
      return kind == Kind::position || kind == Kind::twist ||
             kind == Kind::quaternion;
    }

    /// Per root of @p root (rod_parts()), whether its part is held: whether
    /// any of its positions, twists or junction rotations is (clamps, pins,
    /// prescribed motions).
    std::vector<bool>
    held_parts(const SolvableModel             &model,
               const DofRoles                  &roles,
               const std::vector<unsigned int> &root)
    {
      std::vector<bool> held(root.size(), false);
      for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
        if (moves_with_part(roles.kind(d)) &&
            model.constraints().is_constrained(d))
          held[root[rod_of(model.network(), roles, d)]] = true;
      return held;
    }
  } // namespace

  RigidMotionSplit::RigidMotionSplit(const SolvableModel &model,
                                     const MatrixType    &mass)
      : model(model)
      , mass(mass)
  {
    using Kind = DofRoles::Kind;
    const DofRoles                  roles(model);
    const RodNetwork               &network = model.network();
    const std::vector<unsigned int> root    = rod_parts(network);
    const std::vector<bool>         held    = held_parts(model, roles, root);
    const dealii::IndexSet          owned =
      model.create_vector().locally_owned_elements();
    std::vector<int> part_of_root(root.size(), -1);
    for (unsigned int r = 0; r < root.size(); ++r)
      if (root[r] == r && !held[r])
        {
          part_of_root[r] = parts.size();
          parts.emplace_back();
        }
    for (global_dof_index d = 0; d < roles.n_dofs(); ++d)
      {
        const Kind kind = roles.kind(d);
        if (!moves_with_part(kind))
          continue;
        const int part = part_of_root[root[rod_of(network, roles, d)]];
        // Each process the rows of its own DoFs; the sums over the parts
        // add up the processes' (sum_over_processes()).
        if (part < 0 || model.constraints().is_constrained(d) ||
            !owned.is_element(d))
          continue;
        if (kind == Kind::position)
          moved.push_back({d,
                           unsigned(part),
                           roles.component(d),
                           roles.owner(d),
                           roles.owner(d)});
        else if (kind == Kind::quaternion)
          moved.push_back({d,
                           unsigned(part),
                           3u + roles.component(d),
                           roles.owner(d),
                           roles.owner(d)});
        else
          {
            const auto [r, k] = roles.cell_place(roles.owner(d));
            const std::vector<unsigned int> &chain = network.rods()[r].vertices;
            moved.push_back(
              {d, unsigned(part), 3, chain[k], chain[(k + 1) % chain.size()]});
          }
      }
  }

  void
  RigidMotionSplit::set_centres(const VectorType &x)
  {
    if (!started)
      {
        // M t_a, t_a moving every vertex of the free parts by e_a.
        VectorType translation = model.create_vector();
        for (unsigned int a = 0; a < 3; ++a)
          {
            translation = 0;
            for (const MovedDof &m : moved)
              if (m.component == a)
                translation[m.dof] = 1;
            translation.compress(dealii::VectorOperation::insert);
            mass_translations[a].reinit(translation);
            mass.vmult(mass_translations[a], translation);
          }
        for (unsigned int j = 0; j < 6; ++j)
          {
            rotations[j].reinit(translation);
            mass_rotations[j].reinit(translation);
          }
        started = true;
      }
    const EveryEntry every(x);
    for (Part &part : parts)
      part = Part{0, Vector3::Zero()};
    // The centre of mass of the rows of M: then t_a^T M r_b = e_b x
    // sum_i m_i (x_i - c) = 0, the translations M-orthogonal to the
    // rotations. The mass of each component is the same for the block
    // mass matrices of the rods; the x component is taken.
    for (const MovedDof &m : moved)
      if (m.component < 3)
        {
          const double mass_i = mass_translations[m.component][m.dof];
          const double x_i =
            model.configuration().position(*every, m.vertex)[m.component];
          Part &part = parts[m.part];
          part.centre[m.component] += mass_i * x_i;
          if (m.component == 0)
            part.mass += mass_i;
        }
    for (Part &part : parts)
      {
        sum_over_processes(&part.mass, 1, communicator());
        sum_over_processes(part.centre.data(), 3, communicator());
        part.centre /= part.mass;
      }
  }

  void
  RigidMotionSplit::set_rotations(const VectorType &x)
  {
    for (VectorType &r : rotations)
      r = 0;
    const EveryEntry every(x);
    for (const MovedDof &m : moved)
      {
        if (m.component > 3)
          {
            set_junction_turn(*every, m);
            continue;
          }
        const Vector3 position =
          model.configuration().position(*every, m.vertex);
        if (m.component < 3)
          {
            const Vector3 arm = position - parts[m.part].centre;
            for (unsigned int a = 0; a < 3; ++a)
              rotations[a][m.dof] = Vector3::Unit(a).cross(arm)[m.component];
          }
        else
          {
            const Vector3 tangent =
              (model.configuration().position(*every, m.next) - position)
                .normalized();
            for (unsigned int a = 0; a < 3; ++a)
              rotations[3 + a][m.dof] = tangent[a];
          }
      }
    for (VectorType &r : rotations)
      r.compress(dealii::VectorOperation::insert);
    for (unsigned int j = 0; j < 6; ++j)
      mass.vmult(mass_rotations[j], rotations[j]);
  }

  void
  RigidMotionSplit::set_junction_turn(const VectorType &x, const MovedDof &m)
  {
    // A turn by e_a takes q = (1, a) to (1, e_a / 2) q, which at real part
    // 1 is a + (I - [a]_x + a a^T) e_a / 2 to first order.
    Vector3 a;
    for (unsigned int c = 0; c < 3; ++c)
      a[c] = x[model.layout().rotation_dof(m.vertex, c + 1)];
    const Matrix3 turn =
      (Matrix3::Identity() - cross_matrix(a) + a * a.transpose()) / 2;
    for (unsigned int b = 0; b < 3; ++b)
      rotations[3 + b][m.dof] = turn(m.component - 4, b);
  }

  void
  RigidMotionSplit::remove_rigid_part(const VectorType &x, VectorType &force)
  {
    if (parts.empty())
      return;
    set_centres(x);
    set_rotations(x);
    std::vector<Vector3> resultant(parts.size(), Vector3::Zero());
    std::vector<Matrix6> gram(parts.size(), Matrix6::Zero());
    std::vector<Vector6> moment(parts.size(), Vector6::Zero());
    for (const MovedDof &m : moved)
      {
        if (m.component < 3)
          resultant[m.part][m.component] += force[m.dof];
        for (unsigned int i = 0; i < 6; ++i)
          {
            moment[m.part][i] += rotations[i][m.dof] * force[m.dof];
            for (unsigned int j = 0; j < 6; ++j)
              gram[m.part](i, j) +=
                rotations[i][m.dof] * mass_rotations[j][m.dof];
          }
      }
    // alpha_t = (t^T M t)^-1 t^T f per part (t^T M t = the part's mass),
    // alpha_r = (R^T M R)^+ R^T f for the six rotation columns.
    std::vector<Vector6> alpha(parts.size());
    for (unsigned int p = 0; p < parts.size(); ++p)
      {
        sum_over_processes(resultant[p].data(), 3, communicator());
        sum_over_processes(moment[p].data(), 6, communicator());
        sum_over_processes(gram[p].data(), 36, communicator());
        resultant[p] /= parts[p].mass;
        alpha[p] = scaled_pseudo_solve(gram[p], moment[p]);
      }
    for (const MovedDof &m : moved)
      {
        double rigid = 0;
        for (unsigned int a = 0; a < 3; ++a)
          rigid += resultant[m.part][a] * mass_translations[a][m.dof];
        for (unsigned int j = 0; j < 6; ++j)
          rigid += alpha[m.part][j] * mass_rotations[j][m.dof];
        force[m.dof] -= rigid;
      }
    // Element-wise additions end with compress(add), so that a following
    // insertion (AffineConstraints::set_zero) agrees with deal.II's record
    // of the last operation.
    force.compress(dealii::VectorOperation::add);
  }
} // namespace rodnet
