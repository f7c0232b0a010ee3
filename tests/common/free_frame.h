// The free-flying right-angle frame of the free-flight validation
// (tests/validation/free_flight.cc) and of the stability map of the
// integrators (bench/frame_stability_map.cc): Simo & Vu-Quoc's right-angle
// frame (CMAME 66, 1988) without its clamp, two legs of L = 10 welded at a
// right angle, EA = 1e6, EI1 = EI2 = GJ = 1e3, rho A = 1 and the twist
// inertia of the same slender section, rho (I1 + I2) = 2 rho A EI / EA =
// 2e-3; a force (0, 0, 40) at the tip and a moment 200 about (1, 1, 0) /
// sqrt 2 at the corner, both with the triangular time history
// triangle_pulse() (0 -> 1 -> 0 over 0 <= t <= 2, integral 1).
#ifndef RODNET_TESTS_COMMON_FREE_FRAME_H
#define RODNET_TESTS_COMMON_FREE_FRAME_H

#include <core/mass_matrix.h>
#include <core/rod_model.h>
#include <geometry/network_generators.h>
#include <geometry/rod_graph.h>
#include <materials/linear_elastic_rod.h>

#include <memory>
#include <vector>

namespace rodnet
{
  namespace testing
  {
    inline const double       frame_leg = 10;
    inline const RodStiffness frame_stiffness{1e6, 1e3, 1e3, 1e3};
    inline const RodInertia   frame_inertia{1, 2e-3};
    inline const Vector3      frame_tip_force(0, 0, 40);
    inline const double       frame_pulse_end = 2;

    /// The pulse's load factor: its integral over time is 1.
    inline double
    triangle_pulse(const double t)
    {
      return t <= 0              ? 0.0 :
             t < 1               ? t :
             t < frame_pulse_end ? frame_pulse_end - t :
                                   0.0;
    }

    struct FreeFrame
    {
      std::unique_ptr<RodModel> model;
      /// Triangulation vertices of the corner and the tip.
      unsigned int corner, tip;
    };

    /// The frame, @p n segments per leg, loaded at load factor 1, its
    /// DoFs shared by the processes of @p communicator.
    inline FreeFrame
    free_frame(const unsigned int n,
               const MPI_Comm     communicator = MPI_COMM_WORLD)
    {
      RodGraph graph = network_generators::right_angle_frame(frame_leg);
      graph.nodes[graph.node_index("clamp")].kind.reset();
      BuiltNetwork       built  = build_rod_network(graph, n, "simple");
      const unsigned int n_rods = built.network->rods().size();
      FreeFrame          frame;
      frame.model = std::make_unique<RodModel>(
        std::move(built.network),
        std::vector<std::shared_ptr<const RodMaterial>>(
          n_rods,
          std::make_shared<LinearElasticRod>(frame_stiffness)),
        GhostSpin::exact,
        communicator);
      frame.corner = built.node_vertex[graph.node_index("corner")];
      frame.tip    = built.node_vertex[graph.node_index("tip")];
      frame.model->add_point_force(frame.tip, frame_tip_force);
      frame.model->add_moment(built.node_junction[graph.node_index("corner")],
                              Vector3(1, 1, 0).normalized(),
                              200);
      frame.model->finalize();
      return frame;
    }
  } // namespace testing
} // namespace rodnet

#endif
