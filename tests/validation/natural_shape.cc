// Rods stress free as built (Natural shape = initial geometry) under load:
// - the Gmsh rod with a right-angle kink of issue 11 (under 0.02 N its tip
//   moved 1 m while it was prestressed) has the tip deflection of the
//   L-shaped cantilever by Castigliano, converging at first order (the
//   kink is one hinge);
// - a helix loaded far into the nonlinear range and unloaded again, one
//   reference reset per step, returns to its initial geometry: the natural
//   strains stay those of the undeformed rod through every reset.
#include <common/scene_text.h>

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  constexpr double EA = 1e6, EI1 = 10, EI2 = 20, GJ = 7;
  const Vector3    tip_force(0.02, -0.01, 0.015);

  /**
   * Tip displacement of the L of unit legs, clamped at the origin, along x
   * to the corner (1, 0, 0), then along y to the tip (1, 1, 0); d1 = e_z.
   * In the plane, leg y carries the moment -(1 - y) F_x and the axial
   * force F_y, leg x the moment (1 - x) F_y - F_x and the axial force F_x;
   * out of it, F_z bends leg y by (1 - y) F_z about d2 = e_x, bends leg x
   * by (1 - x) F_z and twists it by F_z.
   */
  Vector3
  l_frame_deflection()
  {
    const double cxx = (1.0 / 3 + 1) / EI1 + 1 / EA;
    const double cyy = 1.0 / (3 * EI1) + 1 / EA;
    const double cxy = -1.0 / (2 * EI1);
    const double czz = 2.0 / (3 * EI2) + 1 / GJ;
    return Vector3(cxx * tip_force[0] + cxy * tip_force[1],
                   cxy * tip_force[0] + cyy * tip_force[1],
                   czz * tip_force[2]);
  }

  /// The kinked rod of tests/input/data/kinked_rod.msh with @p n elements
  /// per leg instead of 10, written to the working directory.
  std::string
  kinked_mesh(const unsigned int n)
  {
    std::vector<Vector3> points;
    for (unsigned int i = 0; i <= n; ++i)
      points.emplace_back(double(i) / n, 0, 0);
    for (unsigned int i = 1; i <= n; ++i)
      points.emplace_back(1, double(i) / n, 0);
    return write_gmsh_chain("kinked_" + std::to_string(n) + ".msh", points);
  }

  /// Relative error of the tip displacement of the kinked rod in @p mesh.
  double
  kinked_tip_error(const std::string &mesh)
  {
    const RunSummary run = run_scene_text(
      cantilever_scene("  set Generator = gmsh\n"
                       "  set Mesh file = " +
                         mesh +
                         "\n"
                         "  set Clamp at first segment midpoint = true\n",
                       direct_material(EA, EI1, EI2, GJ),
                       tip_force),
      "kinked_rod");
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    const Vector3 displacement =
      end_position(run, run.rows.size() - 1) - Vector3(1, 1, 0);
    return (displacement - l_frame_deflection()).norm() /
           l_frame_deflection().norm();
  }

  // Relative tip errors 4.7e-2, 2.3e-2, 1.2e-2 at 10, 20, 40 elements per
  // leg: first order, from the hinge at the kink, whose measure 2 sin(theta
  // / 2) turns half as stiff about the kink's axis at theta = 90 degrees
  // (a Voronoi cell's worth of compliance, O(h)).
  TEST(NaturalShape, KinkedGmshRodIsTheLShapedCantilever)
  {
    const std::array<double, 3> errors = {
      {kinked_tip_error(RODNET_SOURCE_DIR "/tests/input/data/kinked_rod.msh"),
       kinked_tip_error(kinked_mesh(20)),
       kinked_tip_error(kinked_mesh(40))}};
    std::cout << "kinked rod, relative tip error at 10, 20, 40 elements per "
                 "leg: "
              << errors[0] << ", " << errors[1] << ", " << errors[2]
              << std::endl;
    EXPECT_LT(errors[0], 0.05);
    EXPECT_NEAR(errors[0] / errors[1], 2, 0.3);
    EXPECT_NEAR(errors[1] / errors[2], 2, 0.3);
  }

  // A helix clamped at its start, its tip force ramped up to a tip
  // displacement of several coil radii in 20 quasi-static steps and back
  // to zero in 20 more, a reference reset after each: at zero load it is
  // back in its initial geometry.
  TEST(NaturalShape, HelixReturnsToItsInitialGeometryWhenUnloaded)
  {
    const RunSummary run =
      run_scene_text("subsection Geometry\n"
                     "  set Generator = helix\n"
                     "  set Radius = 0.5\n"
                     "  set Rise per radian = 0.1\n"
                     "  set Turns = 1.5\n"
                     "  set Segments = 30\n"
                     "  set Director d1 = 0, 0, 1\n"
                     "end\n" +
                       direct_material(EA, EI1, EI2, GJ) +
                       "subsection Supports\n  set Clamped ends = start\nend\n"
                       "subsection Loads\n"
                       "  set Point forces = end: 4, 0, -6\n"
                       "end\n"
                       "subsection Solver\n"
                       "  set Method = time stepping\n"
                       "  subsection Time stepping\n"
                       "    set Integrator = quasi-static\n"
                       "    set Time step = 0.05\n"
                       "    set End time = 2\n"
                       "    set Load factor = if(t <= 1, t, 2 - t)\n"
                       "  end\n"
                       "end\n" +
                       end_position_output(),
                     "helix_unloaded");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_FALSE(run.rows.empty());
    // The tip of the helix, x = (r cos t, r sin t, c t) at t = 3 pi.
    const Vector3 initial(-0.5, 0, 0.3 * M_PI);
    double        largest = 0;
    Vector3       tip     = Vector3::Zero();
    for (std::size_t row = 0; row < run.rows.size(); ++row)
      {
        tip     = end_position(run, row);
        largest = std::max(largest, (tip - initial).norm());
      }
    std::cout << "helix: largest tip displacement " << largest
              << " m, after unloading " << (tip - initial).norm() << " m"
              << std::endl;
    EXPECT_GT(largest, 1.0);
    EXPECT_LT((tip - initial).norm(), 1e-8);
  }
} // namespace
