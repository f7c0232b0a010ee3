#include <io/probe_plot.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace rodnet
{
  namespace
  {
    /// Fields of one CSV line; a field may be double-quoted with "" for a
    /// quote (RFC 4180).
    std::vector<std::string>
    split_csv_line(const std::string &line)
    {
      std::vector<std::string> fields(1);
      bool                     quoted = false;
      for (std::size_t i = 0; i < line.size(); ++i)
        {
          const char c = line[i];
          if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            {
              fields.back() += '"';
              ++i;
            }
          else if (c == '"')
            quoted = !quoted;
          else if (c == ',' && !quoted)
            fields.emplace_back();
          else
            fields.back() += c;
        }
      return fields;
    }

    /// @p text as a gnuplot single-quoted string, in which nothing but a
    /// doubled quote is special: names and paths cannot break the script.
    std::string
    quote(const std::string &text)
    {
      std::string quoted = "'";
      for (const char c : text)
        quoted += (c == '\'') ? std::string("''") : std::string(1, c);
      return quoted + "'";
    }

    /**
     * Runs `gnuplot script`; returns an empty string on success, otherwise
     * why it failed (the last line gnuplot printed to stderr, if any).
     * posix_spawnp rather than std::system: no shell sees the path.
     */
    std::string
    run_gnuplot(const std::string &script)
    {
      std::array<int, 2> pipe_ends;
      // Close-on-exec: no other program started meanwhile by another
      // thread inherits the pipe (dup2 clears the flag on the child's
      // stderr).
      if (pipe2(pipe_ends.data(), O_CLOEXEC) != 0)
        return std::string("cannot create a pipe: ") + std::strerror(errno);

      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
      posix_spawn_file_actions_addopen(&actions,
                                       STDOUT_FILENO,
                                       "/dev/null",
                                       O_WRONLY,
                                       0);

      std::string program  = "gnuplot";
      std::string argument = script;
      char *const argv[]   = {program.data(), argument.data(), nullptr};
      pid_t       pid;
      const int   spawn_error =
        posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
      posix_spawn_file_actions_destroy(&actions);
      close(pipe_ends[1]);
      if (spawn_error != 0)
        {
          close(pipe_ends[0]);
          return std::string("cannot run gnuplot: ") +
                 std::strerror(spawn_error);
        }

      // Drain stderr before waiting, so that a chatty gnuplot cannot block
      // on a full pipe.
      std::string            messages;
      std::array<char, 4096> buffer;
      ssize_t                n;
      while ((n = read(pipe_ends[0], buffer.data(), buffer.size())) > 0 ||
             (n < 0 && errno == EINTR))
        if (n > 0)
          messages.append(buffer.data(), n);
      close(pipe_ends[0]);

      int status = 0;
      while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
          return std::string("waiting for gnuplot failed: ") +
                 std::strerror(errno);

      if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return "";
      // gnuplot ends its report of a script error with the message itself,
      // after the offending line and a caret.
      std::string       last_line;
      const std::size_t end = messages.find_last_not_of(" \t\r\n");
      if (end != std::string::npos)
        {
          const std::size_t newline = messages.rfind('\n', end);
          const std::size_t begin =
            (newline == std::string::npos) ? 0 : newline + 1;
          last_line = messages.substr(begin, end + 1 - begin);
        }
      const std::string exit_text =
        WIFEXITED(status) ?
          "gnuplot exited with code " + std::to_string(WEXITSTATUS(status)) :
          "gnuplot was killed";
      return last_line.empty() ? exit_text : exit_text + ": " + last_line;
    }

    /// "tip_y [m]": the label of column @p c (counted after "step"), named
    /// @p name, with its unit in @p units if that has one.
    std::string
    axis_label(const std::string              &name,
               const std::vector<std::string> &units,
               const std::size_t               c)
    {
      return c < units.size() && !units[c].empty() ?
               name + " [" + units[c] + "]" :
               name;
    }

    /// Columns of a probe table (1-based, 0 where it has none) that say
    /// how its rows lie on a path.
    struct PathColumns
    {
      int stable    = 0;
      int arclength = 0;
      int jump      = 0;
      /// Whether some row has jump = 1.
      bool has_jumps = false;
    };

    /**
     * The gnuplot command of the panel of column @p column (1-based) of
     * @p csv_path against column 2. Where the table says which rows are
     * stable equilibria (@p path.stable), those are drawn solid and the
     * unstable ones dashed red, as charts of load paths through buckling
     * and snap-through are read; the key only where @p key. A row starts
     * a new stretch of the path where its arclength falls below the one
     * before (the other side of a bifurcation, Switch branches = both) or
     * where the path jumped to it past a limit point (jump = 1, Limit
     * points = snap). The stretches alternate between two series, so that
     * no line joins one to the next and every row keeps its point; a jump
     * is drawn as a dashed black segment from the row before.
     */
    std::string
    plot_command(const std::string &csv_path,
                 const int          column,
                 const PathColumns &path,
                 const bool         key)
    {
      const std::string style = " with linespoints pointtype 7 pointsize 0.5";
      const auto        col   = [](const int c) {
        return "column(" + std::to_string(c) + ")";
      };
      std::string restart;
      if (path.arclength != 0)
        restart = col(path.arclength) + " < s0";
      if (path.has_jumps)
        restart += (restart.empty() ? "" : " || ") + col(path.jump) + " == 1";
      const std::string s0 = path.arclength != 0 ? col(path.arclength) : "0";
      const auto        series = [&](const std::string &y, const int stretch) {
        if (restart.empty())
          return quote(csv_path) + " skip 1 using 2:(" + y + ")";
        return "s0 = -1e300, p = 0, " + quote(csv_path) +
               " skip 1 using 2:(p = (" + restart +
               ") ? 1 - p : p, s0 = " + s0 +
               ", p == " + std::to_string(stretch) + " ? " + y + " : 1/0)";
      };
      const std::string y         = col(column);
      const int         stretches = restart.empty() ? 1 : 2;
      std::string       command;
      for (int stretch = 0; stretch < stretches; ++stretch)
        {
          const bool titled = key && stretch == 0;
          if (path.stable == 0)
            command += series(y, stretch) + style + " linecolor 1 notitle, ";
          else
            {
              const std::string unstable = col(path.stable) + " == 0";
              command += series(unstable + " ? 1/0 : " + y, stretch) + style +
                         " linecolor 1" +
                         (titled ? " title 'stable', " : " notitle, ") +
                         series(unstable + " ? " + y + " : 1/0", stretch) +
                         style + " dashtype 2 linecolor rgb '#d62728'" +
                         (titled ? " title 'unstable', " : " notitle, ");
            }
        }
      if (path.has_jumps)
        // From the row before to the jump's row (gnuplot evaluates the
        // using columns in order).
        command += "x0 = NaN, y0 = NaN, " + quote(csv_path) +
                   " skip 1 using (xp = x0, x0 = column(2), xp):(yp = y0, "
                   "y0 = " +
                   y + ", yp):(" + col(path.jump) +
                   " == 1 ? x0 - xp : 1/0):(y0 - yp) with vectors nohead "
                   "dashtype 2 linewidth 2 linecolor rgb 'black'" +
                   (key ? " title 'jump', " : " notitle, ");
      return "plot " + command.substr(0, command.size() - 2) + "\n";
    }

    /// Whether column @p column (1-based) of some row of the CSV file
    /// @p csv_path, after its header, holds the number 1.
    bool
    some_row_is_one(const std::string &csv_path, const int column)
    {
      std::ifstream csv(csv_path);
      std::string   line;
      std::getline(csv, line);
      while (std::getline(csv, line))
        {
          const std::vector<std::string> fields = split_csv_line(line);
          if (int(fields.size()) >= column &&
              std::strtod(fields[column - 1].c_str(), nullptr) == 1)
            return true;
        }
      return false;
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
  plot_probes(const std::string                              &csv_path,
              const std::string                              &png_path,
              const std::string                              &title,
              const std::optional<std::pair<double, double>> &x_range,
              const std::vector<std::string>                 &units,
              const unsigned int                              unplotted)
  {
    // A failed plot must never cost the user a finished computation.
    try
      {
        std::ifstream csv(csv_path);
        std::string   header;
        if (!csv || !std::getline(csv, header))
          return warn(png_path, "cannot read \"" + csv_path + "\"");
        if (!header.empty() && header.back() == '\r')
          header.pop_back();
        const std::vector<std::string> columns = split_csv_line(header);
        if (columns.size() < 3 + unplotted)
          return warn(png_path, "\"" + csv_path + "\" has no probe column");
        std::string line;
        bool        has_rows = false;
        while (!has_rows && std::getline(csv, line))
          has_rows = line.find_first_not_of(" \t\r") != std::string::npos;
        if (!has_rows)
          return warn(png_path, "\"" + csv_path + "\" has no rows yet");

        // Probes have different units: one panel each, in two columns when
        // there are many.
        const unsigned int n_probes = columns.size() - 2 - unplotted;
        const unsigned int n_cols   = n_probes > 4 ? 2 : 1;
        const unsigned int n_rows   = (n_probes + n_cols - 1) / n_cols;
        const std::string  size     = std::to_string(640 * n_cols) + "," +
                                 std::to_string(80 + 240 * n_rows);

        // "load factor" for the column "load_factor".
        std::string abscissa = columns[1];
        std::replace(abscissa.begin(), abscissa.end(), '_', ' ');

        const std::string script_path = png_path + ".gp";
        {
          std::ofstream script(script_path);
          if (!script)
            return warn(png_path,
                        "cannot write the script \"" + script_path + "\"");
          // pngcairo draws smoother lines, but not every gnuplot build has
          // it; the libgd png terminal is the fallback.
          script << "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                 << "  set terminal pngcairo noenhanced size " << size << "\n"
                 << "} else {\n"
                 << "  set terminal png noenhanced size " << size << "\n"
                 << "}\n"
                 << "set output " << quote(png_path) << "\n"
                 << "set datafile separator ','\n"
                 << "set xlabel " << quote(axis_label(abscissa, units, 0))
                 << "\n"
                 << "set grid\n";
          if (x_range && x_range->first < x_range->second)
            script << std::setprecision(17) << "set xrange [" << x_range->first
                   << ":" << x_range->second << "]\n";
          script << "set multiplot layout " << n_rows << "," << n_cols
                 << " title " << quote(title) << "\n";
          const auto column_of = [&](const std::string &name) {
            const auto c = std::find(columns.begin(), columns.end(), name);
            return c == columns.end() ? 0 : int(c - columns.begin()) + 1;
          };
          PathColumns path;
          path.stable    = column_of("stable");
          path.arclength = column_of("arclength");
          path.jump      = column_of("jump");
          path.has_jumps =
            path.jump != 0 && some_row_is_one(csv_path, path.jump);
          for (unsigned int p = 0; p < n_probes; ++p)
            script << "set ylabel "
                   << quote(axis_label(columns[p + 2], units, p + 1)) << "\n"
                   << plot_command(csv_path, p + 3, path, p == 0);
          script << "unset multiplot\n";
          if (!script)
            return warn(png_path,
                        "cannot write the script \"" + script_path + "\"");
        }

        const std::string failure = run_gnuplot(script_path);
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
