// The same rod read three ways gives the same result: built by the
// straight generator, read from a Gmsh line mesh, and from a .json scene.
#include <deal.II/base/parameter_handler.h>

#include <common/run_scene_text.h>

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
} // namespace
