#ifndef RODNET_IO_BLOCK_MAP_H
#define RODNET_IO_BLOCK_MAP_H

#include <geometry/rod_graph.h>
#include <io/generator_registry.h>

#include <string>
#include <vector>

namespace rodnet
{
  /// What a character of a block map places (doc/networks.md, "Block
  /// maps").
  enum class BlockKind
  {
    none,        ///< ' ': no block
    shrink_up,   ///< '+': horizontal beams in group "shrink-up"
    shrink_down, ///< '-': horizontal beams in group "shrink-down"
    passive      ///< '.': horizontal beams in group "passive"
  };

  /// The blocks of a block map file, row 0 the bottom row (the file's last
  /// line), all rows of one length (short rows padded with no block).
  struct BlockMap
  {
    std::vector<std::vector<BlockKind>> rows;
  };

  /**
   * Reads a block map: one character per block (BlockKind), the file's
   * first line the top row; lines that begin with '#' are comments; rows
   * may be of different lengths (a missing block is no block). Throws
   * std::invalid_argument naming the file, and for a bad character its
   * line and column: an unreadable file, a character other than '+', '-',
   * '.' and ' ', a map without a block, blocks in pieces (two blocks are
   * joined where they share a corner: a network in pieces has rigid
   * motions no single support holds).
   */
  BlockMap
  read_block_map(const std::string &path);

  /**
   * The welded network of the blocks of @p map, each block a rectangle of
   * @p width (its horizontal beams, from left to right) by @p height (its
   * vertical struts, from bottom to top), at (c width, r height) for
   * column c and row r; neighbouring blocks share their beams and struts.
   * Nodes n_i_j at the corners (i width, j height, 0), ordered by j, then
   * i; beams: the horizontal ones by j, then i, then the vertical ones.
   * Groups: "horizontal" and the kind of the blocks beside the beam,
   * "shrink-up", "shrink-down" or "passive": the block below the beam's if
   * it is active ('+' or '-'), else the block above's (an active block's
   * beams are all active; between a '+' and a '-' block the lower one
   * decides); "vertical" for the struts.
   */
  RodGraph
  block_map_network(const BlockMap &map, double width, double height);

  /// "Generator = block map": block_map_network() of "Block map file" with
  /// "Block size".
  class BlockMapGenerator : public GeometryGenerator
  {
  public:
    void
    declare_parameters(dealii::ParameterHandler &prm) const override;

    std::vector<UnreadEntry>
    unread_shared_entries() const override;

    GeneratedGeometry
    generate(const dealii::ParameterHandler &prm,
             const GeneratorInput           &input) const override;
  };
} // namespace rodnet

#endif
