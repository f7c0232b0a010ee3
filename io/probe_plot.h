#ifndef RODNET_IO_PROBE_PLOT_H
#define RODNET_IO_PROBE_PLOT_H

#include <io/probe_plot_plan.h>

#include <string>

namespace rodnet
{
  /**
   * Plots a probe table (probes.csv: a header `step,<abscissa>,<probe
   * names>,<checks>` and one row per recorded step; or a study's
   * summary.csv) as a PNG, planned by plan_probe_plot(): one panel per
   * probe that varies against the abscissa (labelled with its unit), the
   * probes that do not and the checks that hold throughout stated under
   * the title, unstable states dashed and in open red points, lines
   * broken between branches and at jumps. The gnuplot script, with the
   * data it draws as data blocks, is kept next to the image as
   * `<png_path>.gp`, so that a user can restyle the plot and run it again.
   *
   * Plotting is a convenience: if the table cannot be read, has no row or
   * no probe that varies, or gnuplot is missing or fails, one warning
   * line goes to std::cerr and the function returns false. It never
   * throws; it returns true when the PNG was written.
   */
  bool
  plot_probes(const std::string      &csv_path,
              const std::string      &png_path,
              const ProbePlotOptions &options = {});
} // namespace rodnet

#endif
