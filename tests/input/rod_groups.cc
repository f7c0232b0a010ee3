// Rod groups: the generators tag their beams with named groups, and a
// scene's "Group <name>" subsections give the rods of a group a material,
// a director d1 and a number of segments, checked against beam theory;
// a scene names as many materials as it needs; what cannot be meant is
// refused naming the subsection.
#include <common/group_counts.h>
#include <common/scene_text.h>
#include <geometry/network_generators.h>
#include <io/scene_file.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <string>

namespace
{
  using namespace rodnet;
  using rodnet::testing::count_in;
  using rodnet::testing::run_scene_text;

  TEST(RodGroups, LatticesTagTheirBeams)
  {
    // A square lattice of nx x ny cells has nx (ny + 1) beams along x,
    // (nx + 1) ny along y, 2 (nx + ny) on its edge; a honeycomb patch's
    // interior sides are those two cells share: 6 nx ny sides counted per
    // cell are the boundary once and the interior twice.
    const RodGraph square = network_generators::square_lattice(3, 2, 1.0);
    EXPECT_EQ(count_in(square, "x-beams"), 9u);
    EXPECT_EQ(count_in(square, "y-beams"), 8u);
    EXPECT_EQ(count_in(square, "boundary"), 10u);
    EXPECT_EQ(count_in(square, "interior"), 7u);
    for (const auto &[nx, ny] : {std::pair{1u, 1u}, {2u, 2u}, {4u, 3u}})
      {
        const RodGraph hexagons =
          network_generators::hexagonal_lattice(nx, ny, 1.0);
        const unsigned int interior = count_in(hexagons, "interior");
        EXPECT_EQ(interior + count_in(hexagons, "boundary"),
                  hexagons.beams.size());
        EXPECT_EQ(count_in(hexagons, "boundary") + 2 * interior, 6 * nx * ny)
          << nx << " x " << ny;
      }
  }

  /// Writes a network file of @p text to @p path; returns @p path.
  std::string
  network_file(const std::string &path, const std::string &text)
  {
    std::ofstream(path) << text;
    return path;
  }

  /// The material subsection @p title with rigidities EI1 = EI2 = @p EI,
  /// GJ = @p GJ and EA = 1e4 (its round-off floor, 1e4 eps per segment
  /// length, far below the loads).
  std::string
  group_material(const std::string &title, const double EI, const double GJ)
  {
    std::string text = rodnet::testing::direct_material(1e4, EI, EI, GJ);
    return "subsection " + title + text.substr(text.find('\n'));
  }

  /// The vertical displacement of the node "tip" of the network file
  /// @p net with @p segments per beam, under a force @p P along z there,
  /// with the scene text @p groups (materials and groups).
  double
  tip_deflection(const std::string &net,
                 const unsigned int segments,
                 const double       P,
                 const std::string &groups)
  {
    const RunSummary run =
      run_scene_text("subsection Geometry\n  set Generator = network file\n"
                     "  set Network file = " +
                       net + "\n  set Segments = " + std::to_string(segments) +
                       "\nend\n" + groups +
                       "subsection Loads\n  set Point forces = @tip: 0, 0, " +
                       std::to_string(P) + "\nend\n" +
                       rodnet::testing::probes_only("w: position @tip z"),
                     "rod_groups_out");
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    return run.rows.back()[rodnet::testing::probe_column(run, "w")];
  }

  TEST(RodGroups, EachGroupTakesItsMaterial)
  {
    // An L of two beams of length 1 in the xy-plane, clamped at the
    // origin, a force P along z at the tip. Castigliano: the tip deflects
    // P (L_a^3 / (3 EI_a) + L_b^3 / (3 EI_b) + L_b^2 L_a / GJ_a), the
    // first beam bent and twisted by the moment P L_b, the second bent.
    // The second beam's group takes "Material soft"; P is small enough
    // for linear theory (deflection 1e-4 of the length).
    const std::string net = network_file(
      "rod_groups_L.net",
      "node clamp 0 0 0 clamped\nnode corner 1 0 0\nnode tip 1 1 0\n"
      "beam clamp corner group first\nbeam corner tip group second\n");
    const double      EI_a = 2, GJ_a = 1.5, EI_b = 0.5, GJ_b = 0.1, P = 1e-4;
    const double      exact = P * (1 / (3 * EI_a) + 1 / (3 * EI_b) + 1 / GJ_a);
    const std::string groups =
      group_material("Material", EI_a, GJ_a) +
      group_material("Material soft", EI_b, GJ_b) +
      "subsection Group second\n  set Material = soft\nend\n";
    const double w = tip_deflection(net, 40, P, groups);
    std::cout << "L frame: tip deflection " << w << ", Castigliano " << exact
              << std::endl;
    EXPECT_NEAR(w, exact, 1e-3 * exact);
    // Without its group the second beam takes Material: the answer moves
    // by far more than the tolerance.
    const double same = P * (2 / (3 * EI_a) + 1 / GJ_a);
    EXPECT_NEAR(
      tip_deflection(net, 40, P, group_material("Material", EI_a, GJ_a)),
      same,
      1e-3 * same);
  }

