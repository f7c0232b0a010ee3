#include <base/mpi_session.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

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

  namespace
  {
    void
    prefer_fast_singleton_mpi()
    {
      // setenv's last argument 0: an option the user set stays.
      // Without the daemon a singleton cannot spawn further processes
      // (MPI_Comm_spawn), which rodnet never does.
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      // ob1 with the "self" transport only: the default probes for the
      // shared-memory and network transports a single rank never uses.
      setenv("OMPI_MCA_pml", "ob1", 0);
      setenv("OMPI_MCA_btl", "self", 0);
    }

    /**
     * A new empty directory under $TMPDIR (or /tmp) for Open MPI's session
     * files, given to it as orte_tmpdir_base; "" if none could be made or
     * the user chose the base. Every isolated singleton has the same
     * process name, [[0,1],0], hence the same session directory
     * <base>/ompi.<host>.<uid>/jf.0/1/0: with a shared base, a process
     * that ends removes the directory another one is creating, whose
     * MPI_Init then fails ("A call to mkdir was unable to create the
     * desired directory"; 5 of 200 overlapping starts here).
     */
    std::string
    make_private_session_base()
    {
      if (std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr)
        return "";
      const char       *tmpdir = std::getenv("TMPDIR");
      const std::string pattern =
        std::string(tmpdir != nullptr && tmpdir[0] != '\0' ? tmpdir : "/tmp") +
        "/rodnet-mpi-XXXXXX";
      std::vector<char> path(pattern.begin(), pattern.end());
      path.push_back('\0');
      if (mkdtemp(path.data()) == nullptr)
        return ""; // Open MPI's default base then: a rare race, not an error
      setenv("OMPI_MCA_orte_tmpdir_base", path.data(), 1);
      return path.data();
    }
  } // namespace

  MPISession::MPISession(int               &argc,
                         char            **&argv,
                         const unsigned int max_threads)
  {
    if (!started_by_mpi_launcher())
      {
        prefer_fast_singleton_mpi();
        private_session_base = make_private_session_base();
      }
    {
      const MPILeaksIgnored ignored;
      session =
        std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc,
                                                                   argv,
                                                                   max_threads);
    }
    // Open MPI has read it: the processes this one starts (the tests start
    // rodnet-run) must make bases of their own, not inherit this one.
    if (!private_session_base.empty())
      unsetenv("OMPI_MCA_orte_tmpdir_base");
  }

  MPISession::~MPISession()
  {
    {
      const MPILeaksIgnored ignored;
      session.reset();
    }
    if (!private_session_base.empty())
      {
        // Open MPI removed its files at MPI_Finalize; whatever a failed
        // start left goes too. The directory is this process's own.
        std::error_code ignored_error;
        std::filesystem::remove_all(private_session_base, ignored_error);
      }
  }
  bool
  writes_outputs()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }
} // namespace rodnet
