// Lestringant & Kochmann (2020), Fig. 7 (scenes/fig7_shrinking_lattice.prm):
// a planar square lattice whose beams carry the out-of-plane natural
// curvature (0, kappa0 / L) about d2, -kappa0 on the quarters next to the
// junctions and +kappa0 on the middle half, frames x-beams d1 = e_z,
// d2 = -e_y, y-beams d1 = e_z, d2 = e_x, the centre junction clamped.
// Every beam's natural shape leaves and reaches its junctions along its
// axis at the same height (the turns cancel, the tangent angle is odd about
// mid-span), so the lattice takes all of them at once, stress free: its
// junctions stay flat and its footprint shrinks to the chord of that shape,
//   c / L = 4 sin(kappa0 / 4) / kappa0,
// every beam's midpoint sagging by 2 (1 - cos(kappa0 / 4)) / kappa0 L below
// its junctions (kappa2 > 0 turns the tangent towards d1 = e_z). Run here
// on the scene's lattice cut to 2 x 2 cells (12 beams, centre n_1_1) at
// kappa0 = 5.745 with 10, 30 and 90 segments per beam (refined by 3: the
// region ends at L/4 and 3L/4 stay on the boundary of a hinge's Voronoi
// cell), the closed form approached at second order. Ignoring the
// curvature leaves the footprint at L; a frame turned about the beam
// (curvature in the plane) leaves the sag at 0, one of the wrong sense
// raises the beams instead.
#include <common/run_scene_text.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  constexpr double kappa0 = 5.745, L = 1;

  /// The chord of a beam's natural shape over L.
  double
  natural_chord()
  {
    return 4 * std::sin(kappa0 / 4) / kappa0;
  }

  /// The height of a beam's midpoint above its junctions in its natural
  /// shape, over L (negative: below).
  double
  natural_midpoint_height()
  {
    return -2 * (1 - std::cos(kappa0 / 4)) / kappa0;
  }

  /// What the run on 2 x 2 cells measures at load factor 1, over L: the
  /// footprint's extent along x and y, the height of a corner junction
  /// (the centre's is held at 0), the heights of a boundary x-beam's and
  /// y-beam's midpoints above the mean of their junctions', and the
  /// elastic energy (EI = 1).
  struct Footprint
  {
    double width_x, width_y, corner_z, sag_x_beam, sag_y_beam, energy;
  };

  /// scenes/fig7_shrinking_lattice.prm on 2 x 2 cells clamped at n_1_1,
  /// @p segments per beam. Later entries of a subsection override the
  /// scene's (deal.II reads the subsection again). Rod 0: the x-beam
  /// n_0_0 - n_1_0; rod 8: the y-beam n_2_0 - n_2_1, its image under the
  /// quarter turn about the centre, which maps the lattice, its frames and
  /// its curvature onto themselves (x-beams first, j * 2 + i, then
  /// y-beams, 6 + j * 3 + i).
  Footprint
  run_lattice(const unsigned int segments)
  {
    std::ifstream file(RODNET_SOURCE_DIR "/scenes/fig7_shrinking_lattice.prm");
    std::stringstream scene;
    scene << file.rdbuf()
          << "subsection Geometry\n  set Cells = 2, 2\n  set Segments = "
          << segments
          << "\nend\n"
             "subsection Supports\n  set Clamped ends = @n_1_1\nend\n"
             "subsection Loads\n  set Steps = 5\nend\n"
             "subsection Output\n  set Plot = false\n"
             "  set Picture field = none\n"
             "  set Probes = west: position @n_0_1 x; east: position @n_2_1 "
             "x; south: position @n_1_0 y; north: position @n_1_2 y; "
             "corner_z: position @n_2_2 z; mid_x: position 0:mid z; a_x: "
             "position @n_0_0 z; b_x: position @n_1_0 z; mid_y: position "
             "8:mid z; a_y: position @n_2_0 z; b_y: position @n_2_1 z; "
             "energy: energy\nend\n";
    const RunSummary run =
      rodnet::testing::run_scene_text(scene.str(), "fig7_shrinking_lattice");
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    EXPECT_NEAR(run.final_load_factor, 1., 1e-12);
    const std::vector<double> &last  = run.rows.back();
    const auto                 value = [&](const std::string &name) {
      return last[rodnet::testing::probe_column(run, name)];
    };
    return {(value("east") - value("west")) / (2 * L),
            (value("north") - value("south")) / (2 * L),
            value("corner_z") / L,
            (value("mid_x") - (value("a_x") + value("b_x")) / 2) / L,
            (value("mid_y") - (value("a_y") + value("b_y")) / 2) / L,
            value("energy")};
  }

  TEST(Fig7ShrinkingLattice, FootprintIsTheNaturalShapesChord)
  {
    const double chord = natural_chord(), height = natural_midpoint_height();
    // 0.68997 and -0.30143 (the footprint shrinks by 31 %).
    std::cout << "closed form: chord " << chord << ", midpoint " << height
              << std::endl;
    std::vector<double> width_errors, sag_errors;
    double              corner_z_last = 0;
    for (const unsigned int segments : {10u, 30u, 90u})
      {
        const Footprint f = run_lattice(segments);
        std::cout << segments << " segments: width " << f.width_x << ", "
                  << f.width_y << ", sag " << f.sag_x_beam << ", "
                  << f.sag_y_beam << ", corner z " << f.corner_z << ", energy "
                  << f.energy << std::endl;
        // Both families alike: the quarter turn about e_z maps the
        // x-beams' frames onto the y-beams'.
        EXPECT_NEAR(f.width_y, f.width_x, 1e-9) << segments;
        EXPECT_NEAR(f.sag_y_beam, f.sag_x_beam, 1e-9) << segments;
        // Stress free: the lattice held flat would store 12 beams x
        // EI kappa0^2 / (2 L) = 198 EI / L (measured: 2.7e-9, 4.5e-15,
        // 3.0e-18).
        EXPECT_LT(f.energy, 1e-8) << segments;
        corner_z_last = f.corner_z;
        width_errors.push_back(std::abs(f.width_x - chord));
        sag_errors.push_back(std::abs(f.sag_x_beam - height));
      }
    const double width_order =
                   std::log(width_errors[1] / width_errors[2]) / std::log(3.),
                 sag_order =
                   std::log(sag_errors[1] / sag_errors[2]) / std::log(3.);
    std::cout << "errors of the width: " << width_errors[0] << ", "
              << width_errors[1] << ", " << width_errors[2] << " (order "
              << width_order << "); of the sag: " << sag_errors[0] << ", "
              << sag_errors[1] << ", " << sag_errors[2] << " (order "
              << sag_order << ")" << std::endl;
    // Measured at 90 segments: 3.3e-4 and 1.0e-4; the junctions leave the
    // plane by a third-order amount (a corner 4.1e-3, 1.5e-4, 5.6e-6).
    EXPECT_LT(width_errors[2], 4e-4);
    EXPECT_LT(sag_errors[2], 2e-4);
    EXPECT_LT(std::abs(corner_z_last), 1e-5);
    EXPECT_GT(width_order, 1.8);
    EXPECT_LT(width_order, 2.2);
    EXPECT_GT(sag_order, 1.8);
    EXPECT_LT(sag_order, 2.2);
  }
} // namespace
