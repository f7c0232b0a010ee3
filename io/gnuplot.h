#ifndef RODNET_IO_GNUPLOT_H
#define RODNET_IO_GNUPLOT_H

#include <string>

namespace rodnet
{
  /// @p text as a gnuplot single-quoted string, in which nothing but a
  /// doubled quote is special: names and paths cannot break a script.
  std::string
  gnuplot_quote(const std::string &text);

  /**
   * Runs `gnuplot @p script_path`; returns an empty string on success,
   * otherwise why it failed (the last line gnuplot printed to stderr, if
   * any). No shell sees the path.
   */
  std::string
  run_gnuplot(const std::string &script_path);

  /**
   * Keeps @p script, a gnuplot script that draws @p image_path, next to
   * the image as `<image_path>.gp` (a user can restyle it and run it
   * again) and runs it; returns an empty string on success, otherwise why
   * no image was drawn (the script cannot be written, gnuplot is missing
   * or fails: see run_gnuplot()).
   */
  std::string
  draw_with_gnuplot(const std::string &script, const std::string &image_path);
} // namespace rodnet

#endif
