// The peer figures of ../shared/BENCHMARKS.md, read when a benchmark
// runs.
//
// The benchmark programs set their figures beside those of established codes
// (DisMech, DRMSimulationModel, fabsim). BENCHMARKS.md is re-measured from
// time to time: DisMech's P1 times of 2026-12-01, copied into
// p1_gravity_cantilever, were 1.4x those measured side by side with rodnet on
// 2026-12-04, and the program went on printing ratios against the old ones.
// A copy goes stale without a sign, so the programs read the tables of
// BENCHMARKS.md as they stand (the file named by --peers) and label every
// ratio with the date of the figure and its source. A table whose columns
// are not found stops the program with the file, the section and the column.
//
// The date of a row is the first date (YYYY-MM-DD) written in the row; a row
// without one that continues the row above (its first cell starts with the
// same word, as "DisMech | same, dt 0.1") has that row's date, any other the
// first date of the section's text before the table ("Peers re-measured
// 2026-12-04"), else "undated". A cell "a / b" holds two figures, one per
// row: "1e3 / 1e5 | 3.62e5 / 2.98e5" are two rows.
#ifndef RODNET_BENCH_PEER_FIGURES_H
#define RODNET_BENCH_PEER_FIGURES_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace rodnet
{
  namespace bench
  {
    /// The file of peer figures a benchmark reads unless --peers names
    /// another: ../shared/BENCHMARKS.md beside the source tree.
    inline const std::string default_peer_file =
      RODNET_SOURCE_DIR "/../shared/BENCHMARKS.md";

    /// One row of a table of BENCHMARKS.md: a cell per column, and the date
    /// of its figures.
    struct PeerTableRow
    {
      std::vector<std::string> cells;
      std::string              date;
    };

    /// The first table of a section of BENCHMARKS.md.
    struct PeerTable
    {
      std::string               file, section;
      std::vector<std::string>  header;
      std::vector<PeerTableRow> rows;

      /// The index of the column whose header starts with @p name; throws
      /// naming the file, the section and the column if there is none.
      std::size_t
      column(const std::string &name) const
      {
        for (std::size_t c = 0; c < header.size(); ++c)
          if (header[c].compare(0, name.size(), name) == 0)
            return c;
        throw std::runtime_error(file + ", section \"" + section +
                                 "\": no column \"" + name + "\" in its table");
      }
    };

    namespace internal
    {
      inline std::string
      trim(const std::string &text)
      {
        const auto first = text.find_first_not_of(" \t");
        if (first == std::string::npos)
          return "";
        return text.substr(first, text.find_last_not_of(" \t") - first + 1);
      }

      /// The cells of the table line "| a | b |".
      inline std::vector<std::string>
      cells_of(const std::string &line)
      {
        std::vector<std::string> cells;
        std::size_t              start = line.find('|') + 1;
        for (std::size_t bar = line.find('|', start); bar != std::string::npos;
             start = bar + 1, bar = line.find('|', start))
          cells.push_back(trim(line.substr(start, bar - start)));
        return cells;
      }

      /// The first date YYYY-MM-DD in @p text, "" if none.
      inline std::string
      first_date(const std::string &text)
      {
        std::smatch match;
        return std::regex_search(text,
                                 match,
                                 std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2}")) ?
                 match.str() :
                 "";
      }

      /// The first word of @p cell (up to a space, comma or parenthesis).
      inline std::string
      first_word(const std::string &cell)
      {
        return cell.substr(0, cell.find_first_of(" ,("));
      }

      /// The rows of @p cells: one, or one per part where cells hold the
      /// same number (> 1) of parts "a / b".
      inline std::vector<std::vector<std::string>>
      split_pairs(const std::vector<std::string> &cells)
      {
        std::vector<std::vector<std::string>> parts(cells.size());
        std::size_t                           n_rows = 1;
        for (std::size_t c = 0; c < cells.size(); ++c)
          {
            std::size_t start = 0;
            for (std::size_t slash = cells[c].find(" / ", start);;
                 start = slash + 3, slash = cells[c].find(" / ", start))
              {
                parts[c].push_back(trim(cells[c].substr(start, slash - start)));
                if (slash == std::string::npos)
                  break;
              }
            n_rows = std::max(n_rows, parts[c].size());
          }
        std::vector<std::vector<std::string>> rows(n_rows);
        for (std::size_t r = 0; r < n_rows; ++r)
          for (std::size_t c = 0; c < cells.size(); ++c)
            rows[r].push_back(parts[c].size() == n_rows ? parts[c][r] :
                                                          cells[c]);
        return rows;
      }

      /// The leading number of @p cell ("0.0338 s", "2.4e-5 (x: 6.4e-5)"),
      /// NaN if it has none.
      inline double
      leading_number(const std::string &cell)
      {
        const char  *begin = cell.c_str();
        char        *end   = nullptr;
        const double value = std::strtod(begin, &end);
        return end == begin ? NAN : value;
      }

      /// The leading whole number of @p cell ("200", "1e3"), 0 if none.
      inline unsigned int
      whole_number(const std::string &cell)
      {
        const double value = leading_number(cell);
        return value > 0 ? static_cast<unsigned int>(value) : 0;
      }

      /// The number after "x:" in @p cell ("2.4e-5 (x: 6.4e-5)"), NaN if
      /// none.
      inline double
      x_part(const std::string &cell)
      {
        const auto x = cell.find("x:");
        return x == std::string::npos ? NAN :
                                        leading_number(cell.substr(x + 2));
      }
    } // namespace internal

    /// The first table of the section of @p file whose heading starts with
    /// "## " followed by @p section ("P1", "K1"), with the dates of its
    /// rows (see the top of this file). Throws if the file cannot be read
    /// or the section has no table.
    inline PeerTable
    read_peer_table(const std::string &file, const std::string &section)
    {
      std::ifstream in(file);
      if (!in)
        throw std::runtime_error("cannot read the peer figures in " + file +
                                 " (--peers names the file)");
      PeerTable   table{file, section, {}, {}};
      bool        in_section = false;
      std::string section_date, line;
      while (std::getline(in, line))
        {
          if (line.rfind("## ", 0) == 0)
            {
              if (in_section && !table.header.empty())
                break;
              in_section = line.rfind("## " + section, 0) == 0;
            }
          else if (in_section && line.rfind("|", 0) != 0 &&
                   table.header.empty())
            section_date =
              section_date.empty() ? internal::first_date(line) : section_date;
          else if (in_section && line.rfind("|", 0) == 0)
            {
              if (table.header.empty())
                table.header = internal::cells_of(line);
              else if (line.rfind("|---", 0) != 0)
                {
                  const std::vector<std::string> cells =
                    internal::cells_of(line);
                  std::string date = internal::first_date(line);
                  if (date.empty() && !table.rows.empty() &&
                      internal::first_word(table.rows.back().cells[0]) ==
                        internal::first_word(cells[0]))
                    date = table.rows.back().date;
                  if (date.empty())
                    date = section_date.empty() ? "undated" : section_date;
                  for (const auto &row : internal::split_pairs(cells))
                    table.rows.push_back({row, date});
                }
            }
        }
      if (table.header.empty())
        throw std::runtime_error(file + ": no table in a section \"## " +
                                 section + "\"");
      return table;
    }

    /// "BENCHMARKS.md's figure of 2026-12-04": how a printed ratio names
    /// the peer figure it is taken against.
    inline std::string
    peer_source(const std::string &file, const std::string &date)
    {
      const std::string name = file.substr(file.find_last_of('/') + 1);
      return name + "'s figure of " + date;
    }

    /// A peer code's run of P1 (gravity cantilever): a row of the P1 table.
    struct P1PeerRun
    {
      std::string  code;   ///< "DisMech", "DRMSimulationModel"
      std::string  method; ///< "dt 2" where the row names a time step
      unsigned int n             = 0;
      double       time          = NAN; ///< inside the process, s
      double       z_error       = NAN;
      double       x_error       = NAN; ///< NaN where the row gives none
      double       whole_process = NAN; ///< s, NaN where the row gives none
      std::string  date;
      std::string  source; ///< "BENCHMARKS.md's figure of 2026-12-04"

      /// The distance of the tip from the exact one, by which BENCHMARKS.md
      /// judges accuracy; where the row gives no x error, the z error alone
      /// (a lower bound, which can only make the peer look more accurate).
      double
      tip_error() const
      {
        return std::isnan(x_error) ? z_error : std::hypot(x_error, z_error);
      }

      /// "DisMech dt 2 at N = 200" (no comma: it goes into CSV files too).
      std::string
      name() const
      {
        return code + (method.empty() ? "" : " " + method) +
               " at N = " + std::to_string(n);
      }
    };

    /// The runs of the P1 table of @p file that give a size, a time and a
    /// tip error; a row without them (a superseded time quoted for
    /// comparison) is left out. The method is the time step "dt x" where
    /// the row or, for a row "same", the code's previous row names one.
    inline std::vector<P1PeerRun>
    read_p1_peers(const std::string &file)
    {
      const PeerTable   table  = read_peer_table(file, "P1");
      const std::size_t code   = table.column("code"),
                        method = table.column("method"), n = table.column("N"),
                        time  = table.column("time in process"),
                        error = table.column("tip error"),
                        whole = table.column("whole process");
      std::vector<P1PeerRun> runs;
      for (const PeerTableRow &row : table.rows)
        {
          P1PeerRun run;
          run.code          = internal::first_word(row.cells[code]);
          run.n             = internal::whole_number(row.cells[n]);
          run.time          = internal::leading_number(row.cells[time]);
          run.z_error       = internal::leading_number(row.cells[error]);
          run.x_error       = internal::x_part(row.cells[error]);
          run.whole_process = internal::leading_number(row.cells[whole]);
          std::smatch step;
          if (std::regex_search(row.cells[method],
                                step,
                                std::regex("dt [0-9.]+")))
            run.method = step.str();
          else if (!runs.empty() && runs.back().code == run.code)
            run.method = runs.back().method;
          run.date   = row.date;
          run.source = peer_source(file, row.date);
          if (run.n > 0 && !std::isnan(run.time) && !std::isnan(run.z_error))
            runs.push_back(run);
        }
      return runs;
    }

    /// The fastest of the runs of @p code among @p runs whose tip error is
    /// at most @p error (10% more allowed: BENCHMARKS.md quotes errors to two
    /// digits), nullptr if none is that accurate: a time of ours at that
    /// error is set beside this run's.
    inline const P1PeerRun *
    fastest_as_accurate(const std::vector<P1PeerRun> &runs,
                        const std::string            &code,
                        const double                  error)
    {
      const P1PeerRun *fastest = nullptr;
      for (const P1PeerRun &run : runs)
        if (run.code == code && run.tip_error() <= 1.1 * error &&
            (fastest == nullptr || run.time < fastest->time))
          fastest = &run;
      return fastest;
    }

    /// "DisMech dt 2 at N = 200 (tip error 3.8e-05): 0.0338 s, 14.5x, against
    /// BENCHMARKS.md's figure of 2026-12-04", the ratio @p peer's time over
    /// @p our_time.
    inline std::string
    ratio_text(const P1PeerRun &peer, const double our_time)
    {
      char text[200];
      std::snprintf(text,
                    sizeof(text),
                    "%s (tip error %.1e): %.3g s, %.1fx, against %s",
                    peer.name().c_str(),
                    peer.tip_error(),
                    peer.time,
                    peer.time / our_time,
                    peer.source.c_str());
      return text;
    }

    /// A peer code's K1 rates (hinges/s) at one N: a row of the K1 table.
    struct K1PeerFigure
    {
      std::string  code; ///< "fabsim"
      unsigned int n            = 0;
      double       hessian_rate = NAN, gradient_rate = NAN;
      std::string  date, source;
    };

    /// The K1 table of @p file, per code and N the newest row (a dated one
    /// before an undated one).
    inline std::vector<K1PeerFigure>
    read_k1_peers(const std::string &file)
    {
      const PeerTable   table = read_peer_table(file, "K1");
      const std::size_t code = table.column("code"), n = table.column("N"),
                        hessian  = table.column("E+g+H"),
                        gradient = table.column("gradient");
      std::vector<K1PeerFigure> figures;
      for (const PeerTableRow &row : table.rows)
        {
          const K1PeerFigure figure{
            internal::first_word(row.cells[code]),
            internal::whole_number(row.cells[n]),
            internal::leading_number(row.cells[hessian]),
            internal::leading_number(row.cells[gradient]),
            row.date,
            peer_source(file, row.date)};
          const auto older = [](const std::string &a, const std::string &b) {
            return a == "undated" ? b != "undated" : b != "undated" && a < b;
          };
          const auto same =
            std::find_if(figures.begin(),
                         figures.end(),
                         [&](const K1PeerFigure &f) {
                           return f.code == figure.code && f.n == figure.n;
                         });
          if (same == figures.end())
            figures.push_back(figure);
          else if (older(same->date, figure.date))
            *same = figure;
        }
      return figures;
    }
  } // namespace bench
} // namespace rodnet

#endif
