// Coincident nodes (issue 33, item 2): a Gmsh network whose joint is
// written as two node tags at one point is merged into one node, with a
// line naming the merged tags, and gives the answer of the mesh written
// with the node once; nodes a little farther apart, a line element between
// coincident nodes and coincident nodes of a .net file are refused, naming
// them.
#include <common/scene_text.h>
#include <io/gmsh_network.h>
#include <io/gmsh_rods.h>
#include <io/network_file.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  /// Node tag of the apex of dome_mesh(), and of its second copy.
  constexpr long apex_tag = 13, apex_copy_tag = 1000;

  /**
   * A 4 x 4 dome (.msh 2.2): the grid lines of the paraboloid
   * z = 1 - (x^2 + y^2) / 8 over x, y in [-2, 2], every grid edge four
   * line elements of physical line 1, the nodes of the rim clamped
   * (physical point "clamped"), the apex named "apex" (node 13). With
   * @p copy_apex the elements of the grid line along y that end at the
   * apex use node 1000, written at the apex moved by @p offset along x:
   * the apex written twice, as a mesh saved without Gmsh's "Coherence
   * Mesh" has it.
   */
  std::string
  dome_mesh(const bool copy_apex, const double offset = 0)
  {
    constexpr int           n = 4, elements_per_edge = 4;
    std::map<long, Vector3> nodes;
    std::vector<long>       ends; // pairs of element ends
    std::vector<long>       rim;
    const auto              grid = [](int i, int j) { return 1L + 5 * i + j; };
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        {
          const double x = i - n / 2, y = j - n / 2;
          nodes[grid(i, j)] = Vector3(x, y, 1 - (x * x + y * y) / 8);
          if (i == 0 || i == n || j == 0 || j == n)
            rim.push_back(grid(i, j));
        }
    if (copy_apex)
      nodes[apex_copy_tag] = nodes[apex_tag] + Vector3(offset, 0, 0);
    long next_tag = 100;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (const auto &[di, dj] : {std::pair(1, 0), std::pair(0, 1)})
          {
            if (i + di > n || j + dj > n)
              continue;
            const long a = grid(i, j), b = grid(i + di, j + dj);
            // The copy of the apex ends the edges along y.
            const auto tag = [&](const long node) {
              return copy_apex && dj == 1 && node == apex_tag ? apex_copy_tag :
                                                                node;
            };
            std::vector<long> chain{tag(a)};
            for (int k = 1; k < elements_per_edge; ++k)
              {
                nodes[next_tag] =
                  nodes[a] + (nodes[b] - nodes[a]) * k / elements_per_edge;
                chain.push_back(next_tag++);
              }
            chain.push_back(tag(b));
            for (std::size_t k = 0; k + 1 < chain.size(); ++k)
              ends.insert(ends.end(), {chain[k], chain[k + 1]});
          }

    std::ostringstream text;
    text.precision(17);
    text << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
         << "$PhysicalNames\n2\n0 1 \"clamped\"\n0 2 \"apex\"\n"
         << "$EndPhysicalNames\n$Nodes\n"
         << nodes.size() << "\n";
    for (const auto &[tag, x] : nodes)
      text << tag << " " << x[0] << " " << x[1] << " " << x[2] << "\n";
    text << "$EndNodes\n$Elements\n"
         << ends.size() / 2 + rim.size() + 1 << "\n";
    long element = 1;
    for (std::size_t k = 0; k < ends.size(); k += 2)
      text << element++ << " 1 2 1 1 " << ends[k] << " " << ends[k + 1] << "\n";
    for (const long node : rim)
      text << element++ << " 15 2 1 1 " << node << "\n";
    text << element << " 15 2 2 2 " << apex_tag << "\n$EndElements\n";
    return text.str();
  }

  /// Writes @p text to the file @p name; returns @p name.
  std::string
  written(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
    return name;
  }

  /// What a run of the dome of @p mesh_file under a point force at its
  /// apex printed, and the apex's deflection.
  struct DomeRun
  {
    std::string log;
    double      deflection;
  };

  DomeRun
  run_dome(const std::string &mesh_file)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Geometry\n"
      "  set Generator = gmsh network\n"
      "  set Mesh file = " +
      mesh_file + "\nend\n" + rodnet::testing::direct_material(1e4, 1, 1, 1) +
      "subsection Loads\n  set Steps = 1\n"
      "  set Point forces = @apex: 0, 0, -1e-2\nend\n"
      "subsection Output\n  set Probes = apex_z: position @apex z\n"
      "  set Write VTU = false\n  set Plot = false\nend\n");
    const Scene        scene(prm);
    std::ostringstream log;
    const RunSummary   run = run_scene(scene, "out_" + mesh_file, &log);
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    // The apex starts at z = 1.
    return {log.str(), run.rows.back().at(1) - 1};
  }

  /// The message with which @p f refuses its input ("" if it does not).
  template <class F>
  std::string
  refusal_of(const F &f)
  {
    try
      {
        f();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    ADD_FAILURE() << "the input was accepted";
    return "";
  }

  TEST(CoincidentNodes, DomeWithTheApexWrittenTwiceIsOneJoint)
  {
    const DomeRun once  = run_dome(written("dome_once.msh", dome_mesh(false)));
    const DomeRun twice = run_dome(written("dome_twice.msh", dome_mesh(true)));
    // Kept apart, the copy made the grid line along y one rod passing
    // under the loaded apex (39 rods, 1.76 times the deflection).
    ASSERT_LT(once.deflection, -1e-5);
    EXPECT_NEAR(twice.deflection, once.deflection, 1e-12 * -once.deflection);
    EXPECT_EQ(once.log.find("merged"), std::string::npos) << once.log;
    EXPECT_NE(twice.log.find("rodnet: mesh \"./dome_twice.msh\": merged "
                             "coincident nodes (within 5.74e-08 m, 1e-08 of "
                             "the diagonal of the mesh's bounding box): node "
                             "1000 into node 13\n"),
              std::string::npos)
      << twice.log;
  }

  TEST(CoincidentNodes, RoundOffApartIsMerged)
  {
    // 1e-9 m apart, within 1e-8 of the diagonal of the dome's box (5.74 m):
    // the same answer as the node written once.
    const DomeRun once = run_dome(written("dome_one.msh", dome_mesh(false)));
    const DomeRun near =
      run_dome(written("dome_near.msh", dome_mesh(true, 1e-9)));
    EXPECT_NEAR(near.deflection, once.deflection, 1e-12 * -once.deflection);
    EXPECT_NE(near.log.find("node 1000 into node 13"), std::string::npos)
      << near.log;
  }

  TEST(CoincidentNodes, SlightlyApartIsRefused)
  {
    // 1e-5 m: beyond the merge tolerance (5.74e-8 m), below 1e-3 of the
    // shortest element (0.252 m): neither one joint nor surely two nodes.
    const std::string message = refusal_of([] {
      read_gmsh_network(written("dome_apart.msh", dome_mesh(true, 1e-5)));
    });
    EXPECT_NE(message.find("mesh \"dome_apart.msh\": nodes 13 and 1000 are "
                           "1e-05 m apart: too far to be merged (within "
                           "5.74e-08 m) and too close to be distinct"),
              std::string::npos)
      << message;
  }

  TEST(CoincidentNodes, ElementBetweenCoincidentNodesIsRefused)
  {
    const std::string message = refusal_of([] {
      read_gmsh_network(
        written("zero_element.msh",
                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
                "1 0 0 0\n2 1 0 0\n3 1 0 0\n4 2 0 0\n$EndNodes\n"
                "$Elements\n3\n1 1 2 1 1 1 2\n2 1 2 1 1 2 3\n"
                "3 1 2 1 1 3 4\n$EndElements\n"));
    });
    EXPECT_NE(message.find("mesh \"zero_element.msh\": element 2 joins nodes "
                           "2 and 3, which coincide (0 apart, within 2e-08 "
                           "m): a line element of zero length"),
              std::string::npos)
      << message;
  }

  TEST(CoincidentNodes, GmshRodClosesThroughItsCopiedFirstNode)
  {
    // A square ring whose last element ends at a copy of its first node
    // (5 at 1): merged, it is closed, as drawn.
    const std::vector<RodChain> rods = read_gmsh_rods(
      written("copied_start.msh",
              "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n"
              "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 0\n$EndNodes\n"
              "$Elements\n4\n1 1 2 1 1 1 2\n2 1 2 1 1 2 3\n"
              "3 1 2 1 1 3 4\n4 1 2 1 1 4 5\n$EndElements\n"));
    ASSERT_EQ(rods.size(), 1u);
    EXPECT_TRUE(rods[0].closed);
    EXPECT_EQ(rods[0].points.size(), 4u);
  }

  TEST(CoincidentNodes, NetworkFileNodesWithinTheToleranceAreRefused)
  {
    // 1e-10 m apart in a network of size 1: one point, named twice.
    const std::string message = refusal_of([] {
      build_rod_network(read_network_file(
                          written("near_nodes.net",
                                  "node a 0 0 0 clamped\nnode b 1 0 0\n"
                                  "node c 1.0000000001 0 0\nnode d 1 1 0\n"
                                  "beam a b\nbeam c d\n")),
                        2,
                        "simple");
    });
    EXPECT_NE(message.find("nodes \"b\" and \"c\" coincide at (1, 0, 0) "
                           "(1e-10 apart, within 1.41e-08 m): a joint is one "
                           "node"),
              std::string::npos)
      << message;
  }
} // namespace
