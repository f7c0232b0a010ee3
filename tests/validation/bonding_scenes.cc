// scenes/bonded_loop.prm, a rod whose end a bond pulls to a point behind
// its clamp, read and run as shipped, against the same scene with the bond
// replaced by a support that moves the end to the point with the load
// factor (the same path: both ramp the end's target linearly). The loop's
// midpoint and the clamp's reaction agree at every step; the bond is
// reached through the scene entry "Bonding constraints/Bonds".
#include <common/run_scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  TEST(BondingScenes, BondedLoopIsTheEndMovedByASupport)
  {
    const RunSummary bonded =
      run_scene_text(shipped_scene("bonded_loop.prm", {}), "bonded_loop");
    const RunSummary moved = run_scene_text(
      shipped_scene("bonded_loop.prm",
                    {{"Bonds", ""},
                     {"Clamped ends",
                      "start\n  set Prescribed displacements = end: x=-0.8 "
                      "y=0.3 z=0"}}),
      "moved_loop");
    ASSERT_EQ(bonded.rows.size(), 21u);
    ASSERT_EQ(moved.rows.size(), bonded.rows.size());
    for (const char *probe : {"mid_x", "mid_y", "reaction_x", "reaction_y"})
      {
        const std::size_t column = probe_column(bonded, probe);
        double            scale  = 0;
        for (const auto &row : moved.rows)
          scale = std::max(scale, std::abs(row.at(column)));
        for (std::size_t i = 0; i < bonded.rows.size(); ++i)
          EXPECT_NEAR(bonded.rows[i].at(column),
                      moved.rows[i].at(column),
                      1e-8 * scale)
            << probe << " at step " << i;
      }
    std::cout << "clamp reaction at the end: "
              << bonded.rows.back().at(probe_column(bonded, "reaction_x"))
              << ", "
              << bonded.rows.back().at(probe_column(bonded, "reaction_y"))
              << std::endl;
  }
} // namespace
