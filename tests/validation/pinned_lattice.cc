// Lestringant & Kochmann (2020), Fig. 8 (scenes/fig8_pinned_lattice_a.prm,
// _b.prm): a square lattice whose junctions are all pinned (Supports/Pinned
// vertices = junctions), rotations free, buckled by an axial eigenstrain
// e0 ramped to 0.03 (A L^2 / I1 = 1250, e_cr = pi^2 / 1250 = 7.896e-3), the
// pattern selected by imperfection moments held from the first step on
// (Loads/Imperfections). The buckled pattern turns neighbouring junctions in
// opposite senses and bends every beam into the first mode of a pinned-
// pinned column with free end rotations: the joint rotation tau_z is the
// end rotation of the single pinned-pinned column under the eigenstrain
// (the paper's own check, Fig. 8c). The reference is the continuous
// extensible column (curvature per reference length, as the rods measure
// it), solved here by shooting; the discrete column converges to it at
// second order (320 segments: 3e-6).
//  - (a), 4 x 4 cells, one moment: tau_z at every junction two beams or
//    more from the imperfection, at e0 = 0.015, 0.0225, 0.03 (1.9 to 3.8
//    e_cr, away from the bifurcation), within 1.5 % of the column at 10
//    segments per beam (measured 1.09 %) and 0.4 % at 20 (0.27 %), the
//    observed order between 1.8 and 2.2;
//  - (b) as shipped, 11 x 11 cells, two opposite moments point-symmetric
//    about the centre: two domains of opposite pattern, a wall between the
//    junction columns 5 and 6, the junctions three columns or more from it
//    within 1.5 % of the column, the state stable.
#include <common/run_scene_text.h>

