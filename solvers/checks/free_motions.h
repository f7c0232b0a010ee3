#ifndef RODNET_SOLVERS_CHECKS_FREE_MOTIONS_H
#define RODNET_SOLVERS_CHECKS_FREE_MOTIONS_H

#include <core/solvable_model.h>
#include <solvers/checks/dof_roles.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * The connected parts of @p network, rods joined through junctions: for
   * every rod, the index of one rod of its part (the same for the whole
   * part), by union-find.
   */
  std::vector<unsigned int>
  rod_parts(const RodNetwork &network);

  /// The rod of DoF @p d (not inert) of @p roles: that of its vertex, its
  /// segment or (quaternions) the first rod end at its junction, or the rod
  /// a handle inside a rod sits in.
  unsigned int
  rod_of(const RodNetwork &network, const DofRoles &roles, global_dof_index d);

  /**
   * The rigid motions of @p model at the state @p u that neither a support
   * nor the energy stops: for every connected part of the network (rods
   * joined through junctions), the infinitesimal translations t and
   * rotations w about its centroid c that leave every fixed DoF unchanged
   * and along which the tangent is singular. Such a motion moves a vertex
   * by t + w x (x - c), the twist of a segment of unit tangent e by w . e
   * (the material frame turns with the rod, beyond the parallel transport
   * of the reference frame), and a junction's quaternion increment by w / 2
   * at the reference; no load can be balanced along it.
   *
   * The rods' own energy does not resist a rigid motion, but a family that
   * ties the rods to the ground does: an ElasticFoundation holds every
   * motion that moves a vertex along its springs. A rod on a foundation in
   * every direction is held unless it is straight: it can still spin about
   * its own line, which moves no vertex, only the twists; springs along z
   * alone leave the translations in x and y and the rotations about z.
   * The energy is asked through the Hessians of every element family's
   * stencils at @p u and load factor 0 (a load is no support), evaluated
   * only when the supports leave a part some motion, each family measured
   * against its own stiffness (a soft foundation under stiff rods holds as
   * well as a stiff one). This is exact where @p u is unstressed (rods
   * stress free as built, at their undeformed state); where it is
   * stressed, the geometric stiffness of the stresses is part of the
   * Hessians and can hold a rotation that no support holds.
   *
   * Returns an empty string if every part is held; otherwise one line
   * naming each free part and its motions ("rod 0 can translate along
   * (0, 0, 1) and rotate about the axis through vertex 0:start along
   * (0, 0, 1)"). Mechanisms inside a part (a rod turning freely about a
   * pinned junction) are not rigid motions of the part and are not found
   * here; a static solve reports them as a singular tangent.
   */
  std::string
  describe_free_motions(const SolvableModel &model, const VectorType &u);

  /**
   * The symmetry modes of @p model at the equilibrium @p u and
   * @p load_factor: motions along which the total potential does not
   * change, so that the tangent is singular along them at every point of
   * a branch, not only at a bifurcation. Candidates are, per connected
   * part, the rigid motions of describe_free_motions() and, for a single
   * rod without junctions, the turn of all its material frames about
   * their tangents (its twists change alike), combined so that no fixed
   * DoF moves; kept where the Hessians of every family at (@p u,
   * @p load_factor), each in its own units, do not resist them. The
   * buckled elastica with EI1 = EI2 has one: its plane turns about the
   * load axis while its frames turn back at the clamp. Combinations that
   * move no DoF (a straight rod about its line) are dropped. DoF vectors,
   * zero at fixed DoFs.
   */
  std::vector<VectorType>
  symmetry_modes(const SolvableModel &model,
                 const VectorType    &u,
                 double               load_factor);

  /**
   * The rods of @p model whose material frames can all turn together about
   * their tangents (all their twists changing alike) without changing the
   * energy at (@p u, @p load_factor): an isotropic section (EI1 = EI2)
   * without natural curvature, no twist of the rod fixed, and no junction
   * element or other family that resists the turn (each family's Hessian
   * in its own units, as describe_free_motions() asks, to rounding). The
   * discrete energy is exactly invariant under that turn, so the tangent
   * is singular along it at every state; a closed ring, which has no end
   * to clamp, always has it. Returns one free twist DoF per such rod, in
   * the order of the rods: holding it holds the turn.
   */
  std::vector<global_dof_index>
  free_frame_turns(const SolvableModel &model,
                   const VectorType    &u,
                   double               load_factor);
} // namespace rodnet

#endif
