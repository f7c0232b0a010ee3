#ifndef RODNET_CORE_DEAD_LOADS_H
#define RODNET_CORE_DEAD_LOADS_H

#include <core/rod_network.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * The dead forces of a model at load factor 1, as added: point forces on
   * vertices and forces per undeformed length on whole rods, each checked
   * against the network when added. RodModel and DrModel keep one each and
   * lump the distributed forces onto their own DoFs.
   */
  class DeadLoads
  {
  public:
    /// Throws std::invalid_argument if @p vertex is not a vertex of
    /// @p network.
    void
    add_point_force(const RodNetwork  &network,
                    const unsigned int vertex,
                    const Vector3     &force)
    {
      if (vertex >= network.n_vertices())
        throw std::invalid_argument("point force at vertex " +
                                    std::to_string(vertex) +
                                    ", which does not exist");
      point_forces.emplace_back(vertex, force);
    }

    /// Throws std::invalid_argument if @p rod is not a rod of @p network.
    void
    add_distributed_force(const RodNetwork  &network,
                          const unsigned int rod,
                          const Vector3     &force_per_length)
    {
      if (rod >= network.rods().size())
        throw std::invalid_argument("distributed force on rod " +
                                    std::to_string(rod) +
                                    ", which does not exist");
      distributed_forces.emplace_back(rod, force_per_length);
    }

    /**
     * Per vertex of @p network: its point forces plus the distributed
     * forces lumped by the undeformed Voronoi lengths, half of each segment
     * of the rod to either end (exact for the work of a uniform load on
     * linear interpolation; Korner et al. section 4). Both models add these
     * to their position DoFs.
     */
    std::vector<Vector3>
    vertex_forces(const RodNetwork &network) const
    {
      std::vector<Vector3> forces(network.n_vertices(), Vector3::Zero());
      for (const auto &[vertex, force] : point_forces)
        forces[vertex] += force;
      for (const auto &[rod_index, q] : distributed_forces)
        {
          const Rod         &rod = network.rods()[rod_index];
          const unsigned int n   = rod.vertices.size();
          for (unsigned int j = 0; j < (rod.closed ? n : n - 1); ++j)
            {
              const unsigned int a = rod.vertices[j];
              const unsigned int b = rod.vertices[(j + 1) % n];
              const double       half =
                0.5 * (network.vertex(b) - network.vertex(a)).norm();
              forces[a] += half * q;
              forces[b] += half * q;
            }
        }
      return forces;
    }

    /// (vertex, force) pairs.
    std::vector<std::pair<unsigned int, Vector3>> point_forces;
    /// (rod, force per undeformed length) pairs.
    std::vector<std::pair<unsigned int, Vector3>> distributed_forces;
  };
} // namespace rodnet

#endif
