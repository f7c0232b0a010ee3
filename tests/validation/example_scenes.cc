// Every scene shipped in scenes/ runs as shipped and gives the answer its
// header comment promises: one small example per generator, each against
// an independent reference (beam, ring or curved-beam theory, an exact
// statement of statics), and a check that no scene is left untested.
#include <deal.II/base/parameter_handler.h>

#include <common/run_scene_text.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// One probe of a shipped scene at its last converged step.
  struct Expectation
  {
    std::string scene;
    std::string probe;
    /// The reference value of the probe, from theory.
    double reference;
    /// Allowed |value - reference| / scale.
    double tolerance;
    /// The scale of the error: |reference| unless given (a position
    /// probe is compared against the displacement it measures).
    double scale = 0;
    /// Scene text read after the file (later entries override).
    std::string overrides = "";
  };

  std::ostream &
  operator<<(std::ostream &out, const Expectation &e)
  {
    return out << e.scene << ": " << e.probe
               << (e.overrides.empty() ? "" : " (with overrides)");
  }

  /// Runs scenes/@p name.prm as shipped, then @p overrides, without VTU
  /// files and plots.
  RunSummary
  run_shipped_scene(const std::string &name, const std::string &overrides)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/" + name + ".prm");
    std::stringstream text;
    text << file.rdbuf() << "\n"
         << overrides
         << "\nsubsection Output\n  set Write VTU = false\n"
            "  set Plot = false\nend\n";
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    // As rodnet-run reads it: its "Group <name>" and "Material <name>"
    // subsections declared first.
    read_scene_text(prm, text.str(), name + ".prm", false);
    const Scene scene(prm, RODNET_SOURCE_DIR "/scenes");
    return run_scene(scene, "example_" + name, nullptr);
  }

  const double pi = M_PI;

  /// scenes/overcurved_ring.prm at its end, O = 3: the triply covered
  /// polygon of its 400 segments (each of length l = 2 R sin(pi / 400) on
  /// the circle of radius R), whose curvature measure 2 sin(3 pi / 400) / l
  /// falls short of the natural curvature 3 (2 pi / L) by O(1/N^2): the
  /// prestress energy (N l / 2) EI1 (kappa0 - that)^2 (doc/overcurved_ring.md).
  double
  triply_covered_ring_energy()
  {
    const double n = 400, radius = 0.0499746521, ei1 = 50. / 12;
    const double kappa0    = 3 * 20.010144290380847;
    const double segment   = 2 * radius * std::sin(pi / n);
    const double curvature = 2 * std::sin(3 * pi / n) / segment;
    return n * segment / 2 * ei1 * (kappa0 - curvature) * (kappa0 - curvature);
  }

  const std::string energy_search =
    "subsection Solver\n  set Line search = energy\nend\n";
  const std::string trust_region =
    "subsection Solver\n  set Line search = trust region\nend\n";

  // P = 1e-3 N, EI = 1 N m^2 and the lengths of the scenes' comments.
  // Tolerances are a little above the discretization error measured at the
  // scene's resolution (second order in every case; quoted per line).
  const std::vector<Expectation> expectations = {
    // Quarter circle, out-of-plane tip force: P R^3 [pi/(4 EI) + (3 pi/4 -
    // 2)/GJ] with GJ = 2/3 (Castigliano). Measured -3.3e-4 at N = 40.
    {"arc", "tip_z", 1e-3 * (pi / 4 + (3 * pi / 4 - 2) * 1.5), 1e-3},
    {"arc", "clamp_force_z", -1e-3, 1e-9},
    // Ring across a diameter: R - (pi/4 - 2/pi) P R^3 / EI; measured
    // +1.6e-3 of the displacement at N = 160 (+6e-3 at 80, second order).
    {"ring",
     "top_y",
     1 - (pi / 4 - 2 / pi) * 1e-3,
     2.5e-3,
     (pi / 4 - 2 / pi) * 1e-3},
    {"ring", "bottom_force_y", 1e-3, 1e-8},
    // L-shaped rod, out-of-plane force: P L^3 (2/(3 EI) + 1/GJ) = 13/6 P.
    // Measured -6.5e-7 at 80 segments per leg.
    {"polyline", "tip_z", 13. / 6 * 1e-3, 1e-4},
    // Cantilever from a mesh: P L^3 / (3 EI). Measured -6.5e-4 at N = 21.
    {"gmsh_rod", "tip_y", 1e-3 / 3, 1.5e-3},
    // Windmill twisted by 1e-3 rad: M = tau EI / ((127/900) L_b) with
    // L_b = 1/2 (doc/junctions.md). Measured -9.8e-4 at N = 20.
    {"windmill", "top_moment_z", 1e-3 * 900. / 127 / 0.5, 2e-3},
    // Portal frame, sway H / k with k = 24 (1 + 6 r)/(4 + 6 r), r = 1/2.
    // Measured +1.2e-3 at N = 40 (+4.6e-3 at 20, second order).
    {"network_file", "sway", 1e-3 * 7. / 96, 2e-3},
    // Antisymmetric sway: the bases share the horizontal force (the beam
    // carries H/2 across, up to its axial strain).
    {"network_file", "base_shear_left", -5e-4, 1e-3},
    // Clamped-clamped beam, middle force: -P L^3 / (192 EI). Measured
    // +1.25e-3 at 80 elements (+5e-3 at 40, second order).
    {"gmsh_network", "mid_y", -1e-3 / 192, 2e-3},
    {"gmsh_network", "left_force_y", 5e-4, 1e-9},
    // Square lattice stretched by d = 1e-3: each top node EA d / (2 a),
    // exact (no bending); the lattice does not contract sideways.
    {"square_lattice", "corner_force_y", 0.5, 1e-9},
    {"square_lattice", "inner_force_y", 0.5, 1e-9},
    {"square_lattice", "corner_x", 3, 1e-12},
    // Free thermal expansion of the honeycomb: a stress-free dilation by
    // 1 + e0 about the pinned node (0, 1/2), exact.
    {"hexagonal_lattice", "far_x", 3 * std::sqrt(3.) * 1.001, 1e-10},
    {"hexagonal_lattice", "far_y", 0.5 + 3 * 1.001, 1e-10},
    {"hexagonal_lattice", "energy", 0, 1e-20, 1},
    // The default scene: the elastica at P = 5 (VALIDATION.md), exact
    // post-buckled tip; the tip moves by about 1 along both axes.
    {"elastica", "tip_x", 0.059784, 5e-4, 1},
    {"elastica", "tip_y", 0.795217, 5e-4, 1},
    // P1, the gravity cantilever: the inextensible elastica's tip
    // (BENCHMARKS.md); the rod's extension (EA = 7854 N) puts it 3.4e-5
    // lower, in one load step.
    {"p1_gravity_cantilever", "tip_x", 0.5157790, 1e-4, 1},
    {"p1_gravity_cantilever", "tip_z", -0.7938299, 1e-4, 1},
    // Beam on a Winkler foundation (Hetenyi): -P beta / (2 k) under the
    // load, times exp(-beta x)(cos beta x + sin beta x) at x = 1.6 (beta = 1).
    // Measured +6.2e-4 at beta h = 0.05 (second order).
    {"beam_on_elastic_foundation", "mid_z", -1.25e-4, 1e-3},
    {"beam_on_elastic_foundation",
     "x16_z",
     -1.25e-4 * std::exp(-1.6) * (std::cos(1.6) + std::sin(1.6)),
     1e-3,
     1.25e-4},
    // The right-angle frame with its tip moved by a small u_z = 1e-4 (the
    // shipped u_z = L has no closed form): F = (6/13) EI u_z / L^3
    // (VALIDATION.md, doc/junctions.md).
    {"frame",
     "force_z",
     6. / 13 * 1e-4,
     2e-3,
     0,
     "subsection Supports\n  set Prescribed displacements = @tip: z=1e-4\n"
     "end\nsubsection Loads\n  set Steps = 1\nend\n"},
    // The seed examples of Korner et al. section 5, which snap at a limit
    // point (Limit points = snap) and end with the paper's whole curve.
    // The over-curved ring passes O_d on the triply covered ring and ends
    // at O = 3 as its polygon (measured 5e-6 of its energy, 1.59e-5 J).
    {"overcurved_ring", "energy", triply_covered_ring_energy(), 1e-4},
    // The bent ribbon (w = 8 mm) snaps at phi = 115.4 degrees onto the
    // mirror image of its own path, which ends at phi = 180 degrees on the
    // image of its start: the half circle of radius 0.108 again (measured
    // to 1e-14 m).
    {"ribbon_snapping", "apex_y", 0.108, 1e-9},
    // The same references with Newton globalized by the energy line search
    // (doc/nonlinear_solvers.md): P1 needs cut steps, the others none.
    {"p1_gravity_cantilever", "tip_x", 0.5157790, 1e-4, 1, energy_search},
    {"p1_gravity_cantilever", "tip_z", -0.7938299, 1e-4, 1, energy_search},
    {"arc",
     "tip_z",
     1e-3 * (pi / 4 + (3 * pi / 4 - 2) * 1.5),
     1e-3,
     0,
     energy_search},
    {"beam_on_elastic_foundation", "mid_z", -1.25e-4, 1e-3, 0, energy_search},
    // And by the trust region (doc/nonlinear_solvers.md): P1 creeps as with
    // the energy line search, 4 cut steps.
    {"p1_gravity_cantilever", "tip_x", 0.5157790, 1e-4, 1, trust_region},
    {"arc",
     "tip_z",
     1e-3 * (pi / 4 + (3 * pi / 4 - 2) * 1.5),
     1e-3,
     0,
     trust_region},
    {"beam_on_elastic_foundation", "mid_z", -1.25e-4, 1e-3, 0, trust_region},
  };

  /// Scenes with a validation test of their own.
  const std::set<std::string> tested_elsewhere = {
    "bonded_loop",            // validation/bonding_scenes
    "deep_arch",              // validation/continuation
    "eigenstrain_column",     // validation/eigenstrain_column
    "fig6_building_block",    // validation/fig6_building_block
    "fig6_tessellation",      // validation/fig6_building_block
    "fig7_shrinking_lattice", // validation/fig7_shrinking_lattice
    "fig8_pinned_lattice_a",  // validation/pinned_lattice (4 x 4 cells)
    "fig8_pinned_lattice_b",  // validation/pinned_lattice (7 x 7 cells)
    "fig9_popup",             // validation/popup_two_layer
    "gridshell",              // validation/gridshell
    "helical_spring",         // validation/helical_spring
    "hexagonal_truss",        // validation/hexagonal_truss
    "lee_frame",              // validation/continuation_snap
    "moebius_band",           // validation/moebius_band
    "overcurved_ring",        // validation/overcurved_ring
    "ribbon_snapping",        // validation/ribbon_snapping
    "rollup_lateral",         // validation/rollup_lateral
    "spin_up",                // validation/moving_supports
    "substrate_bridge",       // validation/substrate_bridge
  };

  class ExampleScenes : public ::testing::TestWithParam<Expectation>
  {
  };

  TEST_P(ExampleScenes, LastStepMatchesTheReference)
  {
    const Expectation &e   = GetParam();
    const RunSummary   run = run_shipped_scene(e.scene, e.overrides);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_FALSE(run.rows.empty());
    const double value = run.rows.back().at(probe_column(run, e.probe));
    const double scale = e.scale > 0 ? e.scale : std::abs(e.reference);
    std::cout << e << " = " << value << ", reference " << e.reference
              << ", error " << (value - e.reference) / scale << std::endl;
    EXPECT_NEAR(value, e.reference, e.tolerance * scale);
  }

  INSTANTIATE_TEST_SUITE_P(Shipped,
                           ExampleScenes,
                           ::testing::ValuesIn(expectations));

  // A scene added to scenes/ needs a reference here or a test of its own.
  TEST(ExampleScenes, EveryShippedSceneIsTested)
  {
    std::set<std::string> covered = tested_elsewhere;
    for (const Expectation &e : expectations)
      covered.insert(e.scene);
    for (const auto &entry :
         std::filesystem::directory_iterator(RODNET_SOURCE_DIR "/scenes"))
      if (entry.path().extension() == ".prm")
        {
          EXPECT_TRUE(covered.count(entry.path().stem().string()) == 1)
            << "scenes/" << entry.path().filename().string()
            << " is run by no test";
        }
  }
} // namespace
