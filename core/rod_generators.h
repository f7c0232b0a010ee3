#ifndef RODNET_CORE_ROD_GENERATORS_H
#define RODNET_CORE_ROD_GENERATORS_H

#include <elements/quaternion.h>

#include <vector>

namespace rodnet
{
  /**
   * Vertex positions of common rod geometries, uniformly discretized. They
   * throw std::invalid_argument naming the offending argument for
   * degenerate input (zero length or radius, fewer than one segment).
   */
  namespace generators
  {
    /**
     * Straight rod from @p start to @p end with @p n_segments segments. With
     * @p clamp_at_start_midpoint the chain begins half a segment behind
     * @p start: a clamp that fixes the first two vertices then holds the
     * tangent at @p start exactly, which is where the discrete clamp acts
     * (the first hinge's Voronoi cell begins at the first segment's
     * midpoint), so that the free length is |end - start|.
     */
    std::vector<Vector3>
    straight(const Vector3 &start,
             const Vector3 &end,
             unsigned int   n_segments,
             bool           clamp_at_start_midpoint = false);

    /// Circular arc of @p radius about @p center in the plane spanned by
    /// the orthonormal @p e1, @p e2, from angle @p angle0 to @p angle1 (rad).
    std::vector<Vector3>
    arc(const Vector3 &center,
        double         radius,
        const Vector3 &e1,
        const Vector3 &e2,
        double         angle0,
        double         angle1,
        unsigned int   n_segments);

    /// Closed ring of @p n_segments segments (the first vertex is not
    /// repeated).
    std::vector<Vector3>
    ring(const Vector3 &center,
         double         radius,
         const Vector3 &e1,
         const Vector3 &e2,
         unsigned int   n_segments);

    /// Helix x = r cos t, y = r sin t, z = c t about the z axis for t in
    /// [0, 2 pi turns].
    std::vector<Vector3>
    helix(double       radius,
          double       pitch_over_2pi,
          double       turns,
          unsigned int n_segments);

    /// Polyline through @p corners, each piece split into
    /// @p segments_per_piece equal segments.
    std::vector<Vector3>
    polyline(const std::vector<Vector3> &corners,
             unsigned int                segments_per_piece);
  } // namespace generators
} // namespace rodnet

#endif
