// In a scene of several rods (a network) "start", "end", "mid" and vertex
// indices without a rod are ambiguous (they meant rod 0: "Point forces =
// mid: ..." on a dome loaded an edge beam): every entry that names vertices
// refuses them with one line naming the entry and how to write the place
// with its rod. An unknown "@name" lists the names there are, or the
// nearest ones. A scene of one rod reads them as before.
#include <deal.II/base/utilities.h>

#include <common/run_driver.h>
#include <common/scene_text.h>
#include <core/vertex_selector.h>

#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <variant>

namespace
{
  using namespace rodnet::testing;

  /// The frame of Lestringant & Kochmann (two rods, nodes "clamp",
  /// "corner", "tip"; the clamp is held) with the supports, loads and
  /// probes @p entries.
  std::string
  frame_with(const std::string &entries)
  {
    return "subsection Geometry\n  set Generator = frame\n"
           "  set Segments = 8\nend\n" +
           direct_material(1e4, 1, 1, 1) + entries;
  }

  std::string
  in_section(const std::string &section, const std::string &entry)
  {
    return "subsection " + section + "\n  set " + entry + "\nend\n";
  }

  struct AmbiguousName
  {
    std::string name, section, entry, where;
  };

  TEST(NetworkVertexNames, BareNamesAreRefusedInANetwork)
  {
    const std::vector<AmbiguousName> cases = {
      {"force_mid", "Loads", "Point forces = mid: 0, 0, -1", "mid"},
      {"moment_mid", "Loads", "Moments = mid: 0,0,1 0.1", "mid"},
      {"pinned_end", "Supports", "Pinned vertices = end", "end"},
      {"clamped_end", "Supports", "Clamped ends = end", "end"},
      {"fixed_index", "Supports", "Fixed components = 3: z", "3"},
      {"displaced_end",
       "Supports",
       "Prescribed displacements = end: z=0.01",
       "end"},
      {"rotated_end", "Supports", "Prescribed rotations = end: 1,0,0 1", "end"},
      {"probe_start", "Output", "Probes = z: position start z", "start"}};
    for (const AmbiguousName &c : cases)
      {
        const std::string entry =
          c.section + "/" + c.entry.substr(0, c.entry.find(" = "));
        expect_input_error_naming(
          "bare_" + c.name,
          frame_with(in_section(c.section, c.entry)),
          {"entry \"" + entry + "\": \"" + c.where +
           "\" names no rod, and the scene has 2 rods; write \"<rod>:" +
           c.where + "\" (\"0:" + c.where + "\" for rod 0) or \"@<name>\""});
      }
  }

  TEST(NetworkVertexNames, NamesWithTheirRodAreRead)
  {
    // The tip pulled up, read back by rod and by name.
    const DriverOutcome o =
      run_driver("rod_names",
                 frame_with(
                   "subsection Loads\n  set Steps = 1\n"
                   "  set Point forces = 1:end: 0, 0, 1e-4\nend\n" +
                   probes_only("a: position 1:end z; b: position @tip z; "
                               "c: position 1:-1 z; d: position 0:mid z")));
    EXPECT_EQ(o.exit_code, 0) << o.output;
    const std::string  csv = read_file("out_rod_names/probes.csv");
    std::istringstream lines(csv);
    std::string        line;
    std::getline(lines, line);
    EXPECT_EQ(line, "step,load_factor,a,b,c,d,stable,in_range");
    std::getline(lines, line);
    std::getline(lines, line);
    // Step 1: a = b = c, the tip moved up.
    const auto values = dealii::Utilities::string_to_double(
      dealii::Utilities::split_string_list(line, ','));
    EXPECT_GT(values[2], 1e-6);
    EXPECT_EQ(values[2], values[3]);
    EXPECT_EQ(values[2], values[4]);
  }

  TEST(NetworkVertexNames, UnknownNameListsTheNames)
  {
    expect_input_error(
      "unknown_frame_name",
      frame_with(in_section("Loads", "Point forces = @tipp: 0, 0, 1")),
      "entry \"Loads/Point forces\": there is no vertex or junction called "
      "\"tipp\"; the names are \"clamp\", \"corner\", \"tip\"");
    // A junction by name, mistyped: the windmill's junctions.
    expect_input_error(
      "unknown_windmill_junction",
      "subsection Geometry\n  set Generator = windmill\n"
      "  set Segments = 4\nend\n" +
        direct_material(1e4, 1, 1, 1) +
        in_section("Supports", "Prescribed rotations = topp: 0,0,1 1"),
      "entry \"Supports/Prescribed rotations\": there is no junction called "
      "\"topp\"; the names are \"hub\", \"top\"");
    // 16 nodes: the nearest eight, those of column 3 first.
    expect_input_error(
      "unknown_lattice_name",
      "subsection Geometry\n  set Generator = square lattice\n"
      "  set Cells = 3, 3\n  set Segments = 2\nend\n" +
        direct_material(1e4, 1, 1, 1) +
        in_section("Supports", "Pinned vertices = @n_0_0, @n_3_9"),
      "entry \"Supports/Pinned vertices\": there is no vertex or junction "
      "called \"n_3_9\"; the nearest of its 16 names are \"n_3_0\", "
      "\"n_3_1\", \"n_3_2\", \"n_3_3\", \"n_0_0\"");
  }

  TEST(NetworkVertexNames, OneRodReadsBareNamesAsBefore)
  {
    dealii::ParameterHandler prm;
    rodnet::Scene::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n  set Segments = 9\n"
                                "end\n" +
                                direct_material(1e4, 1, 1, 1));
    const auto                       model   = rodnet::Scene(prm).build_model();
    const rodnet::RodNetwork        &network = model->network();
    const std::vector<unsigned int> &v       = network.rods()[0].vertices;
    EXPECT_EQ(rodnet::select_vertex(network, "start", "e"), v.front());
    EXPECT_EQ(rodnet::select_vertex(network, "end", "e"), v.back());
    EXPECT_EQ(rodnet::select_vertex(network, "mid", "e"), v[5]);
    EXPECT_EQ(rodnet::select_vertex(network, "-2", "e"), v[8]);
    EXPECT_EQ(rodnet::select_vertex(network, "0:3", "e"), v[3]);
    const auto end = rodnet::select_rod_end(network, "end", "e");
    ASSERT_TRUE(std::holds_alternative<rodnet::RodEnd>(end));
    EXPECT_FALSE(std::get<rodnet::RodEnd>(end).at_start);
  }
} // namespace
