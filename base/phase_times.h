#ifndef RODNET_BASE_PHASE_TIMES_H
#define RODNET_BASE_PHASE_TIMES_H

#include <deal.II/base/mpi.h>

#include <array>
#include <chrono>
#include <ostream>

namespace rodnet
{
  /**
   * Where a run's wall time goes, by phase, for `rodnet-run --timings` and
   * the benchmarks: the model's build, its assembly (energy only, with the
   * gradient, with the Hessian), the assembly's exchanges between
   * processes (the ghost entries' import, the rows sent to their owners, the
   * sums over processes, each with the wait for the slowest process: where a
   * process has less to evaluate, its wait shows here), the factorizations'
   * analysis and numeric phase, the linear solves, the solvers' checks and
   * the outputs.
   *
   * The times are exclusive: a phase entered inside another (the energy
   * a check assembles, a solve inside a check) is charged to the inner one
   * only, and the outer one's clock stops meanwhile, so that the phases add
   * up to at most the run's time and the rest is the solvers' own work
   * (vector operations, line-search logic, exchanges between processes
   * outside the phases). Each thread keeps its own account; the phases are
   * entered on the thread that drives the run, around the threaded loops,
   * never inside them. A phase costs two clock reads (about 50 ns), which
   * the coarse places they are entered at (a whole assembly, a whole
   * factorization) make negligible.
   */
  namespace phase_times
  {
    /// The phases, in the order the report lists them.
    enum class Phase
    {
      model_build,
      energy_assembly,
      gradient_assembly,
      hessian_assembly,
      exchange,
      factorization_analysis,
      numeric_factorization,
      linear_solves,
      checks,
      outputs,
      n_phases
    };

    /// The phase's name in the report ("Hessian assembly").
    const char *
    name(Phase phase);

    /**
     * Charges the wall time from its construction to its destruction to
     * @p phase, less the time of the scopes opened inside it (on the same
     * thread). Scopes nest as blocks do.
     */
    class Scope
    {
    public:
      explicit Scope(Phase phase);
      ~Scope();

      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      /// The phase that was open when this one opened.
      Phase outer;
    };

    /// The seconds this thread has charged to each phase so far.
    std::array<double, static_cast<std::size_t>(Phase::n_phases)>
    seconds();

    /// Sets this thread's accounts to zero (a program that times several
    /// runs, one after another).
    void
    reset();

    /**
     * Writes to @p out, on rank 0 of @p communicator only, a table of the
     * phases that took 0.5 ms or more on some process: for each, the least
     * and the most seconds over the processes and the most as a share of
     * @p total_seconds (the run's wall time), and where there are several
     * processes the rank of one that took the most (which process the
     * others wait for); then "other", the rest of the run. Collective:
     * every process of @p communicator calls it.
     */
    void
    write_table(std::ostream &out, double total_seconds, MPI_Comm communicator);
  } // namespace phase_times
} // namespace rodnet

#endif
