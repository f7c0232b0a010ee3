// Energies and momenta of a rod network in motion, for probes.
#include <core/mass_matrix.h>
#include <core/motion.h>

namespace rodnet
{
  Motion
  motion_of(const RodModel   &model,
            const MatrixType &mass,
            const VectorType &u,
            const VectorType &v,
            const double      load_factor)
  {
    Motion motion;
    motion.kinetic_energy   = kinetic_energy(mass, v);
    motion.potential_energy = model.assemble(u, load_factor, nullptr, nullptr);
    // p = M v: on a vertex's position rows the momentum of the vertex
    // (junction ends are condensed onto their junction's vertex, whose
    // rows carry the mass of every adjacent segment).
    VectorType momentum(v);
    mass.vmult(momentum, v);
    for (unsigned int i = 0; i < model.network().n_vertices(); ++i)
      {
        Vector3 p;
        for (unsigned int c = 0; c < 3; ++c)
          p[c] = momentum[model.layout().vertex_dof(i, c)];
        motion.linear_momentum += p;
        motion.angular_momentum += model.position(u, i).cross(p);
      }
    return motion;
  }
} // namespace rodnet
