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
    /// 1/2 j |omega|^2 = 1/2 (4 j) |vdot|^2.
    void
    add_vertex_body(const RodModel                          &model,
                    const RigidBody                         &body,
                    const unsigned int                       v,
                    const dealii::AffineConstraints<double> &constraints,
                    MatrixType                              &mass)
    {
      std::vector<global_dof_index> dofs;
      for (unsigned int c = 0; c < 3; ++c)
        dofs.push_back(model.layout().vertex_dof(v, c));
      if (body.axial_inertia > 0)
        {
          const unsigned int j = *model.network().junction_at(v);
          for (unsigned int c = 1; c < 4; ++c)
            dofs.push_back(model.layout().rotation_dof(j, c));
        }
      dealii::FullMatrix<double> block(dofs.size(), dofs.size());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        block(i, i) = i < 3 ? body.mass : 4 * body.axial_inertia;
      constraints.distribute_local_to_global(block, dofs, mass);
    }

    /// The block of a body welded to a free rod end: the centre
    /// x_c = a x_e - b x_p, the tangent rate (xdot_e - xdot_p) / l, the
    /// end segment's twist rate.
    void
    add_end_body(const RodModel                          &model,
                 const RigidBody                         &body,
                 const RodEnd                            &end,
                 const dealii::AffineConstraints<double> &constraints,
                 MatrixType                              &mass)
    {
      const RodNetwork &network          = model.network();
      const auto [before, l]             = end_segment(network, end);
      const Rod                    &rod  = network.rods()[end.rod];
      const double                  b    = body.offset / l;
      const double                  a    = 1 + b;
      const double                  spin = body.transverse_inertia / (l * l);
      const double                  ee   = body.mass * a * a + spin;
      const double                  ep   = -body.mass * a * b - spin;
      const double                  pp   = body.mass * b * b + spin;
      std::vector<global_dof_index> dofs;
      for (const unsigned int v : {network.end_vertex(end), before})
        for (unsigned int c = 0; c < 3; ++c)
          dofs.push_back(model.layout().vertex_dof(v, c));
      dofs.push_back(model.layout().twist_dof(
        end.at_start ? rod.segments.front() : rod.segments.back()));
      dealii::FullMatrix<double> block(7, 7);
      for (unsigned int c = 0; c < 3; ++c)
        {
          block(c, c)         = ee;
          block(c, 3 + c)     = ep;
          block(3 + c, c)     = ep;
          block(3 + c, 3 + c) = pp;
        }
      block(6, 6) = body.axial_inertia;
      constraints.distribute_local_to_global(block, dofs, mass);
    }
  } // namespace

  void
  add_rigid_body_mass(const RodModel                          &model,
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
