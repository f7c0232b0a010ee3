// P1 of ../shared/BENCHMARKS.md, the gravity cantilever with large
// deflection, as the benchmark programs build it for either rod model:
// p1_gravity_cantilever (Newton on discrete elastic rods),
// p1_dynamic_relaxation (the bending-active element, dynamic relaxation) and
// dr_vs_newton (both, for its stability map).
//
// A straight rod from (0,0,0) to (1,0,0), circular section r = 5e-3,
// E = 1e8, nu = 0.5 (G = E/3), rho = 1000, under its weight in g = -9.81 e_z
// (q = rho A g = 0.770476 N/m, EI = 0.0490874, q L^3/EI = 15.696), clamped
// at x = 0. Newton's rod is clamped by its first two vertices, which sit at
// -l/2 and l/2 (generators::straight with the midpoint clamp), so that the
// free length is 1; the element of dynamic relaxation is clamped at one node
// (an anchor holds its frame), so its rod starts at x = 0.
//
// The reference tip is that of the inextensible elastica; both rods have
// EA = 7854 N, which puts their tips ~3.4e-5 (in z) away from it whatever the
// mesh (see doc/performance.md, P1).
#ifndef RODNET_BENCH_P1_PROBLEM_H
#define RODNET_BENCH_P1_PROBLEM_H

#include <core/dr_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <io/scene.h>
#include <materials/cross_section.h>
#include <materials/linear_elastic_rod.h>

#include <memory>

namespace rodnet
{
  namespace bench
  {
    namespace p1
    {
      constexpr double x_exact = 0.5157790;
      constexpr double z_exact = -0.7938299;
      constexpr double radius  = 5e-3;
      constexpr double E       = 1e8;
      constexpr double nu      = 0.5;
      constexpr double density = 1000;
      constexpr double g       = -9.81;

      /// EA, EI1 = EI2, GJ of the circular section; EA times @p ea_scale.
      inline RodStiffness
      stiffness(const double ea_scale = 1)
      {
        RodStiffness s =
          stiffness_from_section(E, E / (2 * (1 + nu)), circle_section(radius));
        s.EA *= ea_scale;
        return s;
      }

      /// Mass per unit length rho A (kg/m).
      inline double
      mass_per_length()
      {
        return density * circle_section(radius).area;
      }

      /// The weight per unit length, rho A g e_z (N/m).
      inline Vector3
      weight_per_length()
      {
        return Vector3(0, 0, mass_per_length() * g);
      }

      /// The rod of @p n_vertices vertices: from -l/2 for Newton's two-vertex
      /// clamp (@p midpoint_clamp), from 0 otherwise, to (1,0,0).
      inline std::unique_ptr<RodNetwork>
      network(const unsigned int n_vertices,
              const bool         midpoint_clamp,
              const Vector3     &director_hint)
      {
        auto network = std::make_unique<RodNetwork>();
        network->add_rod(generators::straight(Vector3::Zero(),
                                              Vector3::UnitX(),
                                              n_vertices - 1,
                                              midpoint_clamp),
                         false,
                         director_hint,
                         "simple");
        network->create_triangulation();
        return network;
      }

      /// P1 for Newton: the clamped, loaded and finalized RodModel.
      inline std::unique_ptr<RodModel>
      rod_model(const unsigned int n_vertices, const double ea_scale = 1)
      {
        auto model = std::make_unique<RodModel>(
          network(n_vertices, true, Vector3::UnitY()),
          std::vector<std::shared_ptr<const RodMaterial>>{
            std::make_shared<LinearElasticRod>(stiffness(ea_scale))});
        model->clamp_end("clamp", 0, true);
        model->add_distributed_force(0, weight_per_length());
        model->finalize();
        return model;
      }

      /// P1 for dynamic relaxation: the element's normals must stay off the
      /// xy plane, so they start along e_z (the plane of bending; the
      /// section is round, so the choice does not change the answer).
      inline std::unique_ptr<DrModel>
      dr_model(const unsigned int n_vertices)
      {
        auto model = std::make_unique<DrModel>(
          network(n_vertices, false, Vector3::UnitZ()),
          std::vector<RodStiffness>{stiffness()});
        model->clamp_end("clamp", 0, true);
        // The weight: mass per length times gravity.
        model->add_distributed_force(0, mass_per_length() * Vector3(0, 0, g));
        model->finalize();
        return model;
      }

      /// The vertex at the free end.
      template <class Model>
      unsigned int
      tip(const Model &model)
      {
        return model.network().rods()[0].vertices.back();
      }
    } // namespace p1
  }   // namespace bench
} // namespace rodnet

#endif
