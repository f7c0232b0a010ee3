#include <base/mpi_session.h>

#include <cstdlib>

namespace rodnet
{
  bool
  started_by_mpi_launcher()
  {
    for (const char *mark : {"OMPI_COMM_WORLD_SIZE",
                             "PMI_RANK",
                             "PMIX_RANK",
                             "PMI_SIZE",
                             "SLURM_STEP_ID",
                             "MPI_LOCALNRANKS"})
      if (std::getenv(mark) != nullptr)
        return true;
    return false;
  }

  void
  prefer_fast_singleton_mpi()
  {
    if (started_by_mpi_launcher())
      return;
    // setenv's last argument 0: an option the user set stays.
    // Without the daemon a singleton cannot spawn further processes
    // (MPI_Comm_spawn), which rodnet never does.
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    // ob1 with the "self" transport only: the default probes for the
    // shared-memory and network transports a single rank never uses.
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
  }

  MPISession::MPISession(int &argc, char **&argv, const unsigned int max_threads)
  {
    prefer_fast_singleton_mpi();
    session = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(
      argc, argv, max_threads);
  }
} // namespace rodnet
