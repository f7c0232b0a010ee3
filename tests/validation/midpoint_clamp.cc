// The midpoint clamp (Geometry/Clamp at first segment midpoint) on curved
// rods: the clamped first segment lies along the rod's tangent at its
// start, centred on it, for every open generator and for Gmsh chains; and a
// quarter-circle cantilever, stress free as built, has the tip deflection of
// curved-beam theory (Castigliano) with a second-order error, from the arc
// generator and from a Gmsh mesh of the same arc, where the plain clamp
// (half a segment in, along the first chord) is first order.
#include <common/scene_text.h>
#include <geometry/rod_generators.h>

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// Direction and midpoint of the first segment of @p points.
  std::pair<Vector3, Vector3>
  first_segment(const std::vector<Vector3> &points)
  {
    return {(points[1] - points[0]).normalized(),
            0.5 * (points[0] + points[1])};
  }

  TEST(MidpointClamp, ClampedSegmentIsTheTangentAtTheStart)
  {
    const double R = 2, a0 = 0.3, a1 = 2.0;
    const auto [arc_t, arc_mid] =
      first_segment(generators::arc(Vector3(1, 1, 0),
                                    R,
                                    Vector3::UnitX(),
                                    Vector3::UnitY(),
                                    a0,
                                    a1,
                                    10,
                                    true));
    EXPECT_LE((arc_t - Vector3(-std::sin(a0), std::cos(a0), 0)).norm(), 1e-14);
    EXPECT_LE(
      (arc_mid - Vector3(1 + R * std::cos(a0), 1 + R * std::sin(a0), 0)).norm(),
      1e-14 * R);

    // x = (r cos t, r sin t, c t): tangent (0, r, c) / |.| at t = 0.
    const double               r = 0.5, c = 0.1;
    const std::vector<Vector3> helix = generators::helix(r, c, 2, 40, true);
    const auto [helix_t, helix_mid]  = first_segment(helix);
    EXPECT_LE((helix_t - Vector3(0, r, c).normalized()).norm(), 1e-14);
    EXPECT_LE((helix_mid - Vector3(r, 0, 0)).norm(), 1e-14 * r);
    // The free length is the helix's: its last vertex is the end.
    EXPECT_LE((helix.back() - Vector3(r, 0, 4 * M_PI * c)).norm(), 1e-14 * r);

    // A polyline's first piece is laid out as a straight rod; its corners
    // stay vertices.
    const std::vector<Vector3> polyline = generators::polyline(
      {Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(1, 2, 0)},
      4,
      true);
    const auto [polyline_t, polyline_mid] = first_segment(polyline);
    EXPECT_LE((polyline_t - Vector3::UnitX()).norm(), 1e-15);
    EXPECT_LE(polyline_mid.norm(), 1e-15);
    EXPECT_EQ(polyline[4], Vector3(1, 0, 0));
    EXPECT_EQ(polyline.size(), 9u);

    // A mesh chain: its first segment is split around its first vertex.
    const std::vector<Vector3> chain = {Vector3(0, 0, 0),
                                        Vector3(0.2, 0.1, 0),
                                        Vector3(0.3, 0.3, 0)};
    const std::vector<Vector3> split =
      generators::center_first_segment_on_start(chain);
    const auto [chain_t, chain_mid] = first_segment(split);
    EXPECT_LE((chain_t - chain[1].normalized()).norm(), 1e-15);
    EXPECT_LE(chain_mid.norm(), 1e-15);
    ASSERT_EQ(split.size(), 4u);
    EXPECT_EQ(split[2], chain[1]);
    EXPECT_EQ(split[3], chain[2]);
  }

  // Quarter circle of radius R = 1 in the xy plane from (R, 0, 0), where it
  // is clamped, to the tip (0, R, 0); d1 = e_z, so EI1 bends in the plane
  // and EI2 out of it.
  constexpr double EA = 1e6, EI1 = 1, EI2 = 2, GJ = 0.7;
  const Vector3    tip_force(1e-6, -2e-6, 1.5e-6);

  /**
   * Tip displacement of the quarter circle by Castigliano: in the plane the
   * moment about e_z is -R cos(phi) F_y - R (1 - sin(phi)) F_x and the
   * axial force -F_x sin(phi) + F_y cos(phi); out of the plane F_z gives
   * the torque R F_z (1 - sin(phi)) and the moment R F_z cos(phi) about d2,
   * the radial direction (ds = R dphi, phi from 0 to pi/2).
   */
  Vector3
  curved_beam_deflection()
  {
    const double R = 1;
    const double cxx =
      std::pow(R, 3) / EI1 * (0.75 * M_PI - 2) + R * M_PI / (4 * EA);
    const double cyy = std::pow(R, 3) / EI1 * M_PI / 4 + R * M_PI / (4 * EA);
    const double cxy = std::pow(R, 3) / (2 * EI1) - R / (2 * EA);
    const double czz =
      std::pow(R, 3) * (M_PI / (4 * EI2) + (0.75 * M_PI - 2) / GJ);
    return Vector3(cxx * tip_force[0] + cxy * tip_force[1],
                   cxy * tip_force[0] + cyy * tip_force[1],
                   czz * tip_force[2]);
  }

  std::string
  quarter_circle_scene(const std::string &geometry)
  {
    return cantilever_scene(geometry,
                            direct_material(EA, EI1, EI2, GJ),
                            tip_force);
  }

  /// Relative error of the tip displacement of a run of @p scene.
  double
  tip_error(const std::string &scene, const std::string &name)
  {
    const RunSummary run = run_scene_text(scene, name);
    EXPECT_TRUE(run.failure.empty()) << run.failure;
    const Vector3 exact = curved_beam_deflection();
    return (end_position(run, run.rows.size() - 1) - Vector3(0, 1, 0) - exact)
             .norm() /
           exact.norm();
  }

  std::string
  arc_geometry(const unsigned int n, const bool midpoint)
  {
    return "  set Generator = arc\n"
           "  set Segments = " +
           std::to_string(n) + "\n  set Clamp at first segment midpoint = " +
           (midpoint ? "true" : "false") + "\n";
  }

  /// The quarter circle as a Gmsh line mesh of @p n elements.
  std::string
  gmsh_geometry(const unsigned int n)
  {
    std::vector<Vector3> points;
    for (unsigned int i = 0; i <= n; ++i)
      points.emplace_back(std::cos(M_PI / 2 * i / n),
                          std::sin(M_PI / 2 * i / n),
                          0);
    return "  set Generator = gmsh\n  set Mesh file = " +
           write_gmsh_chain("quarter_circle_" + std::to_string(n) + ".msh",
                            points) +
           "\n  set Clamp at first segment midpoint = true\n";
  }

  // Relative tip errors at N = 20, 40, 80 (doc/validation.md, "Midpoint
  // clamp"): 2.1e-3, 5.3e-4, 1.3e-4 from the arc generator, 1.3e-3, 3.2e-4,
  // 7.9e-5 from the mesh, 6.7e-2, 3.4e-2, 1.7e-2 with the plain clamp.
  TEST(MidpointClamp, QuarterCircleCantileverConvergesAtSecondOrder)
  {
    std::array<double, 3> arc, gmsh, plain;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const unsigned int n = 20 << k;
        arc[k] = tip_error(quarter_circle_scene(arc_geometry(n, true)),
                           "midpoint_arc");
        gmsh[k] =
          tip_error(quarter_circle_scene(gmsh_geometry(n)), "midpoint_gmsh");
        plain[k] = tip_error(quarter_circle_scene(arc_geometry(n, false)),
                             "midpoint_plain");
        std::cout << "N = " << n << ": relative tip error, midpoint clamp "
                  << arc[k] << " (arc), " << gmsh[k] << " (Gmsh); plain clamp "
                  << plain[k] << std::endl;
      }
    for (const auto &errors : {arc, gmsh})
      {
        EXPECT_LT(errors[1], 1e-3);
        // Second order: halving the segments divides the error by ~4.
        EXPECT_GT(errors[0] / errors[1], 3.5);
        EXPECT_GT(errors[1] / errors[2], 3.5);
      }
    // The plain clamp sits half a segment in, along the first chord: first
    // order, and 60 times the error at N = 40.
    EXPECT_GT(plain[1], 30 * arc[1]);
    EXPECT_NEAR(plain[0] / plain[1], 2, 0.2);
  }
} // namespace
