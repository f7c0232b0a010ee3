// Bad input gives one clear error naming the entry and a non-zero exit of
// rodnet-run, never a crash; a solver failure keeps every earlier output.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>

namespace
{
  struct Outcome
  {
    int         exit_code;
    std::string output;
  };

  /// Writes @p scene to a file and runs rodnet-run on it.
  Outcome
  run_driver(const std::string &name, const std::string &scene)
  {
    const std::string path = name + ".prm";
    std::ofstream(path) << scene;
    const std::string command = std::string(RODNET_BINARY_DIR) +
                                "/rodnet-run " + path + " --output out_" +
                                name + " 2>&1";
    FILE *pipe = popen(command.c_str(), "r");
    EXPECT_NE(pipe, nullptr);
    std::string           output;
    std::array<char, 512> buffer;
    while (fgets(buffer.data(), buffer.size(), pipe) != nullptr)
      output += buffer.data();
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
  }

  const std::string material = "subsection Material\n"
                               "  subsection linear elastic\n"
                               "    set Stiffness input = direct\n"
                               "    set EA = 1e4\n"
                               "    set EI1 = 1\n"
                               "    set EI2 = 1\n"
                               "    set GJ = 1\n"
                               "  end\n"
                               "end\n";

  /// Expects exit code 1 and a message that contains @p needle.
  void
  expect_input_error(const std::string &name,
                     const std::string &scene,
                     const std::string &needle)
  {
    const Outcome o = run_driver(name, scene);
    EXPECT_EQ(o.exit_code, 1) << o.output;
    EXPECT_NE(o.output.find(needle), std::string::npos)
      << "message lacks \"" << needle << "\":\n"
      << o.output;
    EXPECT_EQ(o.output.find("Aborting"), std::string::npos) << o.output;
  }

  TEST(BadScene, UnknownEntry)
  {
    expect_input_error("unknown_entry",
                       "subsection Geometry\n  set Segmnts = 10\nend\n",
                       "Segmnts");
  }

  TEST(BadScene, ValueOutOfRange)
  {
    expect_input_error("out_of_range",
                       "subsection Geometry\n  set Segments = 0\nend\n",
                       "Segments");
  }

  TEST(BadScene, UnknownMaterial)
  {
    expect_input_error("unknown_material",
                       "subsection Material\n  set Model = steel\nend\n",
                       "Model");
  }

  TEST(BadScene, UnknownKernel)
  {
    expect_input_error("unknown_kernel",
                       "subsection Geometry\n  set Hinge kernel = fancy\nend\n",
                       "Hinge kernel");
  }

  TEST(BadScene, ZeroLengthSegment)
  {
    expect_input_error("zero_length",
                       "subsection Geometry\n"
                       "  set Generator = polyline\n"
                       "  set Points = 0,0,0; 1,0,0; 1,0,0; 2,0,0\n"
                       "  set Segments = 2\n"
                       "end\n" +
                         material,
                       "zero-length segment");
  }

  TEST(BadScene, CoincidentVertices)
  {
    expect_input_error("coincident",
                       "subsection Geometry\n"
                       "  set Generator = polyline\n"
                       "  set Points = 0,0,0; 1,0,0; 1,1,0; 0,0,0; 0,-1,0\n"
                       "  set Segments = 1\n"
                       "end\n" +
                         material,
                       "coincide");
  }

  TEST(BadScene, NegativeStiffness)
  {
    expect_input_error("negative_stiffness",
                       "subsection Material\n"
                       "  subsection linear elastic\n"
                       "    set Stiffness input = direct\n"
                       "    set EA = -1\n"
                       "  end\n"
                       "end\n",
                       "EA");
  }

  TEST(BadScene, MissingFile)
  {
    const std::string command =
      std::string(RODNET_BINARY_DIR) +
      "/rodnet-run no_such_scene.prm > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 1);
  }

