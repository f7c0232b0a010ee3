#ifndef RODNET_GEOMETRY_ROD_GENERATORS_H
#define RODNET_GEOMETRY_ROD_GENERATORS_H

#include <elements/quaternion.h>

#include <vector>

namespace rodnet
{
  /**
   * Vertex positions of common rod geometries, uniformly discretized. They
   * throw std::invalid_argument naming the offending argument for
   * degenerate input (zero length or radius, fewer than one segment).
   *
   * <h3>Midpoint clamp</h3>
   * A clamp fixes the first two vertices of a rod; the first hinge's
   * Voronoi cell begins at the first segment's midpoint, so that is where
   * the discrete clamp acts, holding the first segment's direction
   * (doc/theory.md, "Clamps"). With @p clamp_at_start_midpoint an open
   * generator centres its first segment on the curve's start and lays it
   * along the curve's tangent there: vertex 0 is x(0) - (l/2) t(0), vertex
   * 1 is x(0) + (l/2) t(0), and vertices 2..n follow the curve at arc
   * lengths (i - 1/2) l, with l = L / (n - 1/2) for n segments. A clamp of
   * the start then holds the tangent of the curve exactly at its start,
   * and the free length is the curve's length L. Vertex 1 lies off a
   * curved curve by kappa l^2 / 8, a second-order error like that of the
   * discretization.
   */
  namespace generators
  {
    /// Straight rod from @p start to @p end with @p n_segments segments
    /// (midpoint clamp: see above).
    std::vector<Vector3>
    straight(const Vector3 &start,
             const Vector3 &end,
             unsigned int   n_segments,
             bool           clamp_at_start_midpoint = false);

    /// Circular arc of @p radius about @p center in the plane spanned by
    /// the orthonormal @p e1, @p e2, from angle @p angle0 to @p angle1 (rad)
    /// (midpoint clamp: see above).
    std::vector<Vector3>
    arc(const Vector3 &center,
        double         radius,
        const Vector3 &e1,
        const Vector3 &e2,
        double         angle0,
        double         angle1,
        unsigned int   n_segments,
        bool           clamp_at_start_midpoint = false);

    /// Closed ring of @p n_segments segments (the first vertex is not
    /// repeated), wound @p turns times around the circle: vertex k at the
    /// angle 2 pi turns k / n_segments (a multiply covered ring; its
    /// vertices are distinct where n_segments is not a multiple of turns).
    std::vector<Vector3>
    ring(const Vector3 &center,
         double         radius,
         const Vector3 &e1,
         const Vector3 &e2,
         unsigned int   n_segments,
         unsigned int   turns = 1);

    /// Helix x = r cos t, y = r sin t, z = c t about the z axis for t in
    /// [0, 2 pi turns] (midpoint clamp: see above).
    std::vector<Vector3>
    helix(double       radius,
          double       pitch_over_2pi,
          double       turns,
          unsigned int n_segments,
          bool         clamp_at_start_midpoint = false);

    /// Polyline through @p corners, each piece split into
    /// @p segments_per_piece equal segments; with the midpoint clamp the
    /// first piece is laid out as straight() lays out a rod.
    std::vector<Vector3>
    polyline(const std::vector<Vector3> &corners,
             unsigned int                segments_per_piece,
             bool                        clamp_at_start_midpoint = false);

    /**
     * The midpoint clamp for a given open chain (a mesh's): its first
     * vertex p0 is replaced by p0 - (l/2) t and p0 + (l/2) t, with l and t
     * the length and direction of the first segment p0 p1. The first
     * segment is then centred on p0 along the chain's start tangent, the
     * second (to p1) has length l/2, and the free length of a rod clamped
     * at its start is that of the chain. The other vertices are kept, so
     * the chain gains one segment.
     */
    std::vector<Vector3>
    center_first_segment_on_start(const std::vector<Vector3> &chain);
  } // namespace generators
} // namespace rodnet

#endif
