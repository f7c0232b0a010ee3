#ifndef RODNET_IO_PROBE_PLOT_PLAN_H
#define RODNET_IO_PROBE_PLOT_PLAN_H

#include <io/csv_table.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * How to plot a table of probes (probes.csv, summary.csv): which column
   * is the abscissa, which are the probes (one panel each), and what the
   * columns after the probes, the run's checks of each row, are. Those
   * are read by name:
   * - `stable`: 0 where the state is an unstable equilibrium (drawn
   *   dashed, open red points), 1 where it is stable, anything else where
   *   it was not checked (step 0);
   * - `in_range`: 0 where a strain is past the rod model's range (a cross
   *   on the point);
   * - `branch` and `arclength` (continuation): where the branch changes,
   *   the line starts anew; it leaves from the row before only where the
   *   arclength goes on from there (a switched branch leaves its
   *   bifurcation), not where it falls (the other side of a bifurcation,
   *   followed afterwards). A row whose arclength falls below the one
   *   before also starts anew. The load factor turning back (a limit
   *   point) does not break the line;
   * - `jump`: 1 on the first row after a jump (a snap to a distant
   *   state): no line reaches it, a dotted arrow from the row before does;
   * - `finished`: 0 where the row is a run that stopped early (a study's
   *   summary): its own marker, and no line reaches it.
   */
  struct ProbePlotOptions
  {
    std::string title = "rodnet probes";
    /// Column (counted from 0) of the abscissa.
    std::size_t abscissa = 1;
    /// The probes: @p n_probes columns from @p first_probe (by default to
    /// the end of the table).
    std::size_t first_probe = 2;
    std::size_t n_probes    = std::numeric_limits<std::size_t>::max();
    /// Units of the abscissa, then of each probe in order ("m", "rad",
    /// "-", "" for none): the axis labels ("tip_y [m]") and the scales of
    /// rounding noise (see plan_probe_plot()).
    std::vector<std::string> units;
    /// Only the rows whose abscissa lies in this range, if given.
    std::optional<std::pair<double, double>> x_range;
    /// A text column naming each row's abscissa value, if given: the tics
    /// of the abscissa and its label (a study of scene files or of vectors
    /// against the run's number). Such rows are categories: points, no
    /// line between them.
    std::optional<std::size_t> tic_labels;
    /// A length scale of the model (m; 0 if none): positions are constant
    /// where they vary less than 1e-10 of it.
    double length_scale = 0;
    /// The smallest force the run's equilibria resolve (N; 0 if none
    /// given): forces (N) and moments (N m, with the length scale) that
    /// vary less than it are constant, and stated as 0 where they stay
    /// below it (reactions of supports that hold nothing).
    double force_resolution = 0;
    /// What a row is, for the notes: "step", "run's end".
    std::string row_name = "step";
    /// Whether plot_probes() warns where no probe varies (a study's
    /// summary does not: after its first runs, it may not yet).
    bool warn_if_flat = true;
  };

  /// A plot of a table planned: which rows each series draws.
  struct ProbePlotPlan
  {
    /// A panel: the column it shows and its axis label.
    struct Panel
    {
      std::size_t column;
      std::string label;
    };
    using Rows = std::vector<std::size_t>;

    std::string        x_label;
    std::vector<Panel> panels;
    /// Statements that replace panels and marks: the probes that do not
    /// vary ("tip_z = 0 m"), "stable at every step".
    std::vector<std::string> notes;
    /// Pieces of line, each the rows it joins in order.
    std::vector<Rows> stable_lines, unstable_lines;
    /// Rows drawn as points of each kind.
    Rows stable_points, unstable_points, out_of_range, unfinished;
    /// Jumps: (from, to) rows.
    std::vector<std::pair<std::size_t, std::size_t>> jumps;
    /// (value, label) of the abscissa's tics; empty: gnuplot's own.
    std::vector<std::pair<double, std::string>> x_tics;
  };

  /// The ratio to the scale of a unit's values (the largest magnitude of
  /// the probes in that unit, at least the model's length scale for "m" and
  /// 1 for "rad") below which a probe's variation is rounding noise: ten
  /// times below the solvers' default relative tolerance 1e-9, a variation
  /// no run resolves.
  constexpr double rounding_level = 1e-10;

  /**
   * Plans the plot of @p table: a panel per probe that varies over the
   * rows in range (more than rounding_level of its unit's scale), a note
   * for each that does not and for the checks that hold at every row, the
   * pieces of line between rows (see ProbePlotOptions for where they
   * break and which are dashed) and the points (every row's where there
   * are at most 150 rows, otherwise only those on no line).
   */
  ProbePlotPlan
  plan_probe_plot(const CsvTable &table, const ProbePlotOptions &options);
} // namespace rodnet

#endif
