#ifndef RODNET_CORE_MOTION_H
#define RODNET_CORE_MOTION_H

#include <core/solvable_model.h>

namespace rodnet
{
  /**
   * Energies and momenta of a model in motion, at the state (u, v) of a
   * dynamic time integrator: what the probes "kinetic energy", "potential
   * energy", "total energy", "linear momentum" and "angular momentum" read
   * (doc/dynamics.md, "Energy and momenta").
   */
  struct Motion
  {
    /// 1/2 v.Mv, plus what M leaves out of bodies that turn with their
    /// junction: the rotational energy 1/2 omega . R J_0 R^T omega of an
    /// inertia tensor, the motion of a centre off the vertex
    /// (core/tensor_body_spin.h).
    double kinetic_energy = 0;
    /// Pi(u, lambda): stored energy minus the work of the dead loads at the
    /// load factor lambda (SolvableModel::assemble()).
    double potential_energy = 0;
    /// Sum over the position DoFs of M v (a body's centre off its vertex
    /// counted at its own velocity, m xdot_c).
    Vector3 linear_momentum = Vector3::Zero();
    /// Sum over the vertices of x_i x (M v)_i, about the origin, plus the
    /// spin of the sections, sum over the segments of (M v)_twist e, e the
    /// unit tangent, and the spin of the junctions' rotations (a hub's
    /// j omega, a body's R J_0 R^T omega; a centre off the vertex
    /// x_c x m xdot_c; doc/dynamics.md).
    Vector3 angular_momentum = Vector3::Zero();
  };

  /**
   * The Motion of @p model at the displacement @p u and velocity @p v,
   * with the unconstrained mass matrix @p mass (assemble_mass_matrix())
   * and the load factor @p load_factor. Throws std::invalid_argument if
   * the sizes of @p v and @p mass differ.
   */
  Motion
  motion_of(const SolvableModel &model,
            const MatrixType    &mass,
            const VectorType    &u,
            const VectorType    &v,
            double               load_factor);
} // namespace rodnet

#endif
