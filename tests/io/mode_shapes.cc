// Output/Mode shapes: the lowest eigenpairs of the last equilibrium's
// tangent in modes.csv and modes-NNNNN.vtu. A cantilever's lowest two
// eigenvalues against the Euler-Bernoulli beam's: in the DoFs of the vertex
// positions, the tangent is the beam operator EI d^4/dx^4 times the
// segment length h (the energy sums EI kappa^2 h, the Euclidean norm of a
// mode sums w_i^2 ~ int w^2 / h), so lambda_k = h EI (beta_k L)^4 / L^4
// with beta_1 L = 1.8751041 (clamped-free).
#include <common/run_scene_text.h>
#include <common/scene_text.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace rodnet;

  /// A unit cantilever along x of @p n segments, EI1 = 1, EI2 = 2, stiff
  /// in torsion and stretching, unloaded, with Output/Mode shapes = 3.
  std::string
  cantilever_with_modes(const unsigned int n, const std::string &method)
  {
    return "subsection Geometry\n  set Segments = " + std::to_string(n) +
           "\n  set Director d1 = 0, 0, 1\nend\n" +
           rodnet::testing::direct_material(1e6, 1, 2, 100) +
           "subsection Supports\n  set Clamped ends = start\nend\n"
           "subsection Solver\n  set Method = " +
           method +
           "\nend\n"
           "subsection Output\n  set Mode shapes = 3\n  set Plot = false\n"
           "end\n";
  }

  /// The eigenvalues of modes.csv in @p directory.
  std::vector<double>
  read_modes(const std::string &directory)
  {
    std::ifstream       csv(directory + "/modes.csv");
    std::string         line;
    std::vector<double> values;
    std::getline(csv, line);
    EXPECT_EQ(line, "mode,eigenvalue");
    while (std::getline(csv, line))
      values.push_back(std::stod(line.substr(line.find(',') + 1)));
    return values;
  }

  TEST(ModeShapes, CantileverEigenvaluesAreTheBeamsTimesTheSegment)
  {
    const double beta4 = std::pow(1.8751041, 4);
    // The discrete values converge as n^-2 (1.1e-4 at n = 100, 1e-5 at
    // 400); tolerance 10 / n^2.
    for (const unsigned int n : {100u, 400u})
      {
        const std::string directory = "mode_shapes_output_" + std::to_string(n);
        const RunSummary  summary =
          rodnet::testing::run_scene_text(cantilever_with_modes(n, "newton"),
                                          directory);
        ASSERT_TRUE(summary.failure.empty()) << summary.failure;
        const std::vector<double> values = read_modes(directory);
        ASSERT_EQ(values.size(), 3u);
        const double h = 1.0 / n;
        EXPECT_NEAR(values[0] / (h * beta4), 1.0, 10.0 / (n * n));
        EXPECT_NEAR(values[1] / (h * 2 * beta4), 1.0, 10.0 / (n * n));
        std::cout << n << " segments: lambda_1 / (h EI beta^4) = "
                  << values[0] / (h * beta4) << ", lambda_2 / (h 2 EI "
                  << "beta^4) = " << values[1] / (h * 2 * beta4) << std::endl;
        // One VTU per mode, listed in modes.pvd.
        for (const std::string file :
             {"modes.pvd", "modes-00001.vtu", "modes-00003.vtu"})
          EXPECT_TRUE(std::filesystem::exists(directory + "/" + file)) << file;
        EXPECT_NE(std::find(summary.outputs.begin(),
                            summary.outputs.end(),
                            "modes.csv"),
                  summary.outputs.end());
      }
  }

  TEST(ModeShapes, EigenvalueProbeAlongAContinuation)
  {
    // The cantilever compressed by a tip force P = lambda (EI1 = 1,
    // P_cr = pi^2 / 4) and followed by continuation: the lowest eigenvalue
    // starts at h EI beta_1^4 (unloaded), falls to zero at the located
    // bifurcation (the located point and the branch switch's start, within
    // 1e-6 of it), and is positive again on the buckled branch.
    const unsigned int n     = 100;
    std::string        scene = cantilever_with_modes(n, "continuation");
    scene += "subsection Loads\n  set Point forces = end: -1, 0, 0\nend\n"
             "subsection Solver\n  subsection Continuation\n"
             "    set Load factor range = -1, 3\n  end\nend\n"
             "subsection Output\n  set Probes = mu: eigenvalue\nend\n";
    const RunSummary summary =
      rodnet::testing::run_scene_text(scene, "mode_shapes_probe");
    ASSERT_TRUE(summary.failure.empty()) << summary.failure;
    const std::size_t mu       = rodnet::testing::probe_column(summary, "mu");
    const double      unloaded = std::pow(1.8751041, 4) / n;
    EXPECT_NEAR(summary.rows.front()[mu] / unloaded, 1.0, 1e-3);
    // The clamp holds the first segment: the free length is L - h/2, and
    // P_cr = pi^2 EI / (4 (L - h/2)^2).
    const double free_length = 1 - 0.5 / n;
    ASSERT_NEAR(summary.critical_load_factor,
                M_PI * M_PI / (4 * free_length * free_length),
                1e-3);
    for (const std::vector<double> &row : summary.rows)
      if (std::abs(row[0] - summary.critical_load_factor) < 1e-6)
        EXPECT_LT(std::abs(row[mu]), 1e-4 * unloaded);
      else
        EXPECT_GT(row[mu], 0) << "load factor " << row[0];
  }

  TEST(ModeShapes, RefusedWithoutATangent)
  {
    try
      {
        rodnet::testing::run_scene_text(
          cantilever_with_modes(10, "dynamic relaxation"),
          "mode_shapes_refused");
        FAIL() << "no error";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("Output/Mode shapes"),
                  std::string::npos)
          << e.what();
      }
  }
} // namespace
