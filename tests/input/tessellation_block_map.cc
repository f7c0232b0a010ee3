// Block maps (io/block_map.h, doc/networks.md "Block maps"): the welded
// network of the blocks of a text map against counts by hand, the groups
// of the beams blocks of different kinds share, and the refusals, each
// naming the file and the line and column.
#include <common/group_counts.h>
#include <io/block_map.h>

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <string>

namespace
{
  using namespace rodnet;
  using rodnet::testing::count_in;

  /// Writes @p text to the file @p name; returns @p name.
  std::string
  map_file(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
    return name;
  }

  /// The groups of the beam from node @p from to node @p to.
  std::vector<std::string>
  groups_of(const RodGraph    &graph,
            const std::string &from,
            const std::string &to)
  {
    for (const RodGraph::Beam &beam : graph.beams)
      if (graph.nodes[beam.from].name == from &&
          graph.nodes[beam.to].name == to)
        return beam.groups;
    ADD_FAILURE() << "no beam " << from << " -> " << to;
    return {};
  }

  /// The message read_block_map() refuses the map @p text with.
  std::string
  refusal(const std::string &name, const std::string &text)
  {
    try
      {
        read_block_map(map_file(name, text));
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "accepted";
  }

  TEST(BlockMap, NetworkOfThreeBlocksAgainstCountsByHand)
  {
    // Top row "+-", bottom row " .": blocks (column, row from the bottom)
    // (0, 1) '+', (1, 1) '-', (1, 0) '.'. Corners: (1, 0), (2, 0),
    // (0..2, 1), (0..2, 2): 8 nodes, each the corner of a rectangle (two
    // beams or more: 8 junctions). Horizontal beams: one at j = 0, two at
    // j = 1, two at j = 2; struts: two in row 0, three in row 1.
    const RodGraph graph =
      block_map_network(read_block_map(map_file("three_blocks.map",
                                                "# a comment\n+-\n .\n")),
                        2.,
                        0.5);
    ASSERT_EQ(graph.nodes.size(), 8u);
    EXPECT_EQ(graph.beams.size(), 10u);
    EXPECT_EQ(count_in(graph, "horizontal"), 5u);
    EXPECT_EQ(count_in(graph, "vertical"), 5u);
    EXPECT_EQ(count_in(graph, "shrink-up"), 2u);
    EXPECT_EQ(count_in(graph, "shrink-down"), 2u);
    EXPECT_EQ(count_in(graph, "passive"), 1u);
    EXPECT_EQ(graph.nodes[0].name, "n_1_0");
    const Vector3 top_right = graph.nodes[graph.node_index("n_2_2")].position;
    EXPECT_EQ(top_right, Vector3(4., 1., 0.));
    // The beam between '.' (below) and '-' (above) is active: '-'; the one
    // below '.' passive; a '+' block's beams both '+'; beams run left to
    // right and bottom to top.
    using Groups = std::vector<std::string>;
    EXPECT_EQ(groups_of(graph, "n_1_1", "n_2_1"),
              (Groups{"horizontal", "shrink-down"}));
    EXPECT_EQ(groups_of(graph, "n_1_0", "n_2_0"),
              (Groups{"horizontal", "passive"}));
    EXPECT_EQ(groups_of(graph, "n_0_1", "n_1_1"),
              (Groups{"horizontal", "shrink-up"}));
    EXPECT_EQ(groups_of(graph, "n_0_2", "n_1_2"),
              (Groups{"horizontal", "shrink-up"}));
    EXPECT_EQ(groups_of(graph, "n_1_1", "n_1_2"), (Groups{"vertical"}));
    const BuiltNetwork built = build_rod_network(graph, 2, "simple");
    EXPECT_EQ(built.network->junctions().size(), 8u);
  }

  TEST(BlockMap, SharedBeamOfTwoActiveBlocksTakesTheLowerOnes)
  {
    // '+' above '-': the beam between them is '-'.
    const RodGraph graph =
      block_map_network(read_block_map(map_file("stack.map", "+\n-\n")),
                        1.,
                        1.);
    EXPECT_EQ(groups_of(graph, "n_0_1", "n_1_1"),
              (std::vector<std::string>{"horizontal", "shrink-down"}));
    EXPECT_EQ(count_in(graph, "shrink-up"), 1u);
    EXPECT_EQ(count_in(graph, "shrink-down"), 2u);
  }

  TEST(BlockMap, RaggedRowsAndCornersJoin)
  {
    // Rows may be short (missing blocks are none); blocks that share only
    // a corner are one network: 7 nodes, 8 beams, the shared corner n_1_1
    // a junction of four beam ends.
    const RodGraph graph =
      block_map_network(read_block_map(map_file("diagonal.map", "+\n -")),
                        1.,
                        1.);
    EXPECT_EQ(graph.nodes.size(), 7u);
    EXPECT_EQ(graph.beams.size(), 8u);
    const BuiltNetwork built = build_rod_network(graph, 2, "simple");
    EXPECT_EQ(built.network->junctions().size(), 7u);
    const int corner = built.node_junction[graph.node_index("n_1_1")];
    ASSERT_GE(corner, 0);
    EXPECT_EQ(built.network->junctions()[corner].ends.size(), 4u);
  }

  TEST(BlockMap, RefusalsNameFileLineAndColumn)
  {
    EXPECT_EQ(refusal("unknown.map", "# x\n+-\n+x\n"),
              "unknown.map:3:2: unknown block 'x'; a block map knows '+' "
              "(shrink-up), '-' (shrink-down), '.' (passive) and ' ' (no "
              "block)");
    EXPECT_NE(refusal("tab.map", "+\t+\n")
                .find("tab.map:1:2: unknown block "
                      "byte 0x09"),
              std::string::npos);
    EXPECT_EQ(refusal("empty.map", "# only a comment\n  \n"),
              "block map file \"empty.map\" has no block; a map needs at "
              "least one '+', '-' or '.'");
    EXPECT_EQ(refusal("pieces.map", "\n+\n\n..\n"),
              "pieces.map:4:1: this block is not joined to the block at line "
              "2, column 1 (blocks join where they share a corner); a network "
              "in pieces moves rigidly under one support");
    EXPECT_EQ(refusal("/nonexistent/x.map", "+"),
              "cannot open the block map file \"/nonexistent/x.map\"");
  }
} // namespace
