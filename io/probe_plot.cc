#include <io/gnuplot.h>
#include <io/probe_plot.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace rodnet
{
  namespace
  {
    /// Colours of the plot (those of matplotlib's default cycle: readable
    /// on a projector and by the colour-blind).
    const std::string blue = "'#1f77b4'", red = "'#d62728'",
                      orange = "'#ff7f0e'", grey = "'#7f7f7f'";

    /// Characters of a line of notes under the title, per panel column
    /// (615 pixels, some 8 per character of the title's font).
    constexpr std::size_t note_width = 70;

    /// @p value for a data block: 12 digits, NaN where undefined.
    std::string
    datum(const double value)
    {
      if (!std::isfinite(value))
        return "NaN";
      char text[32];
      std::snprintf(text, sizeof(text), "%.12g", value);
      return text;
    }

    /// Row @p r as a line of a data block: the abscissa, then every
    /// panel's value.
    std::string
    data_line(const CsvTable         &table,
              const ProbePlotOptions &options,
              const ProbePlotPlan    &plan,
              const std::size_t       r)
    {
      std::string line = datum(table.number(r, options.abscissa));
      for (const ProbePlotPlan::Panel &panel : plan.panels)
        line += " " + datum(table.number(r, panel.column));
      return line;
    }

    /// Writes the data block @p name of @p pieces, a blank line between
    /// two (gnuplot draws no line across it).
    void
    write_block(std::ostream                           &script,
                const std::string                      &name,
                const std::vector<ProbePlotPlan::Rows> &pieces,
                const CsvTable                         &table,
                const ProbePlotOptions                 &options,
                const ProbePlotPlan                    &plan)
    {
      script << name << " << EOD\n";
      for (std::size_t k = 0; k < pieces.size(); ++k)
        {
          if (k > 0)
            script << "\n";
          for (const std::size_t r : pieces[k])
            script << data_line(table, options, plan, r) << "\n";
        }
      script << "EOD\n";
    }

    /// The data blocks of @p plan: the pieces of line, the points of each
    /// kind, and the jumps (a row: where from, then where to).
    void
    write_data(std::ostream           &script,
               const CsvTable         &table,
               const ProbePlotOptions &options,
               const ProbePlotPlan    &plan)
    {
      script << "# The data drawn, columns: the abscissa, then each panel's "
                "probe.\n"
             << "# Lines break at blank lines: between branches, at jumps.\n";
      write_block(script,
                  "$stable_lines",
                  plan.stable_lines,
                  table,
                  options,
                  plan);
      write_block(script,
                  "$unstable_lines",
                  plan.unstable_lines,
                  table,
                  options,
                  plan);
      for (const auto &[name, rows] :
           {std::make_pair("$stable_points", &plan.stable_points),
            std::make_pair("$unstable_points", &plan.unstable_points),
            std::make_pair("$out_of_range", &plan.out_of_range),
            std::make_pair("$unfinished", &plan.unfinished)})
        write_block(script, name, {*rows}, table, options, plan);
      script << "$jumps << EOD\n";
      for (const auto &[from, to] : plan.jumps)
        script << data_line(table, options, plan, from) << " "
               << data_line(table, options, plan, to) << "\n";
      script << "EOD\n";
    }

    /// The title and the notes under it, wrapped to @p width characters.
    std::vector<std::string>
    title_lines(const std::string   &title,
                const ProbePlotPlan &plan,
                const std::size_t    width)
    {
      std::vector<std::string> lines{title};
      std::string              line;
      for (std::size_t k = 0; k < plan.notes.size(); ++k)
        {
          const std::string item =
            plan.notes[k] + (k + 1 < plan.notes.size() ? ";" : "");
          if (!line.empty() && line.size() + 1 + item.size() > width)
            {
              lines.push_back(line);
              line.clear();
            }
          line += (line.empty() ? "" : " ") + item;
        }
      if (!line.empty())
        lines.push_back(line);
      return lines;
    }

    /// A series of a panel: its data block (none where empty), how it is
    /// drawn and its title in the key.
    struct Series
    {
      bool        present;
      std::string data, style, key;
    };

    /// The series of panel @p k (1-based) that have data. Where every
    /// state is stable or every one unstable, the key does not say so:
    /// the notes do.
    std::vector<Series>
    panel_series(const ProbePlotPlan &plan, const std::size_t k)
    {
      const std::string y    = std::to_string(k + 1);
      const std::string to_x = std::to_string(plan.panels.size() + 2);
      const std::string to_y = std::to_string(plan.panels.size() + 2 + k);
      const bool        stable =
        !plan.stable_lines.empty() || !plan.stable_points.empty();
      const bool unstable =
        !plan.unstable_lines.empty() || !plan.unstable_points.empty();
      const bool both = stable && unstable;
      // Points alone are drawn larger.
      const bool lines =
        !plan.stable_lines.empty() || !plan.unstable_lines.empty();
      const std::string         size   = lines ? "0.6" : "1.2";
      const std::vector<Series> series = {
        {!plan.stable_lines.empty(),
         "$stable_lines using 1:" + y,
         "lines linewidth 2 linecolor rgb " + blue,
         both ? "stable" : ""},
        {!plan.unstable_lines.empty(),
         "$unstable_lines using 1:" + y,
         "lines linewidth 2 dashtype 2 linecolor rgb " + red,
         both ? "unstable" : ""},
        {!plan.stable_points.empty(),
         "$stable_points using 1:" + y,
         "points pointtype 7 pointsize " + size + " linecolor rgb " + blue,
         both && plan.stable_lines.empty() ? "stable" : ""},
        {!plan.unstable_points.empty(),
         "$unstable_points using 1:" + y,
         "points pointtype 6 pointsize 0.9 linecolor rgb " + red,
         both && plan.unstable_lines.empty() ? "unstable" : ""},
        // From (x, y) of the row before the jump to those of the row after
        // (columns n + 2 and n + 2 + k).
        {!plan.jumps.empty(),
         "$jumps using 1:" + y + ":($" + to_x + "-$1):($" + to_y + "-$" + y +
           ")",
         "vectors filled head size screen 0.012,25 dashtype 3 linewidth 2 "
         "linecolor rgb " +
           grey,
         "jump"},
        {!plan.out_of_range.empty(),
         "$out_of_range using 1:" + y,
         "points pointtype 2 pointsize 1.4 linecolor rgb 'black'",
         "strain out of range"},
        {!plan.unfinished.empty(),
         "$unfinished using 1:" + y,
         "points pointtype 8 pointsize 1.4 linewidth 1.5 linecolor rgb " +
           orange,
         "stopped early"}};
      std::vector<Series> present;
      std::copy_if(series.begin(),
                   series.end(),
                   std::back_inserter(present),
                   [](const Series &s) { return s.present; });
      return present;
    }

    /// Whether any of @p series has a title in the key.
    bool
    has_key(const std::vector<Series> &series)
    {
      return std::any_of(series.begin(), series.end(), [](const Series &s) {
        return !s.key.empty();
      });
    }

    /// The command that plots @p series, titled in the key where @p key.
    std::string
    plot_command(const std::vector<Series> &series, const bool key)
    {
      std::string command;
      for (const Series &s : series)
        command +=
          (command.empty() ? "plot " : ", \\\n     ") + s.data + " with " +
          s.style +
          (key && !s.key.empty() ? " title '" + s.key + "'" : " notitle");
      return command + "\n";
    }

    /// The abscissa's tics "set xtics ('a' 1, 'b' 2)", if @p plan has any.
    std::string
    tics_command(const ProbePlotPlan &plan)
    {
      if (plan.x_tics.empty())
        return "";
      std::string command = "set xtics (";
      for (std::size_t k = 0; k < plan.x_tics.size(); ++k)
        command += (k > 0 ? ", " : "") + gnuplot_quote(plan.x_tics[k].second) +
                   " " + datum(plan.x_tics[k].first);
      // Room for the labels of the first and last tics.
      return command + ")\nset offsets graph 0.1, graph 0.1, graph 0.05, " +
             "graph 0.05\n";
    }

    /**
     * Where the panels go, in pixels: a panel's axes 500 x 190, one
     * column of panels, two where there are more than four; room at the
     * left for the tics and label of the ordinate, below each panel for
     * those of the abscissa, above for the title and its notes, and below
     * everything for a one-line key. The axes of every panel line up.
     */
    struct Layout
    {
      std::size_t n_cols, n_rows;
      std::size_t width, height;
      /// "margins <left>,<right>,<bottom>,<top> spacing <x>,<y>" of
      /// `set multiplot layout`, in fractions of the image.
      std::string margins;

      Layout(const std::size_t n_panels,
             const std::size_t n_title_lines,
             const bool        key)
          : n_cols(n_panels > 4 ? 2 : 1)
          , n_rows((n_panels + n_cols - 1) / n_cols)
      {
        const double axes_x = 500, axes_y = 190, left = 90, right = 25,
                     gap_x = 115, gap_y = 70, top = 18 + 20 * n_title_lines,
                     bottom = 55 + (key ? 25 : 0);
        width  = left + right + n_cols * axes_x + (n_cols - 1) * gap_x;
        height = top + bottom + n_rows * axes_y + (n_rows - 1) * gap_y;
        std::ostringstream text;
        text << "margins " << left / width << "," << 1 - right / width << ","
             << bottom / height << "," << 1 - top / height << " spacing "
             << gap_x / width << "," << gap_y / height;
        margins = text.str();
      }
    };

    /// Writes the gnuplot script of @p plan that draws @p png_path.
    void
    write_script(std::ostream           &script,
                 const std::string      &png_path,
                 const CsvTable         &table,
                 const ProbePlotOptions &options,
                 const ProbePlotPlan    &plan)
    {
      // Probes have different units: one panel each.
      const std::size_t              n_panels = plan.panels.size();
      const bool                     key      = has_key(panel_series(plan, 1));
      const std::vector<std::string> lines =
        title_lines(options.title, plan, note_width * (n_panels > 4 ? 2 : 1));
      const Layout layout(n_panels, lines.size(), key);
      std::string  title;
      for (const std::string &line : lines)
        title += (title.empty() ? "" : ".\"\\n\".") + gnuplot_quote(line);
      const std::string size =
        std::to_string(layout.width) + "," + std::to_string(layout.height);
      // pngcairo draws smoother lines, but not every gnuplot build has it;
      // the libgd png terminal is the fallback.
      script << "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
             << "  set terminal pngcairo noenhanced size " << size
             << " font ',11'\n"
             << "} else {\n"
             << "  set terminal png noenhanced size " << size << "\n"
             << "}\n"
             << "set output " << gnuplot_quote(png_path) << "\n";
      write_data(script, table, options, plan);
      script << "set xlabel " << gnuplot_quote(plan.x_label) << "\n"
             << "set grid\n"
             // A margin around the data, so that no point sits on the
             // border: the abscissa's range is that of the data.
             << "set autoscale xfix\n"
             << "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n"
             << tics_command(plan)
             // The key in one line at the bottom: it hides no data.
             << (key ? "set key horizontal at screen 0.5, screen 0.005 "
                       "center bottom\n" :
                       "unset key\n");
      if (options.x_range && options.x_range->first < options.x_range->second)
        script << "set xrange [" << datum(options.x_range->first) << ":"
               << datum(options.x_range->second) << "]\n";
      script << "set multiplot layout " << layout.n_rows << "," << layout.n_cols
             << " " << layout.margins << " title " << title << " font ',12'\n";
      // The key, where there is one, drawn with the first panel only.
      for (std::size_t k = 0; k < n_panels; ++k)
        script << (k == 1 ? "unset key\n" : "") << "set ylabel "
               << gnuplot_quote(plan.panels[k].label) << "\n"
               << plot_command(panel_series(plan, k + 1), k == 0);
      script << "unset multiplot\n";
    }

    bool
    warn(const std::string &png_path, const std::string &reason)
    {
      std::cerr << "warning: no probe plot \"" << png_path << "\": " << reason
                << std::endl;
      return false;
    }
  } // namespace

  bool
  plot_probes(const std::string      &csv_path,
              const std::string      &png_path,
              const ProbePlotOptions &options)
  {
    // A failed plot must never cost the user a finished computation.
    try
      {
        const CsvTable table = read_csv_table(csv_path);
        if (table.rows.empty())
          return warn(png_path, "\"" + csv_path + "\" has no rows yet");
        const ProbePlotPlan plan = plan_probe_plot(table, options);
        if (plan.panels.empty() && !options.warn_if_flat)
          return false;
        if (plan.panels.empty())
          {
            std::string notes;
            for (const std::string &note : plan.notes)
              notes += (notes.empty() ? " (" : "; ") + note;
            return warn(png_path,
                        "no probe varies" + notes + (notes.empty() ? "" : ")"));
          }
        std::ostringstream script;
        write_script(script, png_path, table, options, plan);
        const std::string failure = draw_with_gnuplot(script.str(), png_path);
        if (!failure.empty())
          return warn(png_path, failure);
        return true;
      }
    catch (const std::exception &e)
      {
        return warn(png_path, e.what());
      }
    catch (...)
      {
        return warn(png_path, "unknown exception");
      }
  }
} // namespace rodnet
