// Bad junction input gives one clear std::invalid_argument naming the
// junction: ends that do not meet, a pinned junction of one rod, a non-unit
// prescribed quaternion or axis, a prescribed rotation of a pinned junction,
// a moment on a clamp, a zero-length segment at a junction.
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>

#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;

  /// Expects @p action to throw std::invalid_argument whose message
  /// contains every one of @p words.
  template <typename Action>
  void
  expect_junction_error(Action &&action, const std::vector<std::string> &words)
  {
    try
      {
        action();
        ADD_FAILURE() << "no error";
      }
    catch (const std::invalid_argument &e)
      {
        for (const std::string &w : words)
          EXPECT_NE(std::string(e.what()).find(w), std::string::npos)
            << "\"" << w << "\" missing from: " << e.what();
      }
  }

  /// Two rods along x: [0, 1] and [1 + gap, 2].
  std::unique_ptr<RodNetwork>
  two_rods(const double gap)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3(0, 0, 0),
                                          Vector3(1, 0, 0),
                                          4),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->add_rod(generators::straight(Vector3(1 + gap, 0, 0),
                                          Vector3(2, 0, 0),
                                          4),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    return network;
  }

  TEST(JunctionErrors, RodsThatDoNotMeet)
  {
    auto network = two_rods(1e-3);
    expect_junction_error(
      [&] {
        network->add_junction("knee",
                              JunctionKind::welded,
                              {{0, false}, {1, true}});
      },
      {"knee", "do not meet", "start of rod 1"});
  }

  TEST(JunctionErrors, PinnedJunctionOfOneRod)
  {
    auto network = two_rods(0);
    expect_junction_error(
      [&] {
        network->add_junction("p", JunctionKind::pinned, {{0, false}});
      },
      {"\"p\"", "pinned", "single rod end"});
  }

  TEST(JunctionErrors, EndInTwoJunctions)
  {
    auto network = two_rods(0);
    network->add_junction("a", JunctionKind::welded, {{0, false}, {1, true}});
    expect_junction_error(
      [&] {
        network->add_junction("b", JunctionKind::clamped, {{1, true}});
      },
      {"\"b\"", "already in junction \"a\""});
  }

  TEST(JunctionErrors, ZeroLengthSegmentAtJunction)
  {
    auto network = two_rods(0);
    // The second rod's first segment has zero length: refused when the rod
    // is added, naming it, before any junction can use it.
    expect_junction_error(
      [&] {
        network->add_rod({Vector3(2, 0, 0), Vector3(2, 0, 0), Vector3(3, 0, 0)},
                         false,
                         Vector3::UnitZ(),
                         "simple");
      },
      {"rod 2", "zero-length segment 0"});
  }

  TEST(JunctionErrors, PrescribedRotations)
  {
    auto network = two_rods(0);
    network->add_junction("clamp", JunctionKind::clamped, {{0, true}});
    network->add_junction("knee",
                          JunctionKind::pinned,
                          {{0, false}, {1, true}});
    RodModel model(
      std::move(network),
      {std::make_shared<LinearElasticRod>(RodStiffness{1, 1, 1, 1}),
       std::make_shared<LinearElasticRod>(RodStiffness{1, 1, 1, 1})});
    expect_junction_error(
      [&] { model.prescribe_rotation(0, Quaternion(1, 0.1, 0, 0)); },
      {"norm", "not 1"});
    expect_junction_error(
      [&] { model.prescribe_rotation(0, Vector3(0, 0, 2), 1.0); },
      {"\"clamp\"", "unit vector"});
    expect_junction_error(
      [&] { model.prescribe_rotation(1, Vector3::UnitZ(), 1.0); },
      {"\"knee\"", "pinned junction has no rotation"});
    expect_junction_error([&] { model.add_moment(0, Vector3::UnitZ(), 1.0); },
                          {"\"clamp\"", "no free rotation"});
    // A unit quaternion is accepted.
    EXPECT_NO_THROW(
      model.prescribe_rotation(0,
                               Quaternion(std::cos(0.3), 0, 0, std::sin(0.3))));
  }
} // namespace