#include <array>
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

  constexpr double EI = 1, L = 1, final_eigenstrain = 0.03;
  /// A L^2 / I1 of the scenes.
  constexpr double lattice_EA = 1250;

  /// The load factors checked and their eigenstrains lambda e0.
  constexpr std::array<double, 3> load_factors = {{0.5, 0.75, 1}};

  /**
   * The half column 0 <= s <= L/2 from the pin, s its reference arc
   * length, axial rigidity @p EA: EI theta'' = -H (1 + eps) sin(theta),
   * eps = e0 - H cos(theta)/EA
   * (the pins' thrust H, no shear force in the symmetric mode), theta(0) =
   * @p alpha, theta'(0) = 0 (no moment at the pin), integrated by RK4 in
   * @p n steps. Returns theta(L/2) (zero by symmetry) and x(L/2) - L/2 (the
   * pins L apart).
   */
  std::array<double, 2>
  half_column_mismatch(const double       EA,
                       const double       alpha,
                       const double       H,
                       const double       e0,
                       const unsigned int n = 400)
  {
    using State  = std::array<double, 3>; // theta, EI theta', x
    const auto f = [&](const State &y) {
      const double stretch = 1 + e0 - H * std::cos(y[0]) / EA;
      return State{
        {y[1] / EI, -stretch * H * std::sin(y[0]), stretch * std::cos(y[0])}};
    };
    const auto along = [](const State &y, const double h, const State &k) {
      return State{{y[0] + h * k[0], y[1] + h * k[1], y[2] + h * k[2]}};
    };
    const double h = 0.5 * L / n;
    State        y = {{alpha, 0, 0}};
    for (unsigned int i = 0; i < n; ++i)
      {
        const State k1 = f(y), k2 = f(along(y, h / 2, k1)),
                    k3 = f(along(y, h / 2, k2)), k4 = f(along(y, h, k3));
        for (unsigned int c = 0; c < 3; ++c)
          y[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
      }
    return {{y[0], y[2] - 0.5 * L}};
  }

  /// The end rotation of the buckled continuous column of axial rigidity
  /// @p EA at eigenstrain @p e0: Newton on (alpha, H) with a
  /// finite-difference Jacobian, from the small-amplitude estimates
  /// alpha = 2 sqrt(e0 - e_cr), H = pi^2 EI.
  double
  column_end_rotation(const double e0, const double EA = lattice_EA)
  {
    const double critical = M_PI * M_PI * EI / (EA * L * L);
    double       alpha = 2 * std::sqrt(e0 - critical), H = M_PI * M_PI * EI;
    for (unsigned int it = 0; it < 30; ++it)
      {
        const auto   r   = half_column_mismatch(EA, alpha, H, e0);
        const double d   = 1e-7;
        const auto   ra  = half_column_mismatch(EA, alpha + d, H, e0);
        const auto   rh  = half_column_mismatch(EA, alpha, H + d, e0);
        const double j00 = (ra[0] - r[0]) / d, j01 = (rh[0] - r[0]) / d;
        const double j10 = (ra[1] - r[1]) / d, j11 = (rh[1] - r[1]) / d;
        const double det = j00 * j11 - j01 * j10;
        alpha -= (j11 * r[0] - j01 * r[1]) / det;
        H -= (j00 * r[1] - j10 * r[0]) / det;
        if (std::abs(r[0]) + std::abs(r[1]) < 1e-14)
          break;
      }
    return alpha;
  }

  /// "t_i_j: rotation n_i_j 0,0,1" for every junction of @p cells x @p cells.
  std::string
  every_joint_rotation(const unsigned int cells)
  {
    std::string probes;
    for (unsigned int i = 0; i <= cells; ++i)
      for (unsigned int j = 0; j <= cells; ++j)
        probes += (probes.empty() ? "" : "; ") + std::string("t_") +
                  std::to_string(i) + "_" + std::to_string(j) +
                  ": rotation n_" + std::to_string(i) + "_" +
                  std::to_string(j) + " 0,0,1";
    return probes;
  }

  /// tau_z of junction (i, j) in the row of @p summary at @p lambda.
  double
  joint_rotation(const RunSummary  &summary,
                 const double       lambda,
                 const unsigned int i,
                 const unsigned int j)
  {
    const std::size_t column =
      rodnet::testing::probe_column(summary,
                                    "t_" + std::to_string(i) + "_" +
                                      std::to_string(j));
    for (const std::vector<double> &row : summary.rows)
      if (std::abs(row[0] - lambda) < 1e-12)
        return row[column];
    throw std::runtime_error("no row at load factor " + std::to_string(lambda));
  }

  /// The pattern's sign at (i, j): tau_z (-1)^(i + j).
  double
  staggered(const double tau, const unsigned int i, const unsigned int j)
  {
    return (i + j) % 2 == 0 ? tau : -tau;
  }

  /// The largest relative error of |tau_z| against the column over the
  /// junctions of 4 x 4 cells two beams or more from the imperfection at
  /// (2, 2) (the corners and the middle of the sides), and that they form
  /// the pattern the imperfection selects.
  double
  lattice_a_error(const unsigned int segments)
  {
    const RunSummary summary = rodnet::testing::run_scene_text(
      rodnet::testing::shipped_scene("fig8_pinned_lattice_a.prm",
                                     {{"Cells", "4, 4"},
                                      {"Segments", std::to_string(segments)},
                                      {"Moments", "n_2_2: 0,0,1 0.1"},
                                      {"Probes", every_joint_rotation(4)}}),
      "pinned_lattice_a");
    EXPECT_TRUE(summary.failure.empty()) << summary.failure;
    double worst = 0;
    for (const double lambda : load_factors)
      {
        const double reference =
          column_end_rotation(lambda * final_eigenstrain);
        for (unsigned int i = 0; i <= 4; i += 2)
          for (unsigned int j = 0; j <= 4; j += 2)
            if (i != 2 || j != 2)
              {
                const double tau = joint_rotation(summary, lambda, i, j);
                // The moment M_z > 0 at (2, 2) turns that sublattice
                // positively.
                EXPECT_GT(staggered(tau, i, j), 0) << i << ", " << j;
                worst =
                  std::max(worst, std::abs(std::abs(tau) / reference - 1));
              }
      }
    return worst;
  }

  TEST(PinnedLattice, ContinuousColumnReference)
  {
    // Nearly inextensible (EA = 1e9 EI / L^2): the elastica of length
    // L (1 + e0) between pins L apart, whose end shortening D / L0 =
    // e0 / (1 + e0) is 0.03027 and 0.25898 at the end rotations 20 and
    // 60 deg (VALIDATION.md; D given to 4 and 5 digits: 1e-4 in alpha).
    for (const auto &[degrees, shortening] :
         {std::pair{20.0, 0.03027}, {60.0, 0.25898}})
      EXPECT_NEAR(column_end_rotation(shortening / (1 - shortening), 1e9) /
                    (degrees * M_PI / 180),
                  1,
                  2e-4)
        << degrees;
  }

  TEST(PinnedLattice, JointRotationIsTheColumnsEndRotation)
  {
    const double error_10 = lattice_a_error(10);
    const double error_20 = lattice_a_error(20);
    std::cout << "largest error of tau_z at 10, 20 segments per beam: "
              << error_10 << ", " << error_20 << std::endl;
    EXPECT_LT(error_10, 0.015);
    EXPECT_LT(error_20, 0.004);
    const double order = std::log2(error_10 / error_20);
    EXPECT_GT(order, 1.8);
    EXPECT_LT(order, 2.2);
  }

  TEST(PinnedLattice, TwoDomainsAndAWall)
  {
    // (b) as shipped: 11 x 11 cells, +M at (2, 5) and -M at (9, 6), both
    // at i + j odd, point-symmetric about the centre (5.5, 5.5) in a cell.
    // (On 7 x 7 and 9 x 9 cells the symmetric path bifurcates near the
    // critical eigenstrain and the continuation ends in one domain.)
    const unsigned int cells   = 11;
    const RunSummary   summary = rodnet::testing::run_scene_text(
      rodnet::testing::shipped_scene("fig8_pinned_lattice_b.prm",
                                     {{"Probes", every_joint_rotation(cells)}}),
      "pinned_lattice_b");
    ASSERT_TRUE(summary.failure.empty()) << summary.failure;
    // A stable equilibrium: a wall through a junction column is not.
    EXPECT_EQ(summary.final_stable, 1);
    const double reference = column_end_rotation(final_eigenstrain);
    for (unsigned int i = 0; i <= cells; ++i)
      for (unsigned int j = 0; j <= cells; ++j)
        {
          const double tau = joint_rotation(summary, 1, i, j);
          // Left of the wall the pattern of +M at (2, 5) (i + j odd turns
          // positively), right of it that of -M at (9, 6) (negatively).
          const double sign = i <= 5 ? -1 : 1;
          EXPECT_GT(sign * staggered(tau, i, j), 0) << i << ", " << j;
          // Away from the wall, the column's rotation.
          if (i <= 3 || i >= 8)
            {
              EXPECT_NEAR(std::abs(tau) / reference, 1, 0.015)
                << i << ", " << j;
            }
        }
    // The wall: the beams between the columns 5 and 6 turn both ends the
    // same way (S-shaped), by less than the column's rotation.
    for (unsigned int j = 0; j <= cells; ++j)
      {
        const double left  = joint_rotation(summary, 1, 5, j);
        const double right = joint_rotation(summary, 1, 6, j);
        EXPECT_GT(left * right, 0) << j;
        EXPECT_LT(std::abs(left), 0.95 * reference) << j;
        EXPECT_LT(std::abs(right), 0.95 * reference) << j;
      }
  }
} // namespace
