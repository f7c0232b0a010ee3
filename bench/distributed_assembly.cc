// Assembly of the welded lattice (bench/welded_lattice.h) on one process or
// several (issue 37): the model's set-up, then the residual and tangent
// and the energy alone, each the median (min-max) of --repeats runs, a
// run's time the slowest process's. Run it under mpirun for several
// processes:
//
//   distributed_assembly [--cells n] [--repeats n] [--threads n]
//   mpirun -np 2 distributed_assembly --cells 111
//
// On one process the model assembles by the direct scatter into the
// matrix's compressed rows; on several, each process evaluates the stencils
// it anchors, adds its own rows by the direct scatter and sends the rows of
// other processes to them (doc/architecture.md, "Several processes").
#include <deal.II/base/mpi.h>

#include <core/rod_model.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <bench/welded_lattice.h>
#include <cstdio>
#include <iostream>

namespace
{
  using namespace rodnet;

  struct Options
  {
    unsigned int threads = 1;
    unsigned int repeats = 5;
    unsigned int cells   = 60;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 3),
              bench::number("--cells", cells, 1)};
    }
  };

  /// The slowest process's wall time of @p work, for each of @p repeats
  /// runs after a warm-up.
  std::vector<double>
  slowest_times(const unsigned int repeats, const std::function<void()> &work)
  {
    std::vector<double> samples = bench::time_repeats(repeats, work);
    for (double &t : samples)
      t = dealii::Utilities::MPI::max(t, MPI_COMM_WORLD);
    return samples;
  }

  void
  print_row(const char *what, const bench::Statistics &s)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("  %-22s %8.4f s (%.4f-%.4f)\n",
                  what,
                  s.median,
                  s.min,
                  s.max);
  }

  void
  benchmark(const Options &options)
  {
    const double set_up_start = bench::now();
    const auto   model        = bench::welded_lattice(options.cells);
    const double set_up =
      dealii::Utilities::MPI::max(bench::now() - set_up_start, MPI_COMM_WORLD);
    VectorType u = model->create_vector(), r = model->create_vector();
    MatrixType k;
    model->initialize_matrix(k);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("welded lattice %u x %u, %u DoFs, %u process(es) x %u "
                  "thread(s)\n  %-22s %8.4f s\n",
                  options.cells,
                  options.cells,
                  static_cast<unsigned int>(model->layout().n_dofs()),
                  dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                  options.threads,
                  "set-up",
                  set_up);
    print_row("residual and tangent",
              bench::statistics(slowest_times(options.repeats, [&] {
                model->assemble(u, 0.5, &r, &k);
              })));
    print_row("energy", bench::statistics(slowest_times(options.repeats, [&] {
                model->assemble(u, 0.5, nullptr, nullptr);
              })));
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("distributed_assembly", argc, argv, benchmark);
}
