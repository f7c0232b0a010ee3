// Energies and momenta of a rod network in motion, for probes.
#include <core/every_entry.h>
#include <core/mass_matrix.h>
#include <core/motion.h>
#include <core/tensor_body_spin.h>
#include <elements/junction_moment.h>

#include <vector>

namespace rodnet
{
  namespace
  {
    /// Adds the linear and angular momenta of @p momentum = M v at @p u to
    /// @p motion, both read by global index (whole on this process).
    void
    add_momenta(const SolvableModel &model,
                const VectorType    &u,
                const VectorType    &momentum,
                Motion              &motion)
    {
      // p = M v: on a vertex's position rows the momentum of the vertex
      // (junction ends are condensed onto their junction's vertex, whose
      // rows carry the mass of every adjacent segment). The ends' vertices
      // name the junction vertex's DoFs (DofLayout::vertex_dof()): each DoF
      // is counted once.
      std::vector<bool> counted(u.size(), false);
      for (unsigned int i = 0; i < model.network().n_vertices(); ++i)
        {
          const global_dof_index first = model.layout().vertex_dof(i, 0);
          if (counted[first])
            continue;
          counted[first] = true;
          Vector3 p;
          for (unsigned int c = 0; c < 3; ++c)
            p[c] = momentum[model.layout().vertex_dof(i, c)];
          motion.linear_momentum += p;
          motion.angular_momentum += model.position(u, i).cross(p);
        }
      // The spin of the sections about their centrelines: the twist rows of
      // M v are rho (I1 + I2) l0 theta', the angular momentum of a segment
      // about its unit tangent e (doc/dynamics.md, "Momenta under the
      // midpoint rule": with it the midpoint rule keeps the sum better than
      // the centreline's part).
      for (const SegmentStencil &segment : model.layout().segments())
        {
          const Vector3 e = model.position(u, segment.vertices[1]) -
                            model.position(u, segment.vertices[0]);
          motion.angular_momentum +=
            momentum[model.layout().twist_dof(segment.cell)] * e.normalized();
        }
      // A junction's rotation: the momentum conjugate to its quaternion
      // increment q is a covector on q, turned into the angular momentum as
      // a gradient into a moment (p.qdot = L.omega): at q = (1, 0), where the
      // integrator leaves it after every step, half its vector part (a
      // rigid body's j omega, with omega = 2 adot).
      for (unsigned int j = 0; j < model.network().junctions().size(); ++j)
        if (model.layout().has_rotation_dofs(j))
          {
            Eigen::Vector4d q, p;
            for (unsigned int c = 0; c < 4; ++c)
              {
                q[c] = (c == 0) + u[model.layout().rotation_dof(j, c)];
                p[c] = momentum[model.layout().rotation_dof(j, c)];
              }
            motion.angular_momentum += spatial_moment(q, p);
          }
    }
  } // namespace

  Motion
  motion_of(const SolvableModel &model,
            const MatrixType    &mass,
            const VectorType    &u,
            const VectorType    &v,
            const double         load_factor)
  {
    Motion motion;
    motion.kinetic_energy   = kinetic_energy(mass, v);
    motion.potential_energy = model.assemble(u, load_factor, nullptr, nullptr);
    VectorType momentum(v);
    mass.vmult(momentum, v);
    // The sums read DoFs anywhere: from replicas on several processes,
    // where each process gets the whole sum.
    const EveryEntry every_u(u), every_momentum(momentum);
    add_momenta(model, *every_u, *every_momentum, motion);
    // Bodies that turn with their junction (an inertia tensor, a centre
    // off the vertex), whose motion M does not carry in full.
    const BodySpin spin = tensor_body_spin(model, u, v);
    motion.kinetic_energy += spin.kinetic_energy;
    motion.linear_momentum += spin.linear_momentum;
    motion.angular_momentum += spin.angular_momentum;
    return motion;
  }
} // namespace rodnet
