#include <deal.II/base/utilities.h>

#include <io/block_map.h>
#include <io/scene_entries.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <utility>

namespace rodnet
{
  namespace
  {
    /// A row of a block map as read, with its line for messages.
    struct MapRow
    {
      std::vector<BlockKind> blocks;
      unsigned int           line;
    };

    /// The character @p c for a message: 'x', or its code where it does
    /// not print (a tab, a byte of a multibyte character).
    std::string
    describe(const char c)
    {
      const auto byte = static_cast<unsigned char>(c);
      if (byte > 32 && byte < 127)
        return std::string("'") + c + "'";
      char code[16];
      std::snprintf(code, sizeof code, "byte 0x%02x", byte);
      return code;
    }

    BlockKind
    parse_block(const char         c,
                const std::string &where,
                const std::size_t  column)
    {
      switch (c)
        {
          case ' ':
            return BlockKind::none;
          case '+':
            return BlockKind::shrink_up;
          case '-':
            return BlockKind::shrink_down;
          case '.':
            return BlockKind::passive;
          default:
            throw std::invalid_argument(
              where + ":" + std::to_string(column + 1) + ": unknown block " +
              describe(c) +
              "; a block map knows '+' (shrink-up), '-' (shrink-down), '.' "
              "(passive) and ' ' (no block)");
        }
    }

    bool
    has_block(const MapRow &row)
    {
      for (const BlockKind b : row.blocks)
        if (b != BlockKind::none)
          return true;
      return false;
    }

    /// The rows of the file from its first to its last row with a block,
    /// top first.
    std::vector<MapRow>
    read_rows(const std::string &path)
    {
      std::ifstream in(path);
      if (!in)
        throw std::invalid_argument("cannot open the block map file \"" + path +
                                    "\"");
      std::vector<MapRow> rows;
      std::string         line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          if (!line.empty() && line[0] == '#')
            continue;
          MapRow row{{}, number};
          for (std::size_t c = 0; c < line.size(); ++c)
            row.blocks.push_back(
              parse_block(line[c], path + ":" + std::to_string(number), c));
          if (has_block(row) || !rows.empty())
            rows.push_back(row);
        }
      while (!rows.empty() && !has_block(rows.back()))
        rows.pop_back();
      if (rows.empty())
        throw std::invalid_argument(
          "block map file \"" + path +
          "\" has no block; a map needs at least one '+', '-' or '.'");
      return rows;
    }

    /// Refuses blocks in pieces, naming a block that is not joined to the
    /// first one (through blocks that share a corner).
    void
    require_one_piece(const std::vector<MapRow> &rows, const std::string &path)
    {
      const auto exists = [&](const long r, const long c) {
        return r >= 0 && r < long(rows.size()) &&
               c < long(rows[r].blocks.size()) && c >= 0 &&
               rows[r].blocks[c] != BlockKind::none;
      };
      std::map<std::pair<long, long>, bool> reached;
      std::vector<std::pair<long, long>>    todo;
      for (long r = 0; r < long(rows.size()) && todo.empty(); ++r)
        for (long c = 0; c < long(rows[r].blocks.size()) && todo.empty(); ++c)
          if (exists(r, c))
            todo.emplace_back(r, c);
      const auto first = todo[0];
      while (!todo.empty())
        {
          const auto [r, c] = todo.back();
          todo.pop_back();
          if (!exists(r, c) || reached[{r, c}])
            continue;
          reached[{r, c}] = true;
          for (long dr = -1; dr <= 1; ++dr)
            for (long dc = -1; dc <= 1; ++dc)
              todo.emplace_back(r + dr, c + dc);
        }
      for (long r = 0; r < long(rows.size()); ++r)
        for (long c = 0; c < long(rows[r].blocks.size()); ++c)
          if (exists(r, c) && !reached[{r, c}])
            throw std::invalid_argument(
              path + ":" + std::to_string(rows[r].line) + ":" +
              std::to_string(c + 1) +
              ": this block is not joined to the block at line " +
              std::to_string(rows[first.first].line) + ", column " +
              std::to_string(first.second + 1) +
              " (blocks join where they share a corner); a network in "
              "pieces moves rigidly under one support");
    }

    const char *
    group_of(const BlockKind kind)
    {
      return kind == BlockKind::shrink_up   ? "shrink-up" :
             kind == BlockKind::shrink_down ? "shrink-down" :
                                              "passive";
    }

