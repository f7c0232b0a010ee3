// A structure that can move freely is a bad scene (exit code 1, naming the
// motion), not a solver failure; a mechanism inside a held structure stops
// the solver (exit code 2) with a message that says so. An elastic
// foundation holds what its springs stop and no more.
#include <common/rod_models.h>
#include <common/run_driver.h>
#include <common/scene_text.h>

#include <fstream>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using rodnet::testing::run_driver;

  /// No files but probes.csv: these runs are about their messages.
  const std::string quiet = "subsection Output\n"
                            "  set Write VTU = false\n"
                            "  set Plot = false\n"
                            "end\n";

  const std::string free_rod = "subsection Geometry\n"
                               "  set Segments = 20\n"
                               "  set Director d1 = 0, 0, 1\n"
                               "end\n" +
                               rodnet::testing::direct_material() + quiet;

  /// The straight rod with @p supports and a transverse force at @p vertex.
  std::string
  loaded_rod(const std::string &supports, const std::string &vertex)
  {
    return free_rod + "subsection Supports\n" + supports +
           "end\n"
           "subsection Loads\n"
           "  set Point forces = " +
           vertex + ": 0, 0, 1e-3\nend\n";
  }

  void
  expect_refused(const std::string &name,
                 const std::string &scene,
                 const std::string &motion)
  {
    const rodnet::testing::DriverOutcome o = run_driver(name, scene);
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find("the structure is not held"), std::string::npos)
      << o.output;
    EXPECT_NE(o.output.find(motion), std::string::npos)
      << "message lacks \"" << motion << "\":\n"
      << o.output;
  }

  TEST(FreeMotion, NoSupports)
  {
    expect_refused("rod",
                   loaded_rod("", "end"),
                   "rod 0 can translate in any direction and rotate about "
                   "any axis");
  }

  TEST(FreeMotion, OnePinnedNode)
  {
    expect_refused("one_pin",
                   loaded_rod("  set Pinned vertices = start\n", "end"),
                   "rotate about any axis through vertex 0:start");
  }

  TEST(FreeMotion, RodPinnedAtBothEndsSpins)
  {
    expect_refused("two_pins",
                   loaded_rod("  set Pinned vertices = start, end\n", "mid"),
                   "rotate about the axis through vertex 0:start along (1, "
                   "0, 0)");
  }

  TEST(FreeMotion, StraightRodOnAFoundationSpins)
  {
    // Springs in every direction hold the rod from the origin to (1, 0, 0)
    // but for its spin about its own line, which moves only the twists.
    expect_refused("foundation_spin",
                   loaded_rod("", "mid") + "subsection Elastic foundation\n"
                                           "  set Stiffness = 1\n"
                                           "end\n",
                   "the structure is not held: rod 0 can rotate about the "
                   "axis through (0.5, 0, 0) along (1, 0, 0);");
  }

  TEST(FreeMotion, RingOnSpringsAlongZSlidesAndTurnsInItsPlane)
  {
    expect_refused("foundation_along_z",
                   "subsection Geometry\n"
                   "  set Generator = ring\n"
                   "  set Center = 2, 1, 0\n"
                   "  set Segments = 12\n"
                   "  set Director d1 = 0, 0, 1\n"
                   "end\n" +
                     rodnet::testing::direct_material() + quiet +
                     "subsection Elastic foundation\n"
                     "  set Stiffness = 1\n"
                     "  set Direction = 0, 0, 1\n"
                     "end\n"
                     "subsection Loads\n"
                     "  set Point forces = 0:3: 0, 0, 1e-3\n"
                     "end\n",
                   "rod 0 can translate in the plane normal to (0, 0, 1) "
                   "and rotate about the axis through (2, 1, 0) along (0, "
                   "0, 1);");
  }

  TEST(Mechanism, FourBarLinkageIsReportedAsSuch)
  {
    // Three beams pinned to each other and, at their free ends A and D, to
    // the ground, held in their plane: a four-bar linkage. It sways at no
    // cost, which no rigid motion of the whole describes; a sideways force
    // at B has no equilibrium nearby, and the tangent is singular.
    std::ofstream("four_bar.net") << "node A 0 0 0\n"
                                     "node B 0 1 0 pinned\n"
                                     "node C 1 1 0 pinned\n"
                                     "node D 1 0 0\n"
                                     "beam A B d1 0 0 1\n"
                                     "beam B C d1 0 0 1\n"
                                     "beam C D d1 0 0 1\n";
    const rodnet::testing::DriverOutcome o =
      run_driver("four_bar",
                 "subsection Geometry\n"
                 "  set Generator = network file\n"
                 "  set Network file = four_bar.net\n"
                 "  set Segments = 4\n"
                 "end\n" +
                   rodnet::testing::direct_material() +
                   "subsection Supports\n"
                   "  set Pinned vertices = @A, @D\n"
                   "  set Fixed components = @B: z; @C: z\n"
                   "end\n"
                   "subsection Loads\n"
                   "  set Steps = 2\n"
                   "  set Point forces = @B: 1e-3, 0, 0\n"
                   "end\n"
                   "subsection Solver\n"
                   "  set Minimum step fraction = 0.25\n"
                   "end\n" +
                   quiet);
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find("is singular"), std::string::npos) << o.output;
    EXPECT_NE(o.output.find("(a mechanism)"), std::string::npos) << o.output;
  }
} // namespace
