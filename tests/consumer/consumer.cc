// An outside program that uses the installed rodnet package: a clamped
// cantilever under a small tip load, checked against P L^3 / (3 EI).
#include <base/mpi_session.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/statics/static_solver.h>

#include <cmath>
#include <iostream>

int
main(int argc, char **argv)
{
  using namespace rodnet;
  MPISession mpi(argc, argv);

  auto network = std::make_unique<RodNetwork>();
  network->add_rod(
    generators::straight(Vector3(0, 0, 0), Vector3(1, 0, 0), 50, true),
    false,
    Vector3::UnitY(),
    "simple");
  RodModel model(std::move(network),
                 {std::make_shared<LinearElasticRod>(
                   RodStiffness{1e6, 1.0, 1.0, 1.0})});
  model.clamp_end("clamp", 0, true);
  const unsigned int tip = model.network().rods()[0].vertices.back();
  model.add_point_force(tip, Vector3(0, 0, -1e-4));
  model.finalize();

  VectorType               u = model.create_vector();
  StaticSolver::Parameters parameters;
  parameters.n_steps = 1;
  StaticSolver(model, parameters).run(u, [](const auto &, const auto &) {});

  const double deflection = -model.configuration().position(u, tip)[2];
  const double exact      = 1e-4 / 3;
  std::cout << "tip deflection " << deflection << ", P L^3/(3 EI) " << exact
            << std::endl;
  return std::abs(deflection - exact) < 0.005 * exact ? 0 : 1;
}
