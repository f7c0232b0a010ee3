#ifndef RODNET_CORE_VERTEX_SELECTOR_H
#define RODNET_CORE_VERTEX_SELECTOR_H

#include <core/rod_network.h>

#include <optional>
#include <string>
#include <variant>

namespace rodnet
{
  /**
   * Resolves a vertex named in a scene to a triangulation vertex. Syntax:
   * `[rod:]where`, where `rod` is a rod index and `where` is `start`,
   * `end`, `mid` (the middle vertex), or a vertex index along the rod,
   * negative counting from the end (-1 = last); or `@name`, a vertex the
   * network named (junctions, network nodes). The rod may be left out only
   * where there is one rod. Throws std::invalid_argument naming @p entry
   * and the text for anything else: a `where` without its rod among
   * several rods, an unknown `@name` (listing the names, or the nearest
   * ones where there are many).
   */
  unsigned int
  select_vertex(const RodNetwork  &network,
                const std::string &text,
                const std::string &entry);

  /**
   * Resolves a rod end named in a scene: `[rod:]start` or `[rod:]end` (the
   * rod may be left out only where there is one rod), or
   * `@name` of a vertex that is a free rod end (a network node where one
   * beam ends) or that belongs to a junction. Returns the rod end, or the
   * junction's index; throws std::invalid_argument naming @p entry and the
   * text for anything else.
   */
  std::variant<RodEnd, unsigned int>
  select_rod_end(const RodNetwork  &network,
                 const std::string &text,
                 const std::string &entry);

  /// Where a moment or a prescribed rotation named in a scene acts.
  struct RotationTarget
  {
    /// The vertex (a junction's own vertex for a junction name).
    unsigned int vertex;
    /// The junction named, or the one the vertex belongs to.
    std::optional<unsigned int> junction;
  };

  /// Resolves @p text, a junction name or a vertex as select_vertex()
  /// takes it, to a RotationTarget; throws as select_vertex().
  RotationTarget
  select_rotation_target(const RodNetwork  &network,
                         const std::string &text,
                         const std::string &entry);
} // namespace rodnet

#endif
