#ifndef RODNET_IO_PROBE_PLOT_H
#define RODNET_IO_PROBE_PLOT_H

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * Plots a probe table (see ProbeTable: a header
   * `step,<abscissa>,<probe names>` and one row per converged step) as a
   * PNG with one panel per probe against the abscissa (the load factor or
   * the time, labelled by its column name). The gnuplot
   * script is kept next to the image as `<png_path>.gp`, so that a user can
   * restyle the plot and run it again. With @p x_range, the panels show
   * that range of the abscissa only (a time history after its preload).
   * @p units, if given, are the units of the columns after "step" (the
   * abscissa first), shown in brackets in the axis labels: "tip_y [m]".
   * The last @p unplotted columns get no panel (text, such as the status
   * of a study's runs). Where the table has a column "stable" (Newton and
   * continuation runs), the rows where it is 0 are drawn dashed and red:
   * unstable equilibria.
   *
   * Plotting is a convenience: if the table cannot be read, has no probe or
   * no row, or gnuplot is missing or fails, one warning line goes to
   * std::cerr and the function returns false. It never throws; it returns
   * true when the PNG was written.
   */
  bool
  plot_probes(
    const std::string                              &csv_path,
    const std::string                              &png_path,
    const std::string                              &title,
    const std::optional<std::pair<double, double>> &x_range = std::nullopt,
    const std::vector<std::string>                 &units   = {},
    unsigned int                                    unplotted = 0);
} // namespace rodnet

#endif
