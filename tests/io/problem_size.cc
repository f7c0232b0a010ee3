// The size a scene reports before its model is built is the size of the
// model built: DoFs against the DoF layout, for rods and networks.
#include <deal.II/base/parameter_handler.h>

#include <common/scene_text.h>
#include <io/scene.h>
#include <io/scene_runner.h>

#include <fstream>
#include <gtest/gtest.h>
#include <string>

namespace
{
  using namespace rodnet;

  std::unique_ptr<Scene>
  scene_of(const std::string &geometry, const std::string &more = "")
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n" + geometry + "end\n" +
                                rodnet::testing::direct_material() + more);
    return std::make_unique<Scene>(prm);
  }

  void
  expect_size_of_model(const std::string &geometry)
  {
    const auto   scene = scene_of(geometry);
    const auto   model = scene->build_model();
    const double rods  = model->network().rods().size();
    EXPECT_EQ(scene->size().rods, rods) << geometry;
    EXPECT_EQ(scene->size().dofs(), model->layout().n_dofs()) << geometry;
  }

  TEST(ProblemSize, StraightRod)
  {
    expect_size_of_model("  set Segments = 17\n");
  }

  TEST(ProblemSize, Ring)
  {
    expect_size_of_model("  set Generator = ring\n  set Segments = 12\n"
                         "  set Director d1 = 0, 0, 1\n");
  }

  TEST(ProblemSize, Polyline)
  {
    expect_size_of_model("  set Generator = polyline\n"
                         "  set Points = 0,0,0; 1,0,0; 1,1,0\n"
                         "  set Segments = 5\n"
                         "  set Director d1 = 0, 0, 1\n");
  }

  TEST(ProblemSize, Frame)
  {
    expect_size_of_model("  set Generator = frame\n  set Segments = 6\n");
  }

  TEST(ProblemSize, SquareLattice)
  {
    expect_size_of_model("  set Generator = square lattice\n"
                         "  set Cells = 3, 2\n"
                         "  set Segments = 3\n");
  }

  /// The peak resident memory of this process so far (VmHWM), bytes.
  double
  peak_memory()
  {
    std::ifstream status("/proc/self/status");
    std::string   key;
    double        kilobytes = 0;
    while (status >> key)
      if (key == "VmHWM:" && status >> kilobytes)
        return kilobytes * 1024;
    return 0;
  }

  TEST(ProblemSize, MemoryEstimateOfANewtonRun)
  {
    // 30000 segments (120003 DoFs), one Newton step: the peak memory grows
    // by the estimate per DoF within 50% (measured 1.6 kB per DoF on
    // 4e5 and 2e6 DoFs, 1 kB of it the stability check's LDL^T; the
    // estimate is 1.65 kB).
    const auto scene =
      scene_of("  set Segments = 30000\n  set End = 30, 0, 0\n",
               "subsection Supports\n  set Clamped ends = start\nend\n"
               "subsection Loads\n  set Steps = 1\n"
               "  set Point forces = end: 0, 1e-6, 0\nend\n"
               "subsection Output\n  set Write VTU = false\n"
               "  set Plot = false\nend\n");
#ifdef DEBUG
    GTEST_SKIP() << "the estimate is that of Release builds; deal.II's Debug "
                    "library takes a minute for this run";
#endif
    const double before = peak_memory();
    ASSERT_GT(before, 0) << "no VmHWM in /proc/self/status";
    const RunSummary run = run_scene(*scene, "problem_size_memory", nullptr);
    ASSERT_TRUE(run.failure.empty()) << run.failure;
    const double growth   = peak_memory() - before;
    const double estimate = scene->size().bytes_per_dof * scene->size().dofs();
    std::cout << "peak memory growth " << growth / scene->size().dofs()
              << " bytes per DoF, estimate " << scene->size().bytes_per_dof
              << std::endl;
    EXPECT_GT(growth, 0.5 * estimate);
    EXPECT_LT(growth, 1.5 * estimate);
  }
} // namespace
