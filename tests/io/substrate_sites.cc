// Subsection Substrate: pinned bonding sites end where the substrate's
// affine map x -> c + (I + lambda H)(x - c) carries them, at every load
// factor, for a general in-plane strain about a given centre; a released
// prestretch eps_pre moves them as the compressive strain
// eps_pre / (1 + eps_pre) does, about the sites' centroid; a clamped
// junction moves with the map and keeps its rotation, a clamped free end
// moves rigidly with the map of its end segment's midpoint.
#include <common/run_scene_text.h>
#include <common/scene_text.h>

#include <Eigen/Dense>
#include <array>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  const std::array<const char *, 3> site_names = {{"start", "corner", "end"}};
  const std::array<const char *, 3> site_vertices = {{"start", "4", "end"}};
  const std::array<Eigen::Vector2d, 3> sites      = {
         {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1)}};

  /// An L of two unit legs in the plane z = 0, 4 segments each, its
  /// start, corner and end pinned to the substrate of @p substrate (the
  /// entries), two load steps; probes: the three sites' x, y and z.
  std::string
  pinned_l(const std::string &substrate)
  {
    std::string probes;
    for (unsigned int s = 0; s < 3; ++s)
      for (const char *c : {"x", "y", "z"})
        probes += std::string(probes.empty() ? "" : "; ") + site_names[s] +
                  "_" + c + ": position " + site_vertices[s] + " " + c;
    return direct_material() +
           "subsection Geometry\n  set Generator = polyline\n"
           "  set Points = 0,0,0; 1,0,0; 1,1,0\n  set Segments = 4\n"
           "  set Director d1 = 0, 0, 1\nend\n"
           "subsection Substrate\n  set Pinned sites = start, 4, end\n" +
           substrate +
           "end\nsubsection Loads\n  set Steps = 2\nend\n"
           "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
           "  set Probes = " +
           probes + "\nend\n";
  }


  /// Asserts that every row of @p run has the sites at the map of the
  /// gradient @p h about @p centre at its load factor.
  void
  expect_sites_follow(const RunSummary      &run,
                      const Eigen::Matrix2d &h,
                      const Eigen::Vector2d &centre)
  {
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 3u);
    for (const std::vector<double> &row : run.rows)
      for (unsigned int s = 0; s < 3; ++s)
        {
          const Eigen::Vector2d x =
            centre +
            (Eigen::Matrix2d::Identity() + row[0] * h) * (sites[s] - centre);
          const std::string name = site_names[s];
          EXPECT_NEAR(row.at(probe_column(run, name + "_x")), x[0], 1e-12)
            << name << " at " << row[0];
          EXPECT_NEAR(row.at(probe_column(run, name + "_y")), x[1], 1e-12)
            << name << " at " << row[0];
          EXPECT_NEAR(row.at(probe_column(run, name + "_z")), 0, 1e-12)
            << name << " at " << row[0];
        }
  }

  TEST(SubstrateSites, PinnedSitesFollowAGeneralInPlaneStrain)
  {
    const RunSummary run =
      run_scene_text(pinned_l("  set In-plane strain = 0.1, 0.05, 0.02\n"
                              "  set Centre = 0.3, 0.2\n"),
                     "substrate_in_plane");
    Eigen::Matrix2d h;
    h << 0.1, 0.02, 0.02, 0.05;
    expect_sites_follow(run, h, Eigen::Vector2d(0.3, 0.2));
  }

  TEST(SubstrateSites, ReleasedPrestretchIsItsCompressiveStrain)
  {
    // A substrate bonded compressed by 20 % (eps_pre = -0.2) and released
    // stretches the sites' distances by 1 / 0.8: a compressive strain of
    // -0.25 about the sites' centroid (2/3, 1/3).
    const Eigen::Vector2d centroid(2. / 3, 1. / 3);
    for (const std::string entry : {"  set Released prestretch = -0.2\n",
                                    "  set Compressive strain = -0.25\n"})
      expect_sites_follow(run_scene_text(pinned_l(entry), "substrate_release"),
                          0.25 * Eigen::Matrix2d::Identity(),
                          centroid);
  }
  TEST(SubstrateSites, ClampedJunctionAndEndsTranslateWithTheSubstrate)
  {
    // A T of three unit beams welded at j; its free ends a, b and the
    // junction clamped, the stem's end c free.
    std::ofstream("substrate_t.net") << "node a 0 0 0\nnode j 1 0 0\n"
                                        "node b 2 0 0\nnode c 1 1 0\n"
                                        "beam a j\nbeam j b\nbeam j c\n";
    std::string probes = "rotation: rotation j 0,0,1";
    for (const char *v : {"a", "j", "b"})
      for (const char *c : {"x", "y", "z"})
        probes +=
          std::string("; ") + v + "_" + c + ": position @" + v + " " + c;
    const RunSummary run = run_scene_text(
      direct_material() +
        "subsection Geometry\n  set Generator = network file\n"
        "  set Network file = substrate_t.net\n  set Segments = 4\nend\n"
        "subsection Substrate\n  set Clamped sites = @a, @j, @b\n"
        "  set In-plane strain = 0.1, -0.05, 0.03\n  set Centre = 0, 0\n"
        "end\nsubsection Loads\n  set Steps = 2\nend\n"
        "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
        "  set Probes = " +
        probes + "\nend\n",
      "substrate_t");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    Eigen::Matrix2d h;
    h << 0.1, 0.03, 0.03, -0.05;
    // Where each site is bonded (a and b: the midpoints of their end
    // segments, a quarter beam long) and where its vertex is.
    const std::array<std::pair<const char *, Eigen::Vector2d>, 3> bonded = {
      {{"a", Eigen::Vector2d(0.125, 0)},
       {"j", Eigen::Vector2d(1, 0)},
       {"b", Eigen::Vector2d(1.875, 0)}}};
    const std::array<Eigen::Vector2d, 3> vertex = {
      {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(2, 0)}};
    for (const std::vector<double> &row : run.rows)
      {
        EXPECT_NEAR(row.at(probe_column(run, "rotation")), 0, 1e-12);
        for (unsigned int s = 0; s < 3; ++s)
          {
            const Eigen::Vector2d x = vertex[s] + row[0] * h * bonded[s].second;
            const std::string     name = bonded[s].first;
            EXPECT_NEAR(row.at(probe_column(run, name + "_x")), x[0], 1e-12)
              << name << " at " << row[0];
            EXPECT_NEAR(row.at(probe_column(run, name + "_y")), x[1], 1e-12)
              << name << " at " << row[0];
            EXPECT_NEAR(row.at(probe_column(run, name + "_z")), 0, 1e-12)
              << name << " at " << row[0];
          }
      }
  }
} // namespace
