// Gravity weighs the rods by their material: rho A of its Density and
// cross-section where "Mass per length" is not given. A steel cantilever
// under its own weight against the beam formula q L^4 / (8 EI), q = rho A g;
// a lattice of two material groups against statics (its supports carry the
// weight of both groups); a group without mass refused by name.
#include <common/run_scene_text.h>

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <string>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  const double g = 9.81;

  /// Subsection @p subsection: a linear elastic material of density
  /// @p rho, Young's modulus @p E and a circular section of radius @p r,
  /// with the lines @p extra.
  std::string
  circle_material(const std::string &subsection,
                  const double       rho,
                  const double       E,
                  const double       r)
  {
    return "subsection " + subsection + "\n" +
           "  set Density = " + std::to_string(rho) +
           "\n"
           "  subsection linear elastic\n"
           "    set Stiffness input = section\n"
           "    set Young's modulus = " +
           std::to_string(E) +
           "\n"
           "    set Poisson's ratio = 0.3\n"
           "    set Cross section = circle\n"
           "    set Radius = " +
           std::to_string(r) + "\n  end\nend\n";
  }

  const std::string gravity = "subsection Loads\n"
                              "  set Steps = 1\n"
                              "  set Gravity = 0, 0, -9.81\n"
                              "end\n";

  TEST(GravityWeight, SteelCantileverUnderItsOwnWeight)
  {
    // Steel, r = 10 mm, L = 1 m: q = rho pi r^2 g = 24.19 N/m,
    // EI = E pi r^4 / 4 = 1649 N m^2, w = q L^4 / (8 EI) = 1.83 mm. The
    // large-deflection correction is of order (q L^3 / EI)^2 = 2e-4 and the
    // discretization error (N = 100, midpoint clamp) of order 1e-4:
    // tolerance 1e-3 of w.
    const double     rho = 7850, E = 210e9, r = 0.01, L = 1;
    const RunSummary run = run_scene_text(
      "subsection Geometry\n"
      "  set Segments = 100\n"
      "  set Clamp at first segment midpoint = true\n"
      "end\n" +
        circle_material("Material", rho, E, r) +
        "subsection Supports\n  set Clamped ends = start\nend\n" + gravity +
        "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
        "  set Probes = tip_z: position end z; reaction_z: reaction start z\n"
        "end\n",
      "gravity_steel_cantilever");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.size(), 2u);
    const double q          = rho * M_PI * r * r * g;
    const double EI         = E * M_PI * std::pow(r, 4) / 4;
    const double w          = q * std::pow(L, 4) / (8 * EI);
    const double deflection = -run.rows[1][probe_column(run, "tip_z")];
    std::cout << "tip deflection " << deflection << " m, q L^4 / (8 EI) = " << w
              << " m, relative error " << (deflection - w) / w << std::endl;
    EXPECT_NEAR(deflection, w, 1e-3 * w);
    // The clamp carries the whole weight, of the rod from -l/2 to L
    // (l = L / 99.5: the clamped segment is centred on the start).
    const double length = L + L / 99.5 / 2;
    EXPECT_NEAR(run.rows[1][probe_column(run, "reaction_z")],
                q * length,
                1e-6 * q * length);
  }

  /// A square lattice cell of side 1, beams along x of subsection
  /// Material, along y (group "y-beams") of "Material aluminium", pinned at
  /// its four corners, with @p materials.
  std::string
  two_group_cell(const std::string &materials)
  {
    return "subsection Geometry\n"
           "  set Generator = square lattice\n"
           "  set Cells = 1, 1\n"
           "  set Segments = 10\n"
           "end\n" +
           materials +
           "subsection Group y-beams\n  set Material = aluminium\nend\n"
           "subsection Supports\n"
           "  set Pinned vertices = @n_0_0, @n_1_0, @n_0_1, @n_1_1\n"
           "end\n" +
           gravity;
  }

  TEST(GravityWeight, EachGroupWeighsItsOwnMaterial)
  {
    // Steel beams (r = 10 mm) along x, aluminium (r = 20 mm) along y: the
    // corners carry 2 (m0 + m1) g L, a quarter each by the cell's mirror
    // symmetries (statics, exact: tolerance 1e-6 of the sum, 1e-4 of each
    // corner's share for the symmetry of the converged state).
    const double     m0 = 7850 * M_PI * 1e-4, m1 = 2700 * M_PI * 4e-4;
    const double     weight = 2 * (m0 + m1) * g;
    const RunSummary run    = run_scene_text(
      two_group_cell(circle_material("Material", 7850, 210e9, 0.01) +
                     circle_material("Material aluminium", 2700, 70e9, 0.02)) +
        "subsection Output\n  set Write VTU = false\n  set Plot = false\n"
           "  set Probes = a: reaction @n_0_0 z; b: reaction @n_1_0 z; "
           "c: reaction @n_0_1 z; d: reaction @n_1_1 z\nend\n",
      "gravity_two_groups");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    double sum = 0;
    for (const std::string corner : {"a", "b", "c", "d"})
      {
        const double reaction = run.rows.back()[probe_column(run, corner)];
        EXPECT_NEAR(reaction, weight / 4, 1e-4 * weight / 4) << corner;
        sum += reaction;
      }
    std::cout << "corner reactions " << sum
              << " N, weight 2 (m0 + m1) g L = " << weight
              << " N, relative error " << (sum - weight) / weight << std::endl;
    EXPECT_NEAR(sum, weight, 1e-6 * weight);
  }

  TEST(GravityWeight, GroupWithoutMassIsRefused)
  {
    // Group 1 has a section but no density, and no Mass per length is
    // given: gravity would weigh it as nothing.
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_text(prm,
                    two_group_cell(
                      circle_material("Material", 7850, 210e9, 0.01) +
                      circle_material("Material aluminium", 0, 70e9, 0.02)),
                    "scene",
                    false);
    try
      {
        const Scene scene(prm);
        FAIL() << "a material group without mass was weighed";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find(
                    "entry \"Loads/Gravity\": the rods of \"Material "
                    "aluminium\" have no mass to weigh; give \"Material "
                    "aluminium/Density\""),
                  std::string::npos)
          << e.what();
      }
  }
} // namespace
