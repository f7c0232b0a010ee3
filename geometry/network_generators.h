#ifndef RODNET_GEOMETRY_NETWORK_GENERATORS_H
#define RODNET_GEOMETRY_NETWORK_GENERATORS_H

#include <geometry/rod_graph.h>

namespace rodnet
{
  /**
   * Beam networks of the validation examples and lattices of Lestringant &
   * Kochmann (2020), sections 3 and 4. The node names are part of the
   * interface: scenes refer to junctions and free ends by them. They throw
   * std::invalid_argument naming the argument for a non-positive length or
   * an empty lattice.
   */
  namespace network_generators
  {
    /**
     * The clamped right-angle frame of L&K Fig. 3a: two beams of length
     * @p L welded at a right angle in the xy-plane. Nodes: "clamp" (0,0,0),
     * clamped; "corner" (L,0,0), welded; "tip" (L,L,0), a free end (where
     * the out-of-plane displacement is applied). Beams: clamp -> corner,
     * corner -> tip, in no group; d1 = e_z (out of plane).
     */
    RodGraph
    right_angle_frame(double L);

    /**
     * The windmill of L&K Fig. 3b: a vertical shaft of length
     * @p shaft_length = L_a and three horizontal blades of length
     * L_b = L_a / 2, welded at the hub.
     *
     * Nodes: "hub" (0,0,0), welded; "top" (0,0,L_a), clamped (the twist is
     * prescribed as the rotation of this clamp); "blade1", "blade2",
     * "blade3" at L_b (cos t, sin t, 0) for t = 90, 210, 330 degrees. The
     * blade tips are "attached" in the paper; their kind is left unset (free
     * ends) and the scene decides how they are supported, e.g. by pinning
     * the vertices "@blade1" ... .
     *
     * Beams: 0 hub -> top (group "shaft", d1 = e_x), 1-3 hub -> blade k
     * (group "blades", d1 = e_z).
     */
    RodGraph
    windmill(double shaft_length);

    /**
     * A planar square lattice of @p nx by @p ny square cells of side @p a:
     * nodes "n_i_j" at (i a, j a, 0) for i = 0..nx, j = 0..ny (node index
     * j (nx + 1) + i). Beams: first the horizontal ones n_i_j -> n_(i+1)_j
     * (group "x-beams"), ordered by j then i; then the vertical ones n_i_j
     * -> n_i_(j+1) (group "y-beams"), ordered by j then i; each also in
     * group "boundary" (on the lattice's edge) or "interior". d1 = e_z for
     * all (L&K
     * section 4.3). Kinds are unset: every node joins two beams or more and
     * is welded; scenes choose supports.
     */
    RodGraph
    square_lattice(unsigned int nx, unsigned int ny, double a);

    /**
     * A planar honeycomb of @p nx by @p ny hexagonal cells of side @p a.
     * The hexagons have two sides parallel to y (corners at 30 + 60 k
     * degrees from their centre); a row holds nx cells side by side along
     * x, and every odd row is shifted by half a cell to +x, so that rows
     * nest. The lattice starts at x = 0 and y = 0.
     *
     * Corners lie on the grid x = X sqrt(3) a / 2, y = Y a / 2 with
     * integers X, Y; node "n_X_Y" is the corner there. Nodes are ordered by
     * Y, then X; each shared side is one beam, from its node of lower index
     * to the higher one, beams ordered by those two indices. Groups
     * "boundary" (the sides of one cell) and "interior" (of two), d1 = e_z,
     * kinds unset (welded). A patch has
     * 2 nx ny + 2 nx + 2 ny nodes and 3 nx ny + 2 nx + 2 ny - 1 beams.
     */
    RodGraph
    hexagonal_lattice(unsigned int nx, unsigned int ny, double a);
  } // namespace network_generators
} // namespace rodnet

#endif
