#include <base/mpi_session.h>

#include <cstdlib>

// gcc says AddressSanitizer with __SANITIZE_ADDRESS__, clang (the fuzz
// builds) with __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#  define RODNET_LEAK_SANITIZER 1
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    define RODNET_LEAK_SANITIZER 1
#  endif
#endif
#if defined(RODNET_LEAK_SANITIZER)
#  include <sanitizer/lsan_interface.h>
#endif

namespace rodnet
{
  namespace
  {
    /**
     * While it lives, LeakSanitizer (in a sanitized build) does not report
     * what this thread allocates. Open MPI's plugins allocate in MPI_Init
     * and lose it in MPI_Finalize, when they are unloaded: the stack of
     * such an allocation then names no library, so no suppression can
     * match it without the slow full unwinder on every malloc of the
     * program (doc/sanitizers_and_fuzzing.md).
     */
    class MPILeaksIgnored
    {
    public:
      MPILeaksIgnored()
      {
#if defined(RODNET_LEAK_SANITIZER)
        __lsan_disable();
#endif
      }
      ~MPILeaksIgnored()
      {
#if defined(RODNET_LEAK_SANITIZER)
        __lsan_enable();
#endif
      }
    };
  } // namespace

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
    const MPILeaksIgnored ignored;
    session = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(
      argc, argv, max_threads);
  }

  MPISession::~MPISession()
  {
    const MPILeaksIgnored ignored;
    session.reset();
  }
} // namespace rodnet
