// MUMPS's factorization and solve of a welded lattice's tangent on one or
// several processes (issue 37; run it under mpirun -np P).
//
// The lattice of newton_scaling: n x n cells, beams of length 0.1 in 10
// segments, EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67, pinned at the four
// corners (tests/common/pinned_lattices.h builds it). Its tangent at the flat
// state, that of Newton's first iteration there (gravity, a dead load, adds
// none), is built whole on every process, its rows split into contiguous, even
// parts over the processes, and given to MumpsFactorization (distributed
// assembled input on several processes). Timed, on rank 0 after a barrier: the
// analysis (once), then
// --repeats factorizations and solves after one untimed pair; median
// (min-max) in s. As a check, |K x - b| / |b| of the last solve, b of
// entries sin(0.37 i + 1).
//
// Usage: mpirun -np P mumps_processes [--cells n] [--repeats n]
// (defaults 80 and 5).
#include <deal.II/base/mpi.h>

#include <solvers/newton/mumps_factorization.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <cmath>
#include <iostream>
#include <tests/common/pinned_lattices.h>
#include <tests/common/split_rows.h>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads = 1;
    unsigned int cells   = 80;
    unsigned int repeats = 5;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--cells", cells, 1),
              bench::number("--repeats", repeats, 3)};
    }
  };

  void
  mumps_processes(const Options &options)
  {
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const bool host =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const double start = bench::now();
    const auto   model =
      rodnet::testing::pinned_square_lattice(options.cells,
                                             0.1,
                                             10,
                                             {1e5, 400, 100, 67},
                                             false,
                                             MPI_COMM_SELF);
    MatrixType serial;
    model->initialize_matrix(serial);
    model->assemble(model->create_vector(), 0.0, nullptr, &serial);
    const unsigned int     n     = serial.m();
    const dealii::IndexSet owned = rodnet::testing::contiguous_rows(n, true);
    MatrixType             K;
    rodnet::testing::copy_own_rows(serial, owned, K);
    VectorType b(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      b[i] = std::sin(0.37 * i + 1);
    b.compress(dealii::VectorOperation::insert);
    VectorType   x     = b;
    const double setup = bench::now() - start;

    std::unique_ptr<MumpsFactorization> mumps;
    const double                        analysis = bench::timed_together(
      [&] { mumps = std::make_unique<MumpsFactorization>(K); });
    std::vector<double> factorize, solve;
    for (unsigned int k = 0; k <= options.repeats; ++k)
      {
        const double f = bench::timed_together([&] { mumps->factorize(); });
        const double s = bench::timed_together([&] { mumps->solve(b, x); });
        if (k > 0)
          {
            factorize.push_back(f);
            solve.push_back(s);
          }
      }
    VectorType residual = b;
    K.vmult(residual, x);
    residual.add(-1.0, b);
    const double relative_residual = residual.l2_norm() / b.l2_norm();
    if (!host)
      return;
    std::cout << "lattice " << options.cells << " x " << options.cells << "  "
              << n << " DoFs  " << n_processes << " process(es)  set-up "
              << setup << " s\n  analysis  " << analysis << " s\n  factorize "
              << bench::format_time(bench::statistics(factorize))
              << " s\n  solve     "
              << bench::format_time(bench::statistics(solve))
              << " s\n  factor entries " << mumps->factor_entries()
              << "  negative pivots " << mumps->negative_pivots().value()
              << "  |K x - b| / |b| " << relative_residual << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("mumps_processes", argc, argv, mumps_processes);
}
