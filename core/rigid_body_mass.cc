// The constant mass-matrix blocks of rigid bodies (doc/theory.md, "Rigid
// bodies").
#include <deal.II/lac/full_matrix.h>

#include <core/rigid_body_mass.h>

#include <vector>

namespace rodnet
{
  namespace
  {
    /// The block of a body at vertex @p v: m I_3 on the position, and the
    /// rotation of the junction there, omega = 2 vdot at q = (1, 0):
    /// 1/2 j |omega|^2 = 1/2 (4 j) |vdot|^2 (j the mean moment of an
    /// inertia tensor, about the vertex for a centre off it, whose rest
    /// BodyRotationInertia adds: RigidBody::isotropic_inertia()).
    void
    add_vertex_body(const SolvableModel                     &model,
                    const RigidBody                         &body,
                    const unsigned int                       v,
                    const dealii::AffineConstraints<double> &constraints,
                    MatrixType                              &mass)
    {
      std::vector<global_dof_index> dofs;
      for (unsigned int c = 0; c < 3; ++c)
        dofs.push_back(model.layout().vertex_dof(v, c));
      const double j = body.isotropic_inertia();
      if (j > 0)
        {
          const unsigned int j = *model.network().junction_at(v);
          for (unsigned int c = 1; c < 4; ++c)
            dofs.push_back(model.layout().rotation_dof(j, c));
        }
      if (!adds_here(mass, dofs[0]))
        return;
      dealii::FullMatrix<double> block(dofs.size(), dofs.size());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        block(i, i) = i < 3 ? body.mass : 4 * j;
      constraints.distribute_local_to_global(block, dofs, mass);
    }

    /// The block of a body welded to a free rod end: m on its centre,
    /// J_p on the rate of its tangent, J_t on its spin (EndKinematics),
    /// each the outer product of the weights.
    void
    add_end_body(const SolvableModel                     &model,
                 const RigidBody                         &body,
                 const RodEnd                            &end,
                 const dealii::AffineConstraints<double> &constraints,
                 MatrixType                              &mass)
    {
      const EndKinematics e = end_kinematics(model.network(), end, body.offset);
      const unsigned int  n = e.vertices.size();
      std::vector<global_dof_index> dofs;
      for (const unsigned int v : e.vertices)
        for (unsigned int c = 0; c < 3; ++c)
          dofs.push_back(model.layout().vertex_dof(v, c));
      for (const unsigned int cell : e.segments)
        dofs.push_back(model.layout().twist_dof(cell));
      if (!adds_here(mass, dofs[0]))
        return;
      dealii::FullMatrix<double> block(dofs.size(), dofs.size());
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int c = 0; c < 3; ++c)
            block(3 * i + c, 3 * k + c) =
              body.mass * e.centre[i] * e.centre[k] +
              body.transverse_inertia * e.tangent[i] * e.tangent[k];
      for (unsigned int i = 0; i < e.spin.size(); ++i)
        for (unsigned int k = 0; k < e.spin.size(); ++k)
          block(3 * n + i, 3 * n + k) =
            body.axial_inertia * e.spin[i] * e.spin[k];
      constraints.distribute_local_to_global(block, dofs, mass);
    }
  } // namespace

  void
  add_rigid_body_mass(const SolvableModel                     &model,
                      const dealii::AffineConstraints<double> &constraints,
                      MatrixType                              &mass)
  {
    for (const RigidBody &body : model.rigid_bodies())
      if (const auto *v = std::get_if<unsigned int>(&body.attachment))
        add_vertex_body(model, body, *v, constraints, mass);
      else
        add_end_body(model,
                     body,
                     std::get<RodEnd>(body.attachment),
                     constraints,
                     mass);
  }
} // namespace rodnet
