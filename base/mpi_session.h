#ifndef RODNET_BASE_MPI_SESSION_H
#define RODNET_BASE_MPI_SESSION_H

#include <deal.II/base/mpi.h>

#include <memory>
#include <string>

namespace rodnet
{
  /// Whether an MPI launcher (mpirun, mpiexec, srun) started this process:
  /// it then leaves its marks in the environment (Open MPI's OMPI_COMM_WORLD_
  /// variables, PMI's and PMIx's ranks, Slurm's step).
  bool
  started_by_mpi_launcher();

  /**
   * MPI for the life of a program, as deal.II's MPI_InitFinalize (which it
   * holds). Every program of rodnet starts MPI with it; a user's program
   * may too.
   *
   * For a process that no launcher started (one MPI rank, a "singleton")
   * it first sets the Open MPI options that make MPI_Init cheap, unless the
   * user has set them: no orted daemon (ess_singleton_isolated), the ob1
   * messaging layer and only the "self" transport (a single rank talks to
   * nobody). Open MPI then starts in 0.06 s instead of 0.44 s
   * (doc/performance.md, "Start-up"). Such singletons all have the same
   * name, so each gets a session directory base of its own
   * ($TMPDIR/rodnet-mpi-XXXXXX, removed at the end; orte_tmpdir_base, unless
   * the user set it): many rodnet processes may run side by side. A
   * process started by a launcher keeps the launcher's options.
   */
  class MPISession;

  /**
   * Whether this process writes the outputs of a run, its files and its
   * messages: rank 0 of MPI_COMM_WORLD. On several processes every process
   * computes the same outputs (doc/architecture.md, "Several processes")
   * and one writes them.
   */
  bool
  writes_outputs();

  class MPISession
  {
  public:
    /// Starts MPI with at most @p max_threads threads per process (deal.II's
    /// meaning: 1 for none beyond the main thread).
    MPISession(int &argc, char **&argv, unsigned int max_threads = 1);

    /// Ends MPI (MPI_Finalize, through deal.II).
    ~MPISession();

    MPISession(const MPISession &) = delete;
    MPISession &
    operator=(const MPISession &) = delete;

  private:
    /// The session directory base made for this process ("" if none).
    std::string private_session_base;
    std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> session;
  };
} // namespace rodnet

#endif
