// The cost of the k lowest eigenpairs of a welded lattice's constrained
// tangent (lowest_eigenpairs(), shift-invert block Lanczos on the sparse
// LDL^T) against the DoFs, and against the dense eigen-decomposition
// where that fits: the gridshell of bench/gridshell_scene.h with n x n
// cells, at its first converged load step (compressed, stable). Prints,
// median (min-max) of the repeats:
//   LDL^T:   one sparse factorization of the constrained tangent,
//   eigen:   lowest_eigenpairs() (its factorizations, solves and check),
//   dense:   the dense symmetric eigen-decomposition (up to 3000 free
//            DoFs), the baseline,
// and the eigenvalues found.
//
// Usage: lowest_eigenpairs [--cells n] [--modes k] [--repeats n]
//        (defaults 12, 6 and 3).
#include <io/scene.h>
#include <solvers/stability/lowest_eigenpairs.h>
#include <solvers/stability/stability.h>
#include <solvers/statics/static_solver.h>

#include <bench/gridshell_scene.h>
#include <bench/options.h>
#include <bench/timing.h>
#include <cstdio>

using namespace rodnet;

int
main(int argc, char **argv)
{
  rodnet::MPISession mpi(argc, argv);
  unsigned int       cells = 12, modes = 6, repeats = 3;
  bench::parse(argc,
               argv,
               {bench::number("--cells", cells, 1),
                bench::number("--modes", modes, 1),
                bench::number("--repeats", repeats, 1)});

  const Scene               scene = bench::gridshell(cells);
  std::unique_ptr<RodModel> model = scene.build_model();
  VectorType                u;
  const double              load_factor =
    bench::first_load_step(*model, scene.solver, u).load_factor;
  MatrixType tangent;
  model->initialize_matrix(tangent);
  model->assemble(u, load_factor, nullptr, &tangent);
  const ConstrainedFactorization ldlt(tangent, model->constraints());
  const unsigned int             n_free = ldlt.free_dofs().size();
  std::printf("gridshell of %u x %u cells at load factor %g: %u DoFs, %u "
              "free\n",
              cells,
              cells,
              load_factor,
              static_cast<unsigned int>(model->layout().n_dofs()),
              n_free);

  bench::print_time("LDL^T", bench::time_repeats(repeats, [&] {
                      ConstrainedFactorization(tangent, model->constraints());
                    }));
  Eigenpairs pairs;
  bench::print_time("eigen", bench::time_repeats(repeats, [&] {
                      pairs =
                        lowest_eigenpairs(tangent, model->constraints(), modes);
                    }));
  std::printf("  %u factorizations, %u solves; eigenvalues",
              pairs.factorizations,
              pairs.solves);
  for (const double value : pairs.values)
    std::printf(" %.6g", value);
  std::printf("\n");
  if (n_free <= 3000)
    bench::print_time("dense", bench::time_repeats(repeats, [&] {
                        dense_eigenpairs(tangent, model->constraints(), modes);
                      }));
}
