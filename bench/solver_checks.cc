// What the checks of issue 11 cost against a Newton iteration, on a large
// gridshell: the square lattice of scenes/gridshell.prm with n x n cells
// (8 segments per lath, welded), its two edges pushed together by a tenth of
// the span and a small uplift, solved to the first load step. At the
// converged state the program times, median (min-max) of the repeats:
//   residual / tangent: RodModel::assemble with the residual or the tangent,
//   KLU: the factorization and solve of one Newton iteration,
//   load scale:  ResidualCriterion::load_scale (two residual assemblies),
//   noise:       ResidualCriterion::roundoff_noise (three),
//   equilibrium: check_equilibrium (tangent assembly, sparse LDL^T, inertia,
//                Newton correction),
//   strains:     StrainMonitor::evaluate,
//   free motions: describe_free_motions (once per run),
// and the wall time of the first load step with all the checks.
//
// Usage: solver_checks [--cells n] [--repeats n] (defaults 12 and 5).
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <io/scene.h>
#include <solvers/checks/equilibrium_check.h>
#include <solvers/checks/free_motions.h>
#include <solvers/statics/static_solver.h>

#include <bench/gridshell_scene.h>
#include <bench/options.h>
#include <bench/timing.h>
#include <iostream>
#include <sstream>
#include <string>

using namespace rodnet;

int
main(int argc, char **argv)
{
  rodnet::MPISession mpi(argc, argv);
  unsigned int       cells = 12, repeats = 5;
  bench::parse(argc,
               argv,
               {bench::number("--cells", cells, 1),
                bench::number("--repeats", repeats, 1)});

  const Scene               scene = bench::gridshell(cells);
  std::unique_ptr<RodModel> model = scene.build_model();
  std::printf("gridshell of %u x %u cells: %u DoFs\n",
              cells,
              cells,
              static_cast<unsigned int>(model->layout().n_dofs()));

  // The first load step, with every check.
  StaticSolver::Parameters parameters = scene.solver;
  parameters.n_steps                  = 40;
  VectorType                   u;
  const StaticSolver::StepInfo first =
    bench::first_load_step(*model, parameters, u);
  const double load_factor = first.load_factor;
  std::printf("first load step (load factor %g): %u iterations, %.3g s\n",
              load_factor,
              first.iterations,
              first.wall_time);

  VectorType r = model->create_vector();
  MatrixType tangent;
  model->initialize_matrix(tangent);
  const ResidualCriterion criterion(*model);
  const StrainMonitor     strains(*model, StrainLimits());
  bench::print_time("residual", bench::time_repeats(repeats, [&] {
                      model->assemble(u, load_factor, &r, nullptr);
                    }));
  bench::print_time("tangent", bench::time_repeats(repeats, [&] {
                      model->assemble(u, load_factor, nullptr, &tangent);
                    }));
  bench::print_time("KLU", bench::time_repeats(repeats, [&] {
                      VectorType            du = model->create_vector();
                      dealii::SolverControl control(1, 0);
                      dealii::TrilinosWrappers::SolverDirect direct(control);
                      direct.solve(tangent, du, r);
                    }));
  bench::print_time("load scale", bench::time_repeats(repeats, [&] {
                      criterion.load_scale(u, load_factor);
                    }));
  bench::print_time("noise", bench::time_repeats(repeats, [&] {
                      criterion.roundoff_noise(u, load_factor);
                    }));
  JudgedResult limited;
  limited.rounding_limited = true;
  limited.noise            = criterion.roundoff_noise(u, load_factor);
  limited.scale            = criterion.load_scale(u, load_factor);
  bench::print_time("equilibrium", bench::time_repeats(repeats, [&] {
                      check_equilibrium(*model,
                                        criterion,
                                        u,
                                        load_factor,
                                        tangent,
                                        limited,
                                        1e-6);
                    }));
  bench::print_time("strains",
                    bench::time_repeats(repeats, [&] { strains.evaluate(u); }));
  bench::print_time("free motions", bench::time_repeats(repeats, [&] {
                      describe_free_motions(*model, u);
                    }));
}