  // What the bending-active element of dynamic relaxation cannot represent
  // is refused before any step, naming it.
  const std::string dynamic_relaxation =
    "subsection Solver\n  set Method = dynamic relaxation\nend\n";

  TEST(BadScene, DynamicRelaxationHasNoEigenvalue)
  {
    expect_input_error("dr_eigenvalue",
                       material + dynamic_relaxation +
                         "subsection Supports\n  set Clamped ends = start\n"
                         "end\n"
                         "subsection Output\n  set Probes = mu: eigenvalue\n"
                         "end\n",
                       "eigenvalue");
  }

  TEST(BadScene, DynamicRelaxationHasNoNaturalCurvature)
  {
    expect_input_error("dr_natural_curvature",
                       material +
                         "subsection Material\n"
                         "  subsection linear elastic\n"
                         "    set Natural curvature 1 = 2\n"
                         "  end\n"
                         "end\n" +
                         dynamic_relaxation,
                       "natural shape");
  }

  TEST(BadScene, DynamicRelaxationNormalInThePlane)
  {
    // The element stores n_z >= 0 and cannot take a normal in the xy plane:
    // a rod along x with d1 = e_y.
    expect_input_error("dr_horizontal_normal",
                       "subsection Geometry\n  set Director d1 = 0, 1, 0\n"
                       "end\n" +
                         material + dynamic_relaxation,
                       "rod 0");
  }

  TEST(BadScene, ViscoelasticMaterialNeedsTimeStepping)
  {
    // Until the assembly evolves internal variables, a history-dependent
    // material is refused instead of solved with its instantaneous moduli.
    expect_input_error("viscoelastic",
                       "subsection Material\n"
                       "  set Model = standard linear solid\n"
                       "  subsection standard linear solid\n"
                       "    set Stiffness input = direct\n"
                       "    set EA = 1e4\n"
                       "    set EI1 = 1\n"
                       "    set EI2 = 1\n"
                       "    set GJ = 1\n"
                       "    set Modulus ratio E2/E1 = 0.3\n"
                       "    set Relaxation time = 1\n"
                       "  end\n"
                       "end\n",
                       "internal variables");
  }

  TEST(BadScene, SolverFailureKeepsEarlierSteps)
  {
    // The elastica with four Newton iterations per step, no predictor and
    // no room to cut steps: the nearly linear pre-buckling steps converge,
    // the step across the bifurcation cannot, and the run stops with exit
    // code 2. Every
    // converged step is in probes.csv and has its VTU file.
    const Outcome o =
      run_driver("solver_failure",
                 "subsection Geometry\n"
                 "  set Segments = 50\n"
                 "  set Director d1 = 0, 0, 1\n"
                 "end\n" +
                   material +
                   "subsection Supports\n  set Clamped ends = start\nend\n"
                   "subsection Loads\n"
                   "  set Steps = 10\n"
                   "  set Point forces = end: -10, 1e-3, 0\n"
                   "end\n"
                   "subsection Solver\n"
                   "  set Max iterations = 4\n"
                   "  set Predictor = false\n"
                   "  set Minimum step fraction = 0.5\n"
                   "end\n"
                   "subsection Output\n"
                   "  set Probes = tip_y: position end y\n"
                   "end\n");
    ASSERT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find("solver stopped"), std::string::npos) << o.output;
    std::ifstream csv("out_solver_failure/probes.csv");
    std::string   line;
    unsigned int  rows = 0;
    std::getline(csv, line);
    EXPECT_EQ(line, "step,load_factor,tip_y");
    while (std::getline(csv, line))
      {
        ++rows;
        char name[64];
        std::snprintf(name,
                      sizeof(name),
                      "out_solver_failure/solution-%05u.vtu",
                      rows);
        EXPECT_TRUE(std::filesystem::exists(name)) << name;
      }
    EXPECT_GE(rows, 1u);
    EXPECT_LT(rows, 10u);
  }
} // namespace