  TEST(RodGroups, EachGroupTakesItsDirector)
  {
    // One beam along x clamped at the origin, EI1 = 1 about d1, EI2 = 4
    // about d2, a force along z at its tip of length 1: it bends about y,
    // so with d1 = e_y the tip deflects P / (3 EI1), with d1 = e_z (the
    // default) P / (3 EI2).
    const std::string net =
      network_file("rod_groups_beam.net",
                   "node clamp 0 0 0 clamped\nnode tip 1 0 0\n"
                   "beam clamp tip group beam\n");
    const std::string material = rodnet::testing::direct_material(1e4, 1, 4, 1);
    const double      P        = 1e-4;
    EXPECT_NEAR(tip_deflection(net,
                               40,
                               P,
                               material + "subsection Group beam\n"
                                          "  set Director d1 = 0, 1, 0\nend\n"),
                P / 3,
                1e-3 * P / 3);
    EXPECT_NEAR(tip_deflection(net, 40, P, material), P / 12, 1e-3 * P / 12);
  }

  TEST(RodGroups, EachGroupTakesItsSegments)
  {
    // A 2 x 1 lattice: y-beams of 7 segments, x-beams of Geometry's 3.
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm,
                    "subsection Geometry\n  set Generator = square lattice\n"
                    "  set Cells = 2, 1\n  set Segments = 3\nend\n" +
                      rodnet::testing::direct_material() +
                      "subsection Group y-beams\n  set Segments = 7\nend\n",
                    "scene",
                    false);
    const Scene    scene(prm);
    const auto     model = scene.build_model();
    const RodGraph graph = network_generators::square_lattice(2, 1, 1.0);
    for (unsigned int r = 0; r < graph.beams.size(); ++r)
      EXPECT_EQ(model->network().rods()[r].vertices.size() - 1,
                graph.beams[r].groups.front() == "y-beams" ? 7u : 3u)
        << "rod " << r;
    // The size known before the model is built counts them.
    EXPECT_EQ(scene.size().segments, 4 * 3 + 3 * 7);
  }

  /// The message of the refusal of the scene @p text; empty if accepted.
  std::string
  refusal(const std::string &text)
  {
    try
      {
        dealii::ParameterHandler prm;
        Scene::declare_parameters(prm);
        read_scene_text(prm, text, "scene", false);
        const Scene scene(prm);
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }

  const std::string lattice = "subsection Geometry\n"
                              "  set Generator = square lattice\n"
                              "  set Cells = 2, 2\nend\n" +
                              rodnet::testing::direct_material();

  TEST(RodGroups, WhatCannotBeMeantIsRefused)
  {
    const std::map<std::string, std::string> cases = {
      {"subsection Group x-beam\n  set Segments = 2\nend\n",
       "subsection \"Group x-beam\": no rod is in group \"x-beam\"; the "
       "groups of this geometry are \"x-beams\", \"y-beams\""},
      {"subsection Group x-beams\n  set Material = soft\nend\n"
       "subsection Group boundary\n  set Material = soft\nend\n" +
         group_material("Material soft", 1, 1),
       "subsections \"Group boundary\" and \"Group x-beams\" both give beam 0 "
       "(n_0_0 to n_1_0) a material; a rod takes one"},
      {"subsection Group x-beams\n  set Material = sfot\nend\n" +
         group_material("Material soft", 1, 1),
       "entry \"Group x-beams/Material\": the scene has no subsection "
       "\"Material sfot\"; it names \"soft\""},
      {group_material("Material soft", 1, 1),
       "subsection \"Material soft\": no rod takes this material"},
      {"subsection Group y-beams\n  set Director d1 = 0, 2, 0\nend\n",
       "entry \"Group y-beams/Director d1\": d1 is parallel to beam 6 (n_0_0 "
       "to n_0_1)"},
      {"subsection Group all\n  set Director d1 = 0, 0\nend\n",
       "entry \"Group all/Director d1\": \"0, 0\" is not a vector of three "
       "numbers"},
      {"subsection Material of group 1\n  set Use = true\nend\n",
       "subsection \"Material of group 1\": material groups are named now"}};
    for (const auto &[text, message] : cases)
      EXPECT_NE(refusal(lattice + text).find(message), std::string::npos)
        << refusal(lattice + text) << "\nexpected: " << message;
    // A single rod has no beams to orient by group.
    EXPECT_NE(refusal(rodnet::testing::direct_material() +
                      "subsection Group all\n  set Director d1 = 0, 1, "
                      "0\nend\n")
                .find("entry \"Group all/Director d1\": these rods are not a "
                      "network's beams; Geometry/Director d1 orients them"),
              std::string::npos);
  }
} // namespace
