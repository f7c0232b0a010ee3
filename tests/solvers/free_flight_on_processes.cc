// Free flight on several processes: the unsupported right-angle frame of
// the free-flight validation (tests/common/free_frame.h) through its pulse
// and tumbling after it, under the midpoint rule. Its rigid-motion split
// (RigidMotionSplit) sums the parts' masses, centres, resultants and Gram
// matrices over the processes, its gyroscopic coupling adds rows of other
// processes, and its junction carries a moment: the states of the same
// flight on one process (MPI_COMM_SELF) to 1e-9 of their size, in the same
// Newton iterations. Runs on 1, 2 and 3 processes (RODNET_MPI_TESTS).
#include <deal.II/base/mpi.h>

#include <common/free_frame.h>
#include <solvers/time/time_integrator.h>

#include <gtest/gtest.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  /// The frame of 3 segments per leg flown by the midpoint rule to t = 3
  /// in steps of 0.2, its DoFs shared by the processes of @p communicator.
  struct Flight
  {
    explicit Flight(const MPI_Comm communicator)
        : frame(free_frame(3, communicator))
        , u(frame.model->create_vector())
        , v(frame.model->create_vector())
    {
      TimeIntegrator::Parameters p;
      p.integrator         = "midpoint";
      p.time_step          = 0.2;
      p.end_time           = 3;
      p.load_factor        = triangle_pulse;
      p.relative_tolerance = 1e-10;
      p.progress_interval  = 0;
      TimeIntegrator integrator(*frame.model,
                                std::vector<RodInertia>(2, frame_inertia),
                                p,
                                nullptr);
      integrator.run(u,
                     v,
                     [&](const TimeIntegrator::StepInfo &info,
                         const VectorType &,
                         const VectorType &) {
                       iterations.push_back(info.iterations);
                     });
    }

    FreeFrame                 frame;
    VectorType                u, v;
    std::vector<unsigned int> iterations;
  };

  TEST(FreeFlightOnProcesses, FliesAsOneProcess)
  {
    const Flight one(MPI_COMM_SELF);
    const Flight many(MPI_COMM_WORLD);
    ASSERT_EQ(many.iterations.size(), one.iterations.size());
    EXPECT_EQ(many.iterations, one.iterations);
    // The frame has moved and turned by a good part of its size.
    const double position_scale = one.u.linfty_norm(),
                 velocity_scale = one.v.linfty_norm();
    EXPECT_GT(position_scale, 1.0);
    for (const global_dof_index i : many.frame.model->locally_owned_dofs())
      {
        EXPECT_NEAR(many.u[i], one.u[i], 1e-9 * position_scale) << "DoF " << i;
        EXPECT_NEAR(many.v[i], one.v[i], 1e-9 * velocity_scale) << "DoF " << i;
      }
  }
} // namespace
