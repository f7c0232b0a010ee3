#ifndef RODNET_IO_ROD_GENERATOR_ENTRIES_H
#define RODNET_IO_ROD_GENERATOR_ENTRIES_H

#include <io/generator_registry.h>

namespace rodnet
{
  /// Registers the generators of plain rods with @p registry: straight,
  /// arc, ring, helix, polyline and gmsh (a rod per physical tag).
  void
  register_rod_generators(GeneratorRegistry &registry);
} // namespace rodnet

#endif
