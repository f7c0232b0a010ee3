#ifndef RODNET_IO_OUTPUT_DIRECTORY_H
#define RODNET_IO_OUTPUT_DIRECTORY_H

#include <string>

namespace rodnet
{
  /// Creates @p directory (and its parents) if needed; throws
  /// std::invalid_argument saying why it cannot hold a run's outputs (a
  /// file of that name, no permission to write).
  void
  prepare_output_directory(const std::string &directory);
} // namespace rodnet

#endif
