// A pinned-pinned column under a growing axial eigenstrain, the eigenstrain
// the continuation parameter (Loads/Ramped natural shape), against
// ../shared/VALIDATION.md (Lestringant & Kochmann 2020, Fig. 8c):
//  - extensible, L / r = 100 (scenes/eigenstrain_column.prm): the
//    bifurcation at e_cr = pi^2 I / (A L^2), and the midspan deflection
//    over the stress-free length L (1 + e0) at e0 / e_cr = 2, 5, 10 (the
//    table's exact values; our own shooting solution of the continuous
//    extensible column with the rods' strain measures agrees with the
//    converged discrete values to 1e-6);
//  - the inextensible elastica (L / r = 1000, eigenstrain up to 7.12): at
//    the eigenstrains whose end shortening D / L0 = e0 / (1 + e0) is the
//    table's, the end rotation, the midspan deflection over the stress-free
//    length L0 = L (1 + e0), and the pins' thrust over the Euler load of the
//    stress-free column, P_E = pi^2 EI (1 + e0) / L0^2: the rods measure
//    curvature per length of the reference (unstretched) state, so a rod
//    grown by e0 bends with EI (1 + e0) per length of its stress-free state.
#include <common/run_scene_text.h>

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace
{
  using namespace rodnet;

  const double critical_eigenstrain = M_PI * M_PI * 1e-4; // I / A = 1e-4

  /// The row of @p summary at load factor @p lambda (landed on exactly).
  const std::vector<double> &
  row_at(const RunSummary &summary, const double lambda)
  {
    for (const std::vector<double> &row : summary.rows)
      if (std::abs(row[0] - lambda) < 1e-12)
        return row;
    throw std::runtime_error("no row at load factor " + std::to_string(lambda));
  }

  TEST(EigenstrainColumn, ExtensibleBifurcationAndAmplitudes)
  {
    // At N = 100 / 200: bifurcation -8.2e-5 / -2e-5 off e_cr (N^-2); the
    // deflections within 1.1e-4 of the table at N = 100.
    const RunSummary summary = rodnet::testing::run_scene_text(
      rodnet::testing::shipped_scene("eigenstrain_column.prm",
                                     {{"Segments", "200"}}),
      "eigenstrain_column_output");
    ASSERT_TRUE(summary.failure.empty()) << summary.failure;
    const double e0 = 10 * critical_eigenstrain; // at load factor 1
    EXPECT_NEAR(summary.critical_load_factor * e0 / critical_eigenstrain,
                1.0,
                1e-4);
    const std::size_t w = rodnet::testing::probe_column(summary, "w_mid");
    for (const auto &[ratio, expected] :
         {std::pair{2.0, 0.019979}, {5.0, 0.039862}, {10.0, 0.059556}})
      {
        const double eigenstrain = ratio * critical_eigenstrain;
        const double deflection =
          std::abs(row_at(summary, eigenstrain / e0)[w]) / (1 + eigenstrain);
        EXPECT_NEAR(deflection / expected, 1.0, 2e-4) << ratio;
      }
  }

  TEST(EigenstrainColumn, InextensibleElastica)
  {
    struct Row
    {
      double end_rotation, thrust, deflection, shortening;
    };
    const Row  rows[]      = {{20, 1.01540, 0.10971, 0.03027},
                              {60, 1.15172, 0.29660, 0.25898},
                              {90, 1.39320, 0.38138, 0.54305},
                              {120, 1.88480, 0.40159, 0.87684}};
    const auto eigenstrain = [](const Row &r) {
      return r.shortening / (1 - r.shortening);
    };
    const double       largest = eigenstrain(rows[3]);
    std::ostringstream outputs, value;
    outputs.precision(17);
    value.precision(17);
    for (int i = 0; i < 3; ++i)
      outputs << (i > 0 ? ", " : "") << eigenstrain(rows[i]) / largest;
    value << largest;
    // Buckling at load factor 1.4e-6: a first step far below it.
    const RunSummary summary = rodnet::testing::run_scene_text(
      rodnet::testing::shipped_scene(
        "eigenstrain_column.prm",
        {{"EA", "1e6"},
         {"Axial eigenstrain", value.str()},
         {"Output load factors", outputs.str()},
         // (and two entries the scene leaves at their defaults)
         {"Load factor range",
          "-1e-3, 1\n    set Initial step = 1e-7\n"
          "    set Minimum step = 1e-9"},
         {"Probes",
          "w_mid: position mid y; x1: position 1 x; y1: "
          "position 1 y; thrust: reaction start x"}}),
      "eigenstrain_column_inextensible");
    ASSERT_TRUE(summary.failure.empty()) << summary.failure;
    using rodnet::testing::probe_column;
    // At N = 100, against the table: end rotations within 0.026 deg,
    // deflections within 1.5e-4, thrusts within 8e-4 (at 120 deg; N^-2).
    for (const Row &r : rows)
      {
        const double e0  = eigenstrain(r);
        const auto  &row = row_at(summary, e0 / largest);
        const double L0  = 1 + e0;
        const double rotation =
          std::atan2(std::abs(row[probe_column(summary, "y1")]),
                     row[probe_column(summary, "x1")]) *
          180 / M_PI;
        EXPECT_NEAR(rotation, r.end_rotation, 0.05) << r.end_rotation;
        EXPECT_NEAR(std::abs(row[probe_column(summary, "w_mid")]) / L0 /
                      r.deflection,
                    1.0,
                    3e-4)
          << r.end_rotation;
        const double euler = M_PI * M_PI * (1 + e0) / (L0 * L0);
        EXPECT_NEAR(std::abs(row[probe_column(summary, "thrust")]) / euler /
                      r.thrust,
                    1.0,
                    1.5e-3)
          << r.end_rotation;
      }
  }
} // namespace
