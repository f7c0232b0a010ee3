#ifndef RODNET_IO_OUTPUT_DIRECTORY_H
#define RODNET_IO_OUTPUT_DIRECTORY_H

#include <string>

namespace rodnet
{
  /// Creates @p directory (and its parents) if needed; throws
  /// std::invalid_argument saying why it cannot hold a run's outputs (a
  /// file of that name, no permission to write). Returns whether it made
  /// the directory.
  bool
  prepare_output_directory(const std::string &directory);

  /// Removes @p directory if it is empty (a run refused before it wrote
  /// anything leaves nothing behind); a directory with files stays.
  void
  remove_if_empty(const std::string &directory);
} // namespace rodnet

#endif
