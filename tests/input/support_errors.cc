// Supports that cannot do what they say are refused by rodnet-run with
// exit code 1 and one line naming them: a clamp of a one-segment rod,
// a DoF held twice at different values (naming both supports), a clamp's
// inner vertex held elsewhere, a moment into a clamp or onto a prescribed
// rotation, a rod end name that is no rod end.
#include <common/run_driver.h>
#include <common/scene_text.h>

#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet::testing;

  const std::string material = direct_material(1e4, 1, 1, 1);

  /// A straight rod of @p segments segments with @p supports_and_loads.
  std::string
  rod(const unsigned int segments, const std::string &supports_and_loads)
  {
    return "subsection Geometry\n"
           "  set Segments = " +
           std::to_string(segments) +
           "\n"
           "end\n" +
           material + supports_and_loads;
  }

  std::string
  supports(const std::string &entries)
  {
    return "subsection Supports\n" + entries + "end\n";
  }

  TEST(SupportErrors, ClampOfAOneSegmentRod)
  {
    // Both vertices of the only segment held: every load would vanish.
    expect_input_error_naming("clamp_one_segment",
                              rod(1,
                                  supports("  set Clamped ends = start\n") +
                                    "subsection Loads\n"
                                    "  set Point forces = end: 0, 1, 0\n"
                                    "end\n"),
                              {"\"Clamped ends: start\"",
                               "rod 0 has a single segment",
                               "at least 2 segments"});
  }

  TEST(SupportErrors, ClampedEndPinnedAndPrescribed)
  {
    expect_input_error_naming(
      "clamp_pinned_prescribed",
      rod(10,
          supports("  set Clamped ends = start\n"
                   "  set Pinned vertices = start\n"
                   "  set Prescribed displacements = start: x=0.1\n")),
      {"\"Pinned vertices: start\"",
       "\"Prescribed displacements: start: x=0.1\"",
       "x of vertex 0 of rod 0",
       "0 m and 0.1 m"});
  }

  TEST(SupportErrors, TwoPrescribedDisplacementsOfOneVertex)
  {
    // "end" and "0:10" are the same vertex.
    expect_input_error_naming("two_displacements",
                              rod(10,
                                  supports(
                                    "  set Clamped ends = start\n"
                                    "  set Prescribed displacements = end: "
                                    "y=0.1; 0:10: y=0.2\n")),
                              {"\"Prescribed displacements: end: y=0.1\"",
                               "\"Prescribed displacements: 0:10: y=0.2\"",
                               "y of vertex 10 of rod 0"});
  }

  TEST(SupportErrors, MovedJunctionAndPin)
  {
    // The frame's clamped junction moved by a prescribed displacement and
    // held by a pin.
    expect_input_error_naming("junction_and_pin",
                              "subsection Geometry\n"
                              "  set Generator = frame\n"
                              "  set Segments = 4\n"
                              "end\n" +
                                material +
                                supports(
                                  "  set Pinned vertices = @clamp\n"
                                  "  set Prescribed displacements = @clamp: "
                                  "z=0.01\n"),
                              {"\"Pinned vertices: @clamp\"",
                               "\"Prescribed displacements: @clamp: z=0.01\"",
                               "z of vertex 0 of rod 0"});
  }

  TEST(SupportErrors, InnerVertexOfAMovingClamp)
  {
    // The clamp moves rigidly with its end vertex; a pin of its second
    // vertex would tear it.
    expect_input_error_naming("clamp_inner_vertex",
                              rod(10,
                                  supports(
                                    "  set Clamped ends = start\n"
                                    "  set Pinned vertices = 0:1\n"
                                    "  set Prescribed displacements = start: "
                                    "y=0.1\n")),
                              {"\"Pinned vertices: 0:1\"",
                               "the clamp \"Clamped ends: start\"",
                               "moves rigidly"});
  }

  TEST(SupportErrors, ClampTurnedTwice)
  {
    expect_input_error_naming(
      "clamp_turned_twice",
      rod(10,
          supports("  set Clamped ends = start\n"
                   "  set Prescribed rotations = start: "
                   "0,0,1 10; 0:start: 0,0,1 20\n")),
      {"clamp \"Clamped ends: start\"", "turned twice"});
  }

  TEST(SupportErrors, MomentIntoAClamp)
  {
    expect_input_error_naming("moment_at_clamp",
                              rod(10,
                                  supports(
                                    "  set Clamped ends = start, end\n") +
                                    "subsection Loads\n"
                                    "  set Moments = end: 0,0,1 1\n"
                                    "end\n"),
                              {"entry \"Loads/Moments\"",
                               "\"Clamped ends: end\"",
                               "take up the whole moment"});
  }

  TEST(SupportErrors, MomentOnAPrescribedRotation)
  {
    expect_input_error_naming(
      "moment_on_prescribed_rotation",
      rod(10,
          supports("  set Clamped ends = start\n"
                   "  set Prescribed rotations = end: 0,0,1 "
                   "10\n") +
            "subsection Loads\n"
            "  set Moments = end: 0,0,1 1\n"
            "end\n"),
      {"moment at junction \"end\"", "rotation is held"});
  }

  TEST(SupportErrors, ClampedEndThatIsNoEnd)
  {
    expect_input_error_naming("clamp_mid",
                              rod(10, supports("  set Clamped ends = mid\n")),
                              {"entry \"Supports/Clamped ends\"",
                               "\"mid\" names no rod end"});
    expect_input_error_naming("clamp_unknown_name",
                              "subsection Geometry\n"
                              "  set Generator = square lattice\n"
                              "  set Segments = 2\n"
                              "end\n" +
                                material +
                                supports("  set Clamped ends = @n_9_9\n"),
                              {"entry \"Supports/Clamped ends\"", "\"n_9_9\""});
  }

  /// The rod above in quasi-static time stepping, with the support entries
  /// @p support_entries and the load entries @p load_entries.
  std::string
  rod_in_time(const std::string &support_entries,
              const std::string &load_entries)
  {
    return rod(10, supports("  set Clamped ends = start\n" + support_entries)) +
           "subsection Loads\n" + load_entries +
           "end\n"
           "subsection Solver\n"
           "  set Method = time stepping\n"
           "  subsection Time stepping\n"
           "    set Integrator = quasi-static\n"
           "    set Time step = 0.25\n"
           "  end\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Plot = false\n"
           "end\n";
  }

  TEST(SupportErrors, FixedLoadsWithOnlySupportsMovingInTime)
  {
    // A support "in time" follows its function of time, not the load
    // factor: with the loads fixed, the load factor has nothing to ramp.
    expect_input_error_naming(
      "fixed_loads_in_time",
      rod_in_time("  set Prescribed displacements = end: x=0.01 in time t\n",
                  "  set Fixed loads = true\n"),
      {"entry \"Loads/Fixed loads\"",
       "the load factor has nothing to ramp",
       "without \"in time\""});
    // One item the load factor ramps is enough.
    const DriverOutcome ramped = run_driver(
      "fixed_loads_ramped_and_in_time",
      rod_in_time("  set Prescribed displacements = end: x=0.01\n"
                  "  set Prescribed rotations = end: 0,0,1 10 in time t\n",
                  "  set Fixed loads = true\n"));
    EXPECT_EQ(ramped.exit_code, 0) << ramped.output;
    // A held imperfection perturbs what a support moving in time does:
    // something moves besides it.
    const DriverOutcome held = run_driver(
      "held_imperfection_in_time",
      rod_in_time("  set Prescribed displacements = end: y=0.01 in time t\n",
                  "  subsection Imperfections\n"
                  "    set Point forces = end: 0, 0, 1e-6\n"
                  "  end\n"));
    EXPECT_EQ(held.exit_code, 0) << held.output;
    // So does an activation field driven in time (it was refused: "the
    // load factor has nothing else to ramp").
    const DriverOutcome activated = run_driver(
      "held_imperfection_activation_in_time",
      rod_in_time("",
                  "  subsection Imperfections\n"
                  "    set Point forces = end: 0, 0, 1e-6\n"
                  "  end\n") +
        "subsection Group all\n  set Natural twist = 0.5 in time t\nend\n");
    EXPECT_EQ(activated.exit_code, 0) << activated.output;
  }

  TEST(SupportErrors, ConditionalInTimeIsNotTheVertexColon)
  {
    // The ':' of a conditional in the function of time is not the one
    // that ends the vertex (it used to be taken as such: "unknown vertex").
    const DriverOutcome conditional = run_driver(
      "conditional_in_time",
      rod_in_time(
        "  set Prescribed displacements = end: y=0.01 in time t < 0.5 ? t : "
        "0.5\n",
        ""));
    EXPECT_EQ(conditional.exit_code, 0) << conditional.output;
  }
} // namespace
