#include <io/probe_plot_plan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace rodnet
{
  namespace
  {
    /// Rows that draw more points than this get lines only.
    constexpr std::size_t max_rows_with_points = 150;

    /// The columns of @p table and @p options, and the rows plotted.
    struct TableView
    {
      const CsvTable         &table;
      const ProbePlotOptions &options;
      std::size_t             n_probes;
      ProbePlotPlan::Rows     rows;

      TableView(const CsvTable &table, const ProbePlotOptions &options)
          : table(table)
          , options(options)
          , n_probes(
              std::min(options.n_probes,
                       table.names.size() -
                         std::min(table.names.size(), options.first_probe)))
      {
        for (std::size_t r = 0; r < table.rows.size(); ++r)
          {
            const double x = table.number(r, options.abscissa);
            if (std::isfinite(x) &&
                (!options.x_range ||
                 (x >= options.x_range->first && x <= options.x_range->second)))
              rows.push_back(r);
          }
      }

      /// The check @p name of row @p r (columns after the probes); NaN
      /// where the table has no such column.
      double
      check(const std::size_t r, const std::string &name) const
      {
        const auto c = table.column(name, options.first_probe + n_probes);
        return c ? table.number(r, *c) : std::nan("");
      }

      /// The unit of column @p c (the abscissa or a probe), "" if none.
      std::string
      unit(const std::size_t c) const
      {
        const std::size_t k =
          c == options.abscissa ? 0 : c - options.first_probe + 1;
        return k < options.units.size() ? options.units[k] : "";
      }
    };

    /// "tip_y [m]", or the name alone without a unit.
    std::string
    axis_label(const std::string &name, const std::string &unit)
    {
      return unit.empty() ? name : name + " [" + unit + "]";
    }

    /// "tip_z = 0 m" for a probe of @p value, shown 0 at rounding level.
    std::string
    constant_note(const std::string &name,
                  const std::string &unit,
                  const double       value,
                  const double       rounding)
    {
      char text[32];
      std::snprintf(text,
                    sizeof(text),
                    "%.6g",
                    std::abs(value) <= rounding ? 0.0 : value);
      const bool shown = !unit.empty() && unit != "-" && unit != "mixed";
      return name + " = " + text + (shown ? " " + unit : "");
    }

    /// Per unit, the scale of its values: the largest magnitude over the
    /// probes in it, at least the length scale for "m" and 1 for "rad".
    std::map<std::string, double>
    unit_scales(const TableView &view)
    {
      std::map<std::string, double> scales{{"m", view.options.length_scale},
                                           {"rad", 1.0}};
      for (std::size_t p = 0; p < view.n_probes; ++p)
        {
          const std::size_t c     = view.options.first_probe + p;
          double           &scale = scales[view.unit(c)];
          for (const std::size_t r : view.rows)
            if (const double v = view.table.number(r, c); std::isfinite(v))
              scale = std::max(scale, std::abs(v));
        }
      return scales;
    }

    /// The resolution of the equilibria in @p unit: the force resolution
    /// for forces, times the length scale for moments; 0 for the others.
    double
    resolution(const TableView &view, const std::string &unit)
    {
      if (unit == "N")
        return view.options.force_resolution;
      if (unit == "N m")
        return view.options.force_resolution * view.options.length_scale;
      return 0;
    }

    /// A panel for every probe that varies beyond rounding, a note for
    /// every other.
    void
    plan_panels(const TableView &view, ProbePlotPlan &plan)
    {
      const std::map<std::string, double> scales = unit_scales(view);
      for (std::size_t p = 0; p < view.n_probes; ++p)
        {
          const std::size_t  c    = view.options.first_probe + p;
          const std::string &name = view.table.names[c];
          const std::string  unit = view.unit(c);
          double             low = INFINITY, high = -INFINITY;
          unsigned int       n_values = 0;
          for (const std::size_t r : view.rows)
            if (const double v = view.table.number(r, c); std::isfinite(v))
              {
                low  = std::min(low, v);
                high = std::max(high, v);
                ++n_values;
              }
          // The empty unit is no unit: such a probe is only its own scale.
          const double scale    = unit.empty() ?
                                    std::max(std::abs(low), std::abs(high)) :
                                    scales.at(unit);
          const double rounding =
            std::max(rounding_level * scale, resolution(view, unit));
          if (n_values == 0)
            plan.notes.push_back(name + ": no value");
          else if (n_values == 1)
            plan.notes.push_back(constant_note(name, unit, low, rounding) +
                                 " (one " + view.options.row_name + " only)");
          else if (high - low <= rounding)
            plan.notes.push_back(
              constant_note(name, unit, (low + high) / 2, rounding));
          else
            plan.panels.push_back({c, axis_label(name, unit)});
        }
    }

    /// A note where the check @p name holds (1) or fails (0) at every
    /// row that has it, in the words @p holds or @p fails.
    void
    note_uniform_check(const TableView   &view,
                       const std::string &name,
                       const std::string &holds,
                       const std::string &fails,
                       ProbePlotPlan     &plan)
    {
      unsigned int n_true = 0, n_false = 0;
      for (const std::size_t r : view.rows)
        {
          const double value = view.check(r, name);
          n_true += value == 1;
          n_false += value == 0;
        }
      const std::string every = " at every " + view.options.row_name;
      if (n_true > 0 && n_false == 0)
        plan.notes.push_back(holds + every);
      else if (n_false > 0 && n_true == 0)
        plan.notes.push_back(fails + every);
    }

    /**
     * Whether a line joins row @p r to @p previous, the row drawn before
     * it: not across a jump, nor where the branch changes unless the
     * arclength goes on from @p previous (the branch leaves it), nor where
     * the arclength falls (the other side of a bifurcation).
     */
    bool
    joined(const TableView  &view,
           const std::size_t previous,
           const std::size_t r)
    {
      if (view.check(r, "jump") == 1)
        return false;
      const double s0 = view.check(previous, "arclength"),
                   s1 = view.check(r, "arclength");
      if (s1 < s0)
        return false;
      const double b0        = view.check(previous, "branch"),
                   b1        = view.check(r, "branch");
      const bool same_branch = b0 == b1 || (std::isnan(b0) && std::isnan(b1));
      // NaN compares false: without an arclength a new branch starts anew.
      return same_branch || s1 >= s0;
    }

    /// Adds the piece from row @p from to row @p to to @p lines: to the
    /// last line where it ends at @p from, otherwise as a new line.
    void
    add_piece(std::vector<ProbePlotPlan::Rows> &lines,
              const std::size_t                 from,
              const std::size_t                 to)
    {
      if (!lines.empty() && lines.back().back() == from)
        lines.back().push_back(to);
      else
        lines.push_back({from, to});
    }

    /// The pieces of line between the rows that are not unfinished runs,
    /// stable or unstable (dashed where either end is unstable), and the
    /// jumps.
    void
    plan_lines(const TableView &view, ProbePlotPlan &plan)
    {
      // Rows named by tics are categories: points, no lines.
      if (view.options.tic_labels)
        return;
      std::optional<std::size_t> previous;
      for (const std::size_t r : view.rows)
        {
          if (view.check(r, "finished") == 0)
            continue;
          if (previous && joined(view, *previous, r))
            {
              const bool unstable = view.check(*previous, "stable") == 0 ||
                                    view.check(r, "stable") == 0;
              add_piece(unstable ? plan.unstable_lines : plan.stable_lines,
                        *previous,
                        r);
            }
          else if (previous && view.check(r, "jump") == 1)
            plan.jumps.emplace_back(*previous, r);
          previous = r;
        }
    }

    /// The points: every row's where there are few, otherwise those of
    /// rows on no line; crosses where a strain is out of range, triangles
    /// for runs that stopped early.
    void
    plan_points(const TableView &view, ProbePlotPlan &plan)
    {
      std::vector<bool> on_a_line(view.table.rows.size(), false);
      for (const auto *lines : {&plan.stable_lines, &plan.unstable_lines})
        for (const ProbePlotPlan::Rows &line : *lines)
          for (const std::size_t r : line)
            on_a_line[r] = true;
      const bool every_row = view.rows.size() <= max_rows_with_points;
      for (const std::size_t r : view.rows)
        {
          if (view.check(r, "finished") == 0)
            plan.unfinished.push_back(r);
          else if (every_row || !on_a_line[r])
            (view.check(r, "stable") == 0 ? plan.unstable_points :
                                            plan.stable_points)
              .push_back(r);
          if (view.check(r, "in_range") == 0)
            plan.out_of_range.push_back(r);
        }
    }
  } // namespace

  ProbePlotPlan
  plan_probe_plot(const CsvTable &table, const ProbePlotOptions &options)
  {
    const TableView   view(table, options);
    ProbePlotPlan     plan;
    const std::size_t x_name =
      options.tic_labels ? *options.tic_labels : options.abscissa;
    std::string name = table.names.at(x_name);
    // "load factor" for the column "load_factor".
    std::replace(name.begin(), name.end(), '_', ' ');
    plan.x_label = axis_label(name, view.unit(options.abscissa));
    if (options.tic_labels)
      for (const std::size_t r : view.rows)
        plan.x_tics.emplace_back(table.number(r, options.abscissa),
                                 table.text(r, *options.tic_labels));

    plan_panels(view, plan);
    note_uniform_check(view, "stable", "stable", "unstable", plan);
    note_uniform_check(view,
                       "in_range",
                       "strains within the rod model's range",
                       "strains past the rod model's range",
                       plan);
    plan_lines(view, plan);
    plan_points(view, plan);
    return plan;
  }
} // namespace rodnet
