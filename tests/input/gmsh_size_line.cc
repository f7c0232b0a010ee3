// The size line of a Gmsh network counts what is built (issue 33, item 8:
// "20 segments, 87 DoFs" was printed for a model of 15 DoFs), and a beam
// that is a chain of two line elements gets one warning that its one hinge
// gives a first-order answer: the L below is 20% off Castigliano's
// deflection with that hinge, within 1% once its corner is a junction.
#include <common/run_driver.h>
#include <common/scene_text.h>
#include <io/gmsh_network.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;

  /// An L of two line elements of one physical group, (0, 0, 0) - (1, 0,
  /// 0) - (1, 1, 0), clamped at node 1; with @p welded_corner node 2 is a
  /// physical point "corner", a welded junction.
  std::string
  l_mesh(const bool welded_corner)
  {
    return std::string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n") +
           "$PhysicalNames\n2\n0 1 \"clamped\"\n0 2 \"corner\"\n"
           "$EndPhysicalNames\n"
           "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 1 1 0\n$EndNodes\n"
           "$Elements\n" +
           (welded_corner ? "4\n4 15 2 2 2 2\n" : "3\n") +
           "1 15 2 1 1 1\n2 1 2 4 1 1 2\n3 1 2 4 1 2 3\n$EndElements\n";
  }

  /// The L of l_mesh(@p welded_corner) as a scene, Segments = 20, a force
  /// P = 1e-3 along -z at its tip; EI1 = EI2 = GJ = 1.
  std::string
  l_scene(const bool welded_corner)
  {
    const std::string mesh =
      welded_corner ? "l_welded_corner.msh" : "l_two_elements.msh";
    std::ofstream(mesh) << l_mesh(welded_corner);
    return "subsection Geometry\n  set Generator = gmsh network\n"
           "  set Mesh file = " +
           mesh + "\n  set Segments = 20\nend\n" +
           rodnet::testing::direct_material(1e4, 1, 1, 1) +
           "subsection Loads\n  set Steps = 1\n"
           "  set Point forces = @node3: 0, 0, -1e-3\nend\n"
           "subsection Output\n  set Probes = tip_z: position @node3 z\n"
           "  set Write VTU = false\n  set Plot = false\nend\n";
  }

  /// Castigliano: both legs bent (P a^3 / 3 EI each), the first twisted
  /// by P a (P a^3 / GJ): 5 P / 3 with a = EI = GJ = 1.
  constexpr double exact_deflection = -5e-3 / 3;

  /// The tip's deflection of the L of l_scene(@p welded_corner), run
  /// through the library.
  double
  tip_deflection(const bool welded_corner)
  {
    const RunSummary run =
      rodnet::testing::run_scene_text(l_scene(welded_corner),
                                      welded_corner ? "out_l_welded_lib" :
                                                      "out_l_two_lib");
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    return run.rows.back().at(1);
  }

  std::size_t
  occurrences(const std::string &text, const std::string &part)
  {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos;
         at      = text.find(part, at + 1))
      ++n;
    return n;
  }

  TEST(GmshSizeLine, CornerChainOfTwoElements)
  {
    const rodnet::testing::DriverOutcome o =
      rodnet::testing::run_driver("l_two_elements", l_scene(false));
    ASSERT_EQ(o.exit_code, 0) << o.output;
    // The estimate before the build, and the model built.
    EXPECT_NE(o.output.find("rodnet: 1 rod(s), 2 segments, 15 DoFs, memory"),
              std::string::npos)
      << o.output;
    EXPECT_NE(o.output.find("rodnet: 1 rod(s), 15 DoFs, 1 hinges"),
              std::string::npos)
      << o.output;
    EXPECT_EQ(occurrences(o.output, "warning: "), 1u) << o.output;
    EXPECT_NE(o.output.find(
                "warning: mesh \"./l_two_elements.msh\": beam 0 (node1 to "
                "node3, its hinge at node 2) is a chain of two line "
                "elements, whose one hinge gives a first-order answer; the "
                "mesh decides its segments: refine the mesh, or mark the "
                "hinge's node with a physical point"),
              std::string::npos)
      << o.output;
    // What the warning says: the one hinge is 20% off.
    EXPECT_GT(std::abs(tip_deflection(false) / exact_deflection - 1), 0.1);
  }

  TEST(GmshSizeLine, WeldedCornerHasNoWarningAndConverges)
  {
    // The advice of the warning: the corner a junction, each leg one
    // element split into Segments = 20.
    const rodnet::testing::DriverOutcome o =
      rodnet::testing::run_driver("l_welded_corner", l_scene(true));
    ASSERT_EQ(o.exit_code, 0) << o.output;
    EXPECT_EQ(o.output.find("warning"), std::string::npos) << o.output;
    // 2 rods of 20 segments, 42 vertices, the clamp and the corner: 3 * 42
    // + 40 + 2 * 4 = 174 DoFs.
    EXPECT_NE(o.output.find("rodnet: 2 rod(s), 40 segments, 174 DoFs"),
              std::string::npos)
      << o.output;
    EXPECT_NE(o.output.find("rodnet: 2 rod(s), 174 DoFs"), std::string::npos)
      << o.output;
    EXPECT_LT(std::abs(tip_deflection(true) / exact_deflection - 1), 0.01);
  }
  TEST(GmshSizeLine, OneWarningForSeveralChains)
  {
    // A star of three chains of two elements from hub node 1 (as in
    // input/network_inputs): one warning names the three beams.
    std::ofstream("star_of_chains.msh")
      << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n7\n"
         "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
         "5 0.5 0 0\n6 0 0.5 0\n7 0 0 0.5\n$EndNodes\n$Elements\n6\n"
         "1 1 2 1 1 1 5\n2 1 2 1 1 5 2\n3 1 2 1 1 3 6\n4 1 2 1 1 6 1\n"
         "5 1 2 1 1 7 1\n6 1 2 1 1 7 4\n$EndElements\n";
    ReadNotes notes;
    read_gmsh_network("star_of_chains.msh", &notes);
    EXPECT_TRUE(notes.info.empty());
    ASSERT_EQ(notes.warnings.size(), 1u);
    EXPECT_EQ(notes.warnings[0].rfind(
                "mesh \"star_of_chains.msh\": 3 rods are chains of two line "
                "elements, whose one hinge gives a first-order answer: beam 0 "
                "(node1 to node2, its hinge at node 5), beam 1 (node3 to "
                "node1, its hinge at node 6), beam 2 (node4 to node1, its "
                "hinge at node 7); the mesh decides their segments: ",
                0),
              0u)
      << notes.warnings[0];
  }
} // namespace