    bool
    active(const BlockKind kind)
    {
      return kind == BlockKind::shrink_up || kind == BlockKind::shrink_down;
    }
  } // namespace

  BlockMap
  read_block_map(const std::string &path)
  {
    const std::vector<MapRow> rows = read_rows(path);
    require_one_piece(rows, path);
    std::size_t columns = 0;
    for (const MapRow &row : rows)
      columns = std::max(columns, row.blocks.size());
    BlockMap map;
    for (auto row = rows.rbegin(); row != rows.rend(); ++row)
      {
        map.rows.push_back(row->blocks);
        map.rows.back().resize(columns, BlockKind::none);
      }
    return map;
  }

  RodGraph
  block_map_network(const BlockMap &map,
                    const double    width,
                    const double    height)
  {
    const long n_rows    = map.rows.size();
    const long n_columns = n_rows == 0 ? 0 : map.rows[0].size();
    const auto block     = [&](const long c, const long r) {
      return r < 0 || r >= n_rows || c < 0 || c >= n_columns ? BlockKind::none :
                                                                   map.rows[r][c];
    };
    const auto any_block = [&](const long c, const long r) {
      return block(c - 1, r - 1) != BlockKind::none ||
             block(c, r - 1) != BlockKind::none ||
             block(c - 1, r) != BlockKind::none ||
             block(c, r) != BlockKind::none;
    };
    RodGraph                                      graph;
    std::map<std::pair<long, long>, unsigned int> node;
    for (long j = 0; j <= n_rows; ++j)
      for (long i = 0; i <= n_columns; ++i)
        if (any_block(i, j))
          {
            node[{i, j}] = graph.nodes.size();
            graph.nodes.push_back(
              {"n_" + std::to_string(i) + "_" + std::to_string(j),
               Vector3(i * width, j * height, 0),
               std::nullopt});
          }
    const auto add_beam = [&](const std::pair<long, long> &from,
                              const std::pair<long, long> &to,
                              std::vector<std::string>     groups) {
      RodGraph::Beam beam;
      beam.from   = node.at(from);
      beam.to     = node.at(to);
      beam.groups = std::move(groups);
      graph.beams.push_back(beam);
    };
    for (long j = 0; j <= n_rows; ++j)
      for (long i = 0; i < n_columns; ++i)
        {
          const BlockKind below = block(i, j - 1), above = block(i, j);
          const BlockKind kind =
            active(below) || above == BlockKind::none ? below : above;
          if (kind != BlockKind::none)
            add_beam({i, j}, {i + 1, j}, {"horizontal", group_of(kind)});
        }
    for (long j = 0; j < n_rows; ++j)
      for (long i = 0; i <= n_columns; ++i)
        if (block(i - 1, j) != BlockKind::none ||
            block(i, j) != BlockKind::none)
          add_beam({i, j}, {i, j + 1}, {"vertical"});
    return graph;
  }

  void
  BlockMapGenerator::declare_parameters(dealii::ParameterHandler &prm) const
  {
    prm.declare_entry("Block map file",
                      "",
                      dealii::Patterns::Anything(),
                      "Block map: path of the map ('+', '-', '.', ' ' per "
                      "block), relative to the scene file. [-]");
    prm.declare_entry(
      "Block size",
      "1, 1",
      dealii::Patterns::List(dealii::Patterns::Double(0), 2, 2, ","),
      "Block map: width and height of a block. [m]");
  }

  std::vector<UnreadEntry>
  BlockMapGenerator::unread_shared_entries() const
  {
    return {{"Director d1",
             "a network orients each beam itself: a block map's beams take "
             "d1 = e_z unless their group gives another (\"Group "
             "horizontal/Director d1\"; doc/networks.md)"}};
  }

  GeneratedGeometry
  BlockMapGenerator::generate(const dealii::ParameterHandler &prm,
                              const GeneratorInput           &input) const
  {
    const std::vector<double> size = dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(prm.get("Block size"), ','));
    if (!(size[0] > 0 && size[1] > 0))
      throw std::invalid_argument(
        "entry \"Geometry/Block size\": a block's width and height must be "
        "positive, got \"" +
        prm.get("Block size") + "\"");
    GeneratedGeometry geometry;
    geometry.graph = block_map_network(
      read_block_map(
        scene_entries::get_file(prm, "Block map file", input.scene_directory)),
      size[0],
      size[1]);
    return geometry;
  }
} // namespace rodnet
