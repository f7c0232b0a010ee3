#ifndef RODNET_IO_CSV_TABLE_H
#define RODNET_IO_CSV_TABLE_H

#include <optional>
#include <string>
#include <vector>

namespace rodnet
{
  /**
   * A CSV file read whole, as the tables rodnet writes (probes.csv,
   * summary.csv): the header's column names and the fields of every row,
   * a field double-quoted where it holds a comma ("" for a quote, RFC
   * 4180). Blank lines are left out.
   */
  struct CsvTable
  {
    std::vector<std::string>              names;
    std::vector<std::vector<std::string>> rows;

    /// The first column called @p name at or after @p from, if any.
    std::optional<std::size_t>
    column(const std::string &name, std::size_t from = 0) const;

    /// Field @p c of row @p r as a number; NaN where it is missing, empty
    /// or not a number ("nan", text).
    double
    number(std::size_t r, std::size_t c) const;

    /// Field @p c of row @p r; empty where the row is shorter.
    std::string
    text(std::size_t r, std::size_t c) const;
  };

  /// Reads the CSV file @p path; throws std::runtime_error naming it if it
  /// cannot be read or has no header.
  CsvTable
  read_csv_table(const std::string &path);
} // namespace rodnet

#endif
