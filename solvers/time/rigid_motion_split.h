#ifndef RODNET_SOLVERS_TIME_RIGID_MOTION_SPLIT_H
#define RODNET_SOLVERS_TIME_RIGID_MOTION_SPLIT_H

#include <core/solvable_model.h>

#include <array>
#include <vector>

namespace rodnet
{
  /**
   * The rigid motions of the unsupported parts of a model (connected rods
   * none of whose positions, twists or junction rotations is held), and the
   * removal of their part from a force: what the midpoint rule's discrete
   * gradient needs to put its correction where it changes no momentum
   * (doc/dynamics.md, "Momenta under the midpoint rule").
   *
   * At a configuration x, the rigid motions of a free part are the columns
   * of R: three translations t_a (every vertex moves by e_a), three
   * rotations of the centreline r_a (a vertex by e_a x (x - c), c the
   * part's centre of mass) and three turns of the material frames s_a (the
   * twist of a segment of unit tangent e by e_a . e, and the vector part a
   * of a junction's increment q = (1, a) by (I - [a]_x + a a^T) e_a / 2,
   * its turn by e_a at real part 1). They are kept apart
   * so that a force orthogonal to all of them has no resultant, no moment
   * on the centreline and none on the frames. With the mass matrix M,
   * remove_rigid_part() takes f = M d to
   *   w = M d - M R alpha,  alpha = (R^T M R)^+ R^T M d,
   * i.e. M times the part of d that is M-orthogonal to the rigid motions
   * (the deformation of the step, as the mass measures it). Then
   * R^T w = 0 and w.d = |d - R alpha|_M^2 >= 0. The translations are M-
   * orthogonal to the rotations (c is the centre of mass of M's rows), so
   * the translation part is removed exactly; the six rotation columns are
   * solved together, scaled to unit diagonal, dropping directions of
   * relative size below 1e-12 (a straight part has no rotation about its
   * line; a planar one no turn of its frames about the normal).
   *
   * The junctions' turns matter where a rigid body's rotary inertia
   * gives their rows mass (RigidBody): without them w would put a moment
   * c w on the body, unbalanced, and the angular momentum of a free part
   * with a body would drift with the correction c.
   */
  class RigidMotionSplit
  {
  public:
    /// @p model must be finalized and outlive this object, @p mass is
    /// its unconstrained mass matrix, read at the first call only.
    RigidMotionSplit(const SolvableModel &model, const MatrixType &mass);

    /// Whether some part of the model is free.
    bool
    has_free_parts() const
    {
      return !parts.empty();
    }

    /**
     * Removes from @p force (M d for a step d) the part M R alpha of the
     * rigid motions of every free part at the displacement @p x, so that
     * it has neither resultant nor moment on any free part. Rows of
     * supported parts are left as they are.
     */
    void
    remove_rigid_part(const VectorType &x, VectorType &force);

  private:
    /// The communicator of the model's vectors.
    MPI_Comm
    communicator() const
    {
      return mass.get_mpi_communicator();
    }

    /// A DoF of this process that a rigid motion of a free part moves.
    struct MovedDof
    {
      global_dof_index dof;
      unsigned int     part;
      /// Position: 0, 1, 2; twist: 3; a junction's quaternion: 3 + its
      /// component (4, 5, 6 for the vector part).
      unsigned int component;
      /// Position: its vertex; twist: the vertices of its segment;
      /// quaternion: the junction (vertex).
      unsigned int vertex, next;
    };

    /// Mass and centre of mass of every part at @p x, from M t_a.
    void
    set_centres(const VectorType &x);

    /// The rotations r_a and turns s_a at @p x into rotations[0..5].
    void
    set_rotations(const VectorType &x);

    /// The turns s_a of the junction quaternion row @p m at @p x.
    void
    set_junction_turn(const VectorType &x, const MovedDof &m);

    const SolvableModel  &model;
    const MatrixType     &mass;
    std::vector<MovedDof> moved;
    /// Per free part: its mass and centre of mass, its rotation Gram
    /// matrix and right-hand side (scratch).
    struct Part
    {
      double  mass = 0;
      Vector3 centre;
    };
    std::vector<Part> parts;
    /// M t_a (constant), the rotation columns and M times them.
    std::array<VectorType, 3> mass_translations;
    std::array<VectorType, 6> rotations, mass_rotations;
    bool                      started = false;
  };
} // namespace rodnet

#endif
