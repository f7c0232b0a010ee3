// The over-curved ring (scenes/overcurved_ring.prm; Korner, Audoly &
// Bhattacharya 2021, section 5(b); Mouthuy et al. 2012): a closed
// inextensible ring with the Slinky's section whose natural curvature grows
// to O times that of the circle. The references are the closed forms of
// the linear stability analysis of doc/overcurved_ring.md (a p times
// covered ring loses stability in the mode of wavenumber n = j / p per turn
// where B C (n^2 - 1) + m (B + C) - m^2 = 0, m = A (1 - O / p)), and the
// statement that the triply covered ring is stress free at O = 3. N = 64
// (the shipped scene has 400; the runs here take a few seconds):
//  - the shipped path (Limit points = snap): from the stress-free circle,
//    the bifurcation at O_b (n = 2), the fold where the two-lobe branch
//    ends on the triply covered ring at O_d (j = 2), its opposite points
//    L / (3 pi) apart, and past it the triply covered ring up to O = 3,
//    every state there the triply covered polygon of the ring's segments
//    with its prestress; the supports carry no force along the whole path;
//  - the triply covered ring followed in O from 0 to 3.3: stable between
//    O_d and O_u (j = 4), its energy zero at O = 3.
#include <common/run_scene_text.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  // The scene's section: in-plane A = EI1, out-of-plane B = EI2, twist C.
  const double A = 50.0 / 12, B = 8.0 / 12, C = 2.048 / 2.82;
  const double L = 0.314;

  /// The over-curvature where a ring covered @p p times loses stability in
  /// the out-of-plane mode with @p j waves along its length, on the side of
  /// over-curvature (@p over) or under it: the root m of
  /// B C (n^2 - 1) + m (B + C) - m^2 = 0, n = j / p, with O = p (1 - m / A).
  double
  critical_over_curvature(const unsigned int p,
                          const unsigned int j,
                          const bool         over)
  {
    const double n2 = double(j * j) / (p * p);
    const double m =
      ((B + C) +
       (over ? -1 : 1) * std::sqrt((B + C) * (B + C) + 4 * B * C * (n2 - 1))) /
      2;
    return p * (1 - m / A);
  }

  /// Where run_ring() writes, one folder per process: the tests read
  /// probes.csv back, and other test runs on the machine write theirs.
  std::string
  ring_directory()
  {
    return (std::filesystem::temp_directory_path() /
            ("rodnet_overcurved_ring_" + std::to_string(::getpid())))
      .string();
  }

  /// scenes/overcurved_ring.prm at N = 64 (supports and probes moved to
  /// its vertices), with @p overrides, without VTU files and plots.
  RunSummary
  run_ring(const std::string &overrides)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/overcurved_ring.prm");
    std::stringstream text;
    text << file.rdbuf() << "\n"
         << "subsection Geometry\n  set Segments = 64\nend\n"
            "subsection Supports\n"
            "  set Fixed components = 0: x y z; 32: y z; 16: z; 48: z\n"
            "end\n"
            "subsection Output\n  set Write VTU = false\n"
            "  set Plot = false\n"
            "  set Probes = energy: energy; lowest: eigenvalue; "
            "d0: distance 0 32; d8: distance 8 40; d16: distance 16 48; "
            "d24: distance 24 56; r0x: reaction 0 x; r0y: reaction 0 y; "
            "r0z: reaction 0 z; r32y: reaction 32 y; r32z: reaction 32 z; "
            "r16z: reaction 16 z; r48z: reaction 48 z\n"
            "end\n"
         << overrides;
    return run_scene_text(text.str(), ring_directory());
  }

  /// The largest reaction of the supports over all rows of @p run.
  double
  largest_reaction(const RunSummary &run)
  {
    double largest = 0;
    for (const char *name :
         {"r0x", "r0y", "r0z", "r32y", "r32z", "r16z", "r48z"})
      for (const std::vector<double> &row : run.rows)
        largest = std::max(largest, std::abs(row[probe_column(run, name)]));
    return largest;
  }

  /// The least distance of the probed pairs of opposite vertices in @p row.
  double
  opposite_distance(const RunSummary &run, const std::vector<double> &row)
  {
    double d = std::numeric_limits<double>::max();
    for (const char *name : {"d0", "d8", "d16", "d24"})
      d = std::min(d, row[probe_column(run, name)]);
    return d;
  }

  // A support that held more than the free motions would carry forces of
  // the order of the internal ones, M / R ~ 1e3 N here. These stay at the
  // force residual's rounding floor, which the solver estimates at 1e-5 N
  // for this model (the multipliers' rows have the stiffness EI1 / l^3):
  // measured 7.4e-8 N at N = 64 (3.5e-7 N at N = 400), against the force
  // scale A / L^2 = 42 N.
  const double reaction_tolerance = 1e-7 * A / (L * L);

  /// The triply covered polygon of the ring's N = 64 segments (each of
  /// length l = 2 R sin(pi / N), R = L / (2 pi)): its curvature measure
  /// 2 sin(3 pi / N) / l differs from 6 pi / L by O(1/N^2), opposite
  /// vertices lie a diameter 2 / curvature apart, and at over-curvature O
  /// it is prestressed by EI1 (O 2 pi / L - curvature) along its length.
  struct TriplyCoveredPolygon
  {
    double n_segments = 64;
    double segment    = 2 * L / (2 * M_PI) * std::sin(M_PI / n_segments);
    double curvature  = 2 * std::sin(3 * M_PI / n_segments) / segment;
    double diameter   = 2 / curvature;

    double
    energy(const double o) const
    {
      const double mismatch = o * 2 * M_PI / L - curvature;
      return n_segments * segment / 2 * A * mismatch * mismatch;
    }
  };

  TEST(OvercurvedRing, BucklesAtObFoldsAtOdAndStaysTriplyCoveredToThree)
  {
    // As shipped (Limit points = snap): the whole path from O = 1 to 3.
    // Before the snapping, the two-lobe branch and its mirror image made a
    // closed loop between O_b and O_d, and the run stopped after its
    // points with exit code 2.
    const RunSummary run = run_ring("");
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    ASSERT_EQ(run.rows.back()[0], 2.) << "the path does not end at O = 3";

    // O_b: measured 1.167727 (formula 1.166920; 6.9e-4 relative,
    // O(1/N^2): 1.7e-5 at N = 400).
    const double o_b = critical_over_curvature(1, 2, true);
    std::cout << "O_b = " << 1 + run.critical_load_factor << ", formula " << o_b
              << std::endl;
    EXPECT_NEAR(1 + run.critical_load_factor, o_b, 1.5e-3 * o_b);

    // One jump, from the fold (the row before it) to the triply covered
    // ring just past it.
    const std::vector<double> jumps =
      probes_csv_column(ring_directory(), "jump");
    ASSERT_EQ(jumps.size(), run.rows.size());
    ASSERT_EQ(std::count(jumps.begin(), jumps.end(), 1.), 1);
    const std::size_t jump =
      std::find(jumps.begin(), jumps.end(), 1.) - jumps.begin();
    ASSERT_GT(jump, 1u);
    const std::vector<double> &fold = run.rows[jump - 1];
    // O_d: measured 2.822797 (formula 2.833233; -3.7e-3, O(1/N^2): the
    // fold lies at 2.8147, 2.8228, 2.83297 for N = 48, 64, 400, errors
    // in the ratio (N'/N)^2). The fold is the largest O of the path before
    // the jump, located by bisection.
    const double o_d = critical_over_curvature(3, 2, true);
    const double o   = 1 + fold[0];
    std::cout << std::setprecision(10) << "O_d = " << o << ", formula " << o_d
              << std::setprecision(6) << std::endl;
    EXPECT_NEAR(o, o_d, 5e-3 * o_d);
    for (std::size_t i = 0; i < jump; ++i)
      EXPECT_LE(run.rows[i][0], fold[0]) << "row " << i;
    // There the lobes have closed into the triply covered polygon,
    // prestressed. Measured: D 6e-10 and the energy 1.4e-8 off (the fold
    // located to 1e-4 of the step that passed it, where the largest O of
    // the followed loop was 3e-4 and 1.3e-4 off).
    const TriplyCoveredPolygon polygon;
    const double               d = opposite_distance(run, fold);
    std::cout << "D at the fold = " << d << ", triply covered polygon "
              << polygon.diameter << ", L / (3 pi) = " << L / (3 * M_PI)
              << "; relative errors of D " << d / polygon.diameter - 1
              << " and of the energy "
              << fold[probe_column(run, "energy")] / polygon.energy(o) - 1
              << std::endl;
    EXPECT_NEAR(d, polygon.diameter, 1e-6 * polygon.diameter);
    EXPECT_NEAR(fold[probe_column(run, "energy")],
                polygon.energy(o),
                1e-6 * polygon.energy(o));

    // Stable on the whole two-lobe branch (the lowest eigenvalue crosses
    // zero only at O_b and touches it at O_d).
    for (std::size_t i = 0; i + 1 < jump; ++i)
      if (run.rows[i][0] > run.critical_load_factor + 1e-6)
        EXPECT_GT(run.rows[i][probe_column(run, "lowest")], 0) << "row " << i;

    // From the jump (1e-3 past the fold in load factor) to O = 3, the
    // state is the triply covered polygon, stable, with the prestress of
    // its O: at O = 3 what the polygon's curvature measure leaves, 0.0033
    // of the prestress at O_d. Measured: D within 6e-10, the energy within
    // 1.0e-7 J (7.3 J at O_d, 0.024 J at O = 3).
    EXPECT_GT(run.rows[jump][0], fold[0]);
    EXPECT_LT(run.rows[jump][0] - fold[0], 2e-3 * fold[0]);
    double diameter_error = 0, energy_error = 0;
    for (std::size_t i = jump; i < run.rows.size(); ++i)
      {
        const std::vector<double> &row = run.rows[i];
        diameter_error =
          std::max(diameter_error,
                   std::abs(opposite_distance(run, row) / polygon.diameter -
                            1));
        energy_error = std::max(energy_error,
                                std::abs(row[probe_column(run, "energy")] -
                                         polygon.energy(1 + row[0])));
        EXPECT_NEAR(opposite_distance(run, row),
                    polygon.diameter,
                    1e-8 * polygon.diameter)
          << "row " << i;
        EXPECT_NEAR(row[probe_column(run, "energy")],
                    polygon.energy(1 + row[0]),
                    1e-6 * polygon.energy(o) + 1e-6 * polygon.energy(3))
          << "row " << i;
        EXPECT_GT(row[probe_column(run, "lowest")], 0) << "row " << i;
      }
    std::cout << "from the jump on: D within " << diameter_error
              << " of the polygon's, the energy within " << energy_error
              << " J of its prestress" << std::endl;
    std::cout << "energy at O = 3: "
              << run.rows.back()[probe_column(run, "energy")]
              << " J, triply covered polygon " << polygon.energy(3) << " J"
              << std::endl;

    // The supports hold only rigid motions and the slide: no force.
    std::cout << "largest reaction " << largest_reaction(run) << " N"
              << std::endl;
    EXPECT_LT(largest_reaction(run), reaction_tolerance);
  }

  TEST(OvercurvedRing, TriplyCoveredRingIsStressFreeAtThreeAndStableAround)
  {
    // The triply covered ring of radius L / (6 pi), bent from a straight
    // rod (O = lambda), followed from O = 0 to 3.3 on its branch.
    std::ostringstream triple;
    triple.precision(17);
    triple << "subsection Geometry\n  set Radius = " << L / (6 * M_PI)
           << "\n  set Turns = 3\n  set Natural shape = straight\nend\n"
              "subsection Material\n  subsection linear elastic\n"
              "    set Natural curvature 1 = "
           << 2 * M_PI / L << "\n  end\nend\n";
    const RunSummary run =
      run_ring(triple.str() + "subsection Solver\n  subsection Continuation\n"
                              "    set Load factor range = -0.5, 3.3\n"
                              "    set Output load factors = 3\n"
                              "    set Switch branches = false\n  end\nend\n");
    ASSERT_TRUE(run.failure.empty()) << run.failure;

    // Where the lowest eigenvalue crosses zero, interpolated linearly
    // between the two rows around the crossing (one of them is the stable
    // side of the located bifurcation, its eigenvalue below 1e-6).
    const std::size_t   lowest = probe_column(run, "lowest");
    std::vector<double> up, down;
    for (std::size_t i = 1; i < run.rows.size(); ++i)
      {
        const double l0 = run.rows[i - 1][lowest], l1 = run.rows[i][lowest];
        const double crossing =
          run.rows[i - 1][0] +
          (run.rows[i][0] - run.rows[i - 1][0]) * l0 / (l0 - l1);
        if (l0 <= 0 && l1 > 0)
          up.push_back(crossing);
        if (l0 > 0 && l1 <= 0)
          down.push_back(crossing);
      }
    ASSERT_EQ(up.size(), 1u);
    ASSERT_EQ(down.size(), 1u);
    // Stable between O_d (j = 2) and O_u (j = 4); measured 2.83189 and
    // 3.17070 (formulas 2.833233 and 3.166881: -4.7e-4 and 1.2e-3;
    // 2.833199 and 3.166977 at N = 400).
    const double o_d = critical_over_curvature(3, 2, true);
    const double o_u = critical_over_curvature(3, 4, true);
    std::cout << "triply covered ring stable from " << up[0]
              << " (O_d = " << o_d << ") to " << down[0] << " (O_u = " << o_u
              << ")" << std::endl;
    EXPECT_NEAR(up[0], o_d, 1.5e-3 * o_d);
    EXPECT_NEAR(down[0], o_u, 3e-3 * o_u);

    // At O = 3 the natural curvature is the ring's: no energy (measured
    // 7e-27 J against the energy scale B / L = 2.1 J; the polygon's
    // curvature measure 2 sin(theta / 2) / l is exactly 1 / R).
    for (const std::vector<double> &row : run.rows)
      if (row[0] == 3)
        {
          const double energy = row[probe_column(run, "energy")];
          std::cout << "energy at O = 3: " << energy << " J" << std::endl;
          EXPECT_LT(std::abs(energy), 1e-9 * B / L);
          EXPECT_NEAR(opposite_distance(run, row), L / (3 * M_PI), 1e-9 * L);
        }
    EXPECT_LT(largest_reaction(run), reaction_tolerance);
  }
} // namespace
