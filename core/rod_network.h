#ifndef RODNET_CORE_ROD_NETWORK_H
#define RODNET_CORE_ROD_NETWORK_H

#include <deal.II/grid/tria.h>

#include <elements/quaternion.h>

#include <string>
#include <vector>

namespace rodnet
{
  /**
   * One rod of a network: an ordered chain of vertices of the triangulation,
   * its segments (cells) in the same order, and the direction that fixes the
   * orientation of its first director d1.
   */
  struct Rod
  {
    /// Vertex indices of the triangulation, in order along the rod. For a
    /// closed rod the first vertex is not repeated at the end.
    std::vector<unsigned int> vertices;
    /// Active cell indices of the segments: segment j joins vertices j, j+1.
    std::vector<unsigned int> segments;
    /// Whether the last vertex connects back to the first one.
    bool closed = false;
    /// d1 of the undeformed configuration is this vector made orthogonal
    /// to each segment's tangent.
    Vector3 director_hint = Vector3::UnitY();
    /// Name of the hinge kernel of the rod ("simple" or "classic").
    std::string hinge_kernel = "simple";
  };

  /**
   * The undeformed geometry of a set of rods as a Triangulation<1,3>, with
   * each rod's vertex chain. Every cell belongs to exactly one rod; its
   * vertex 0 -> vertex 1 direction follows the rod.
   */
  class RodNetwork
  {
  public:
    RodNetwork();

    /**
     * Adds a rod through @p points (open, or closed when @p closed). Points
     * are checked: consecutive points closer than a relative tolerance are a
     * zero-length segment, other coincident points are reported too; the
     * error names the rod and the vertex indices.
     */
    void
    add_rod(const std::vector<Vector3> &points,
            bool                        closed,
            const Vector3              &director_hint,
            const std::string          &hinge_kernel);

    /// Builds the triangulation from the rods added so far. Call once.
    void
    create_triangulation();

    const dealii::Triangulation<1, 3> &
    triangulation() const
    {
      return tria;
    }

    const std::vector<Rod> &
    rods() const
    {
      return rod_list;
    }

    /// Undeformed position of triangulation vertex @p v.
    Vector3
    vertex(unsigned int v) const
    {
      return points[v];
    }

    unsigned int
    n_vertices() const
    {
      return points.size();
    }

  private:
    dealii::Triangulation<1, 3> tria;
    std::vector<Vector3>        points;
    std::vector<Rod>            rod_list;
  };
} // namespace rodnet

#endif
