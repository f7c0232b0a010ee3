#include <io/csv_table.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    /// Fields of one CSV line (RFC 4180 quoting, without line breaks in
    /// a field).
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

    /// @p line without a trailing carriage return (a file written on
    /// Windows).
    std::string
    without_carriage_return(std::string line)
    {
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      return line;
    }
  } // namespace

  std::optional<std::size_t>
  CsvTable::column(const std::string &name, const std::size_t from) const
  {
    for (std::size_t c = from; c < names.size(); ++c)
      if (names[c] == name)
        return c;
    return std::nullopt;
  }

  double
  CsvTable::number(const std::size_t r, const std::size_t c) const
  {
    const std::string field = text(r, c);
    try
      {
        std::size_t  used  = 0;
        const double value = std::stod(field, &used);
        return used == field.size() ? value : std::nan("");
      }
    catch (const std::exception &)
      {
        return std::nan("");
      }
  }

  std::string
  CsvTable::text(const std::size_t r, const std::size_t c) const
  {
    return c < rows[r].size() ? rows[r][c] : std::string();
  }

  CsvTable
  read_csv_table(const std::string &path)
  {
    std::ifstream file(path);
    std::string   line;
    if (!file || !std::getline(file, line))
      throw std::runtime_error("cannot read \"" + path + "\"");
    CsvTable table;
    table.names = split_csv_line(without_carriage_return(line));
    while (std::getline(file, line))
      {
        line = without_carriage_return(line);
        if (line.find_first_not_of(" \t") != std::string::npos)
          table.rows.push_back(split_csv_line(line));
      }
    return table;
  }
} // namespace rodnet
