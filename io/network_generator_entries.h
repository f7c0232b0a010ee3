#ifndef RODNET_IO_NETWORK_GENERATOR_ENTRIES_H
#define RODNET_IO_NETWORK_GENERATOR_ENTRIES_H

#include <io/generator_registry.h>

namespace rodnet
{
  /// Registers the generators of rod networks with @p registry: frame,
  /// windmill, square and hexagonal lattice, network file, gmsh
  /// network and block map (io/block_map.h).
  void
  register_network_generators(GeneratorRegistry &registry);
} // namespace rodnet

#endif
