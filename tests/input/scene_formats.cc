// The same rod read three ways gives the same result: built by the
// straight generator, read from a Gmsh line mesh, and from a .json scene;
// and the same supports named two ways: by a node's name and by the
// network's own declaration or the rod end.
#include <deal.II/base/parameter_handler.h>

#include <common/run_scene_text.h>
#include <common/scene_text.h>

#include <fstream>
#include <gtest/gtest.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  std::string
  cantilever(const std::string &geometry)
  {
    return "subsection Geometry\n" + geometry +
           "  set Director d1 = 0, 0, 1\n"
           "end\n"
           "subsection Material\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = direct\n"
           "    set EA = 1e4\n"
           "    set EI1 = 1\n"
           "    set EI2 = 2\n"
           "    set GJ = 1\n"
           "  end\n"
           "end\n"
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Loads\n"
           "  set Steps = 2\n"
           "  set Point forces = end: 0, 1, 2\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "  set Probes = x: position end x; y: position end y; "
           "z: position end z; mid_y: position mid y\n"
           "end\n";
  }

  void
  expect_same_rows(const RunSummary &a, const RunSummary &b)
  {
    ASSERT_TRUE(a.failure.empty()) << a.failure;
    ASSERT_TRUE(b.failure.empty()) << b.failure;
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t r = 0; r < a.rows.size(); ++r)
      for (std::size_t c = 0; c < a.rows[r].size(); ++c)
        EXPECT_NEAR(a.rows[r][c], b.rows[r][c], 1e-10);
  }

  const std::string straight_geometry = "  set Generator = straight\n"
                                        "  set Segments = 10\n";

  TEST(SceneFormats, GmshMeshMatchesGenerator)
  {
    const RunSummary generated =
      run_scene_text(cantilever(straight_geometry), "formats_generated");
    // The mesh lists its nodes and segments out of order on purpose.
    const RunSummary meshed =
      run_scene_text(cantilever("  set Generator = gmsh\n"
                                "  set Mesh file = " RODNET_SOURCE_DIR
                                "/tests/input/data/straight_rod.msh\n"),
                     "formats_gmsh");
    expect_same_rows(generated, meshed);
    // The load bends the rod visibly: the comparison is not trivial.
    EXPECT_GT(generated.rows.back()[2], 0.1);
  }

  TEST(SceneFormats, JsonSceneMatchesPrm)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(cantilever(straight_geometry));
    {
      std::ofstream json("formats.json");
      prm.print_parameters(json, dealii::ParameterHandler::OutputStyle::JSON);
    }
    dealii::ParameterHandler from_json;
    Scene::declare_parameters(from_json);
    from_json.parse_input("formats.json");
    const RunSummary a = run_scene(Scene(prm), "formats_prm", nullptr);
    const RunSummary b = run_scene(Scene(from_json), "formats_json", nullptr);
    expect_same_rows(a, b);
  }

  /// A scene with @p geometry (Geometry entries), @p supports (Supports
  /// entries), a force down at @p loaded and probes of its position and of
  /// the reaction and clamp moment at @p clamped.
  std::string
  supported(const std::string &geometry,
            const std::string &supports,
            const std::string &loaded,
            const std::string &clamped)
  {
    return "subsection Geometry\n" + geometry + "end\n" +
           direct_material(1e4, 1, 1, 1) + "subsection Supports\n" + supports +
           "end\n"
           "subsection Loads\n"
           "  set Steps = 2\n"
           "  set Point forces = " +
           loaded + ": 0, 0, -0.05\nend\n" +
           probes_only("z: position " + loaded + " z; force: reaction " +
                       clamped + " z; moment: moment " + clamped + " y");
  }

  // Lattice node names work in every entry: a square cell clamped at
  // "@n_0_0" (a junction, held whole) and pinned at "@n_1_0" behaves as the
  // same cell read from a node list that declares those nodes clamped and
  // welded-and-pinned.
  TEST(SceneFormats, LatticeNodeNamesMatchDeclaredSupports)
  {
    const std::string cell = "  set Generator = square lattice\n"
                             "  set Cells = 1, 1\n"
                             "  set Segments = 6\n";
    const RunSummary  named =
      run_scene_text(supported(cell,
                               "  set Clamped ends = @n_0_0\n"
                               "  set Pinned vertices = @n_1_0\n",
                               "@n_1_1",
                               "@n_0_0"),
                     "formats_lattice_named");
    std::ofstream("lattice_cell.net") << "node n_0_0 0 0 0 clamped\n"
                                         "node n_1_0 1 0 0 welded-and-pinned\n"
                                         "node n_0_1 0 1 0\n"
                                         "node n_1_1 1 1 0\n"
                                         "beam n_0_0 n_1_0\n"
                                         "beam n_0_1 n_1_1\n"
                                         "beam n_0_0 n_0_1\n"
                                         "beam n_1_0 n_1_1\n";
    const RunSummary declared =
      run_scene_text(supported("  set Generator = network file\n"
                               "  set Network file = lattice_cell.net\n"
                               "  set Segments = 6\n",
                               "",
                               "@n_1_1",
                               "@n_0_0"),
                     "formats_lattice_declared");
    expect_same_rows(named, declared);
    EXPECT_LT(named.rows.back()[1], -0.01);
  }

  // A free end of a network, "@tip" of the frame, is a rod end: clamped as
  // "@tip" it is the clamp of "1:end".
  TEST(SceneFormats, FreeEndNameIsTheRodEnd)
  {
    const std::string frame   = "  set Generator = frame\n"
                                "  set Segments = 8\n";
    const RunSummary  by_name = run_scene_text(
      supported(frame, "  set Clamped ends = @tip\n", "@corner", "@tip"),
      "formats_frame_named");
    const RunSummary by_end = run_scene_text(
      supported(frame, "  set Clamped ends = 1:end\n", "@corner", "1:end"),
      "formats_frame_end");
    expect_same_rows(by_name, by_end);
    EXPECT_LT(by_name.rows.back()[1], -0.001);
  }
} // namespace
