#ifndef RODNET_SOLVERS_FREE_MOTIONS_H
#define RODNET_SOLVERS_FREE_MOTIONS_H

#include <core/rod_model.h>

#include <string>

namespace rodnet
{
  /**
   * The rigid motions that no support of @p model stops, at the state
   * @p u: for every connected part of the network (rods joined through
   * junctions), the infinitesimal translations t and rotations w about its
   * centroid c that leave every fixed DoF unchanged. Such a motion moves a
   * vertex by t + w x (x - c), the twist of a segment of unit tangent e by
   * w . e (the material frame turns with the rod, beyond the parallel
   * transport of the reference frame), and a junction's quaternion
   * increment by w / 2; it costs no energy, so the static tangent is
   * singular along it and no load can be balanced there.
   *
   * Returns an empty string if every part is held; otherwise one line
   * naming each free part and its motions ("rod 0 can translate along
   * (0, 0, 1) and rotate about the axis through vertex 0:start along
   * (0, 0, 1)"). Mechanisms inside a part (a rod turning freely about a
   * pinned junction) are not rigid motions of the part and are not found
   * here; a static solve reports them as a singular tangent.
   */
  std::string
  describe_free_motions(const RodModel &model, const VectorType &u);
} // namespace rodnet

#endif
