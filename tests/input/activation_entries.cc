// The items of the activation entries of a group (io/activation_fields.h,
// doc/morphing.md): what an item says, and the integrals of its field over
// arc-length intervals against hand integration.
#include <common/run_scene_text.h>
#include <common/scene_text.h>
#include <io/activation_fields.h>

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;

  const ActivationEntry curvature_entry   = activation_entries()[0],
                        eigenstrain_entry = activation_entries()[2];

  TEST(ActivationEntries, ItemsRegionsAndRamps)
  {
    const std::vector<ActivationItem> items = parse_activation_items(
      "x-beams",
      curvature_entry,
      "min(s, 0.5), 2 on 0.1 to 0.4 fixed; 1, 0 on near ends 0.2;"
      " 0, 3*s/L ramped; 0, 5 on near ends 0.1 in time 1 - exp(-t/2)");
    using Kind = ActivationDrive::Kind;
    ASSERT_EQ(items.size(), 4u);
    EXPECT_EQ(items[0].entry, "Group x-beams/Natural curvature");
    EXPECT_EQ(items[0].drive.kind, Kind::fixed);
    EXPECT_EQ(items[0].region, ActivationItem::Region::interval);
    EXPECT_EQ(items[0].start, 0.1);
    EXPECT_EQ(items[0].end, 0.4);
    EXPECT_EQ(items[1].region, ActivationItem::Region::near_ends);
    EXPECT_EQ(items[1].start, 0.2);
    EXPECT_EQ(items[1].drive.kind, Kind::load_factor);
    EXPECT_EQ(items[2].region, ActivationItem::Region::whole_rod);
    EXPECT_EQ(items[2].drive.kind, Kind::load_factor);
    // The function of time, its blanks included, after the region.
    EXPECT_EQ(items[3].region, ActivationItem::Region::near_ends);
    EXPECT_EQ(items[3].start, 0.1);
    ASSERT_EQ(items[3].drive.kind, Kind::time);
    EXPECT_NEAR((*items[3].drive.of_time)(2.), 1 - std::exp(-1.), 1e-15);
    EXPECT_THROW(
      (*parse_activation_items("all", eigenstrain_entry, "0.01 in time log(t)")
          .at(0)
          .drive.of_time)(-1.),
      std::invalid_argument);
  }

  TEST(ActivationEntries, IntegralsOverIntervals)
  {
    const auto item = [](const std::string &text) {
      return parse_activation_items("all", curvature_entry, text).at(0);
    };
    // min(s, 0.5) on [0.1, 0.4] is s: its integral over [0, 0.3] is
    // (0.09 - 0.01) / 2; the constant 2 gives 2 x 0.2.
    const Eigen::Vector4d a =
      activation_field(item("min(s, 0.5), 2 on 0.1 to 0.4"),
                       1.,
                       0.,
                       "rod 0")(0., 0.3);
    EXPECT_NEAR(a[0], 0.04, 1e-15);
    EXPECT_NEAR(a[1], 0.4, 1e-15);
    EXPECT_EQ(a[2], 0.);
    EXPECT_EQ(a[3], 0.);
    // Near ends 0.8 of a rod of length 1: the ends overlap, the whole rod
    // once. The polygon starts 0.05 behind s = 0 (a midpoint clamp).
    const ActivationField whole =
      activation_field(item("1, 0 on near ends 0.8"), 1., 0.05, "rod 0");
    EXPECT_NEAR(whole(0., 1.05)[0], 1., 1e-15);
    EXPECT_NEAR(whole(0., 0.15)[0], 0.1, 1e-15);
    // 3 s / L with L = 2 over [0, 2]: 3.
    EXPECT_NEAR(activation_field(item("0, 3*s/L"), 2., 0., "rod 0")(0., 2.)[1],
                3.,
                1e-14);
    // An eigenstrain is the fourth density.
    EXPECT_NEAR(activation_field(parse_activation_items("all",
                                                        eigenstrain_entry,
                                                        "0.01 on 0.5 to 1")
                                   .at(0),
                                 1.,
                                 0.,
                                 "rod 0")(0.25, 0.75)[3],
                0.0025,
                1e-17);
  }

  /// The scene of a clamped rod with @p field in "Group all" and the loads
  /// fixed.
  std::string
  fixed_loads_scene(const std::string &field)
  {
    return rodnet::testing::direct_material(1e4, 1, 1, 1) +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Group all\n  set " +
           field + "\nend\nsubsection Loads\n  set Fixed loads = true\nend\n";
  }

  TEST(ActivationEntries, FixedLoadsRampAField)
  {
    // With the loads held, a ramped field is what the load factor ramps;
    // a fixed one leaves it nothing.
    for (const bool fixed : {false, true})
      {
        dealii::ParameterHandler prm;
        Scene::declare_parameters(prm);
        read_scene_text(prm,
                        fixed_loads_scene(fixed ? "Natural twist = 1 fixed" :
                                                  "Natural twist = 1"),
                        "scene",
                        false);
        if (fixed)
          EXPECT_THROW(Scene{prm}, std::invalid_argument);
        else
          EXPECT_NO_THROW(Scene{prm});
      }
  }
} // namespace
