// Many rodnet-run processes started side by side on one machine (a sweep
// spread over cores by xargs -P, ctest -j) must not break each other's MPI
// start: every isolated Open MPI singleton has the same process name, and
// with a shared session directory one that ends removed the directory
// another was creating ("A call to mkdir was unable to create the desired
// directory", MPI_Init aborts; 5 of 200 overlapping starts without
// MPISession's private session base, 1 failed test of a CI run).
#include <common/run_driver.h>

#include <base/mpi_session.h>
#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <thread>
#include <unistd.h>
#include <vector>

namespace
{
  namespace fs = std::filesystem;
  using rodnet::testing::read_file;

  /// Starts rodnet-run @p argument with TMPDIR @p tmpdir and its stdout
  /// and stderr in @p log; returns its process id.
  pid_t
  start_driver(const std::string &argument,
               const std::string &tmpdir,
               const std::string &log)
  {
    const std::string program = std::string(RODNET_BINARY_DIR) + "/rodnet-run";
    const pid_t       pid     = fork();
    if (pid == 0)
      {
        const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(out, STDOUT_FILENO);
        dup2(out, STDERR_FILENO);
        setenv("TMPDIR", tmpdir.c_str(), 1);
        execl(program.c_str(),
              program.c_str(),
              argument.c_str(),
              static_cast<char *>(nullptr));
        _exit(127);
      }
    return pid;
  }

  TEST(ConcurrentRuns, MPIStartsDoNotCollide)
  {
    // A scene file that does not exist: each process starts MPI, reports
    // the bad input (exit code 1) and ends, so starts and ends overlap.
    const std::string tmpdir = fs::absolute("concurrent_runs_tmp").string();
    fs::remove_all(tmpdir);
    fs::create_directory(tmpdir);
    constexpr unsigned int n_processes = 16;
    std::vector<pid_t>     pids;
    for (unsigned int p = 0; p < n_processes; ++p)
      {
        pids.push_back(
          start_driver("no_such_scene.prm",
                       tmpdir,
                       "concurrent_run_" + std::to_string(p) + ".log"));
        ASSERT_GT(pids.back(), 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(15));
      }
    for (unsigned int p = 0; p < n_processes; ++p)
      {
        int status = 0;
        waitpid(pids[p], &status, 0);
        const std::string log =
          read_file("concurrent_run_" + std::to_string(p) + ".log");
        ASSERT_TRUE(WIFEXITED(status)) << "process " << p << ":\n" << log;
        EXPECT_EQ(WEXITSTATUS(status), 1) << "process " << p << ":\n" << log;
        EXPECT_NE(log.find("no_such_scene.prm"), std::string::npos) << log;
        EXPECT_EQ(log.find("MPI"), std::string::npos) << log;
      }
    // Each process removed the session directory base it made.
    EXPECT_TRUE(fs::is_empty(tmpdir));
  }

  // The deterministic half of the above: this test program's own MPI
  // session (tests/common/gtest_mpi_main.cc) lives in a base of its own,
  // and the processes it starts do not inherit that base (they all would
  // share it, and collide again: every run of the test above failed so).
  TEST(ConcurrentRuns, SessionBaseIsPrivateAndNotInherited)
  {
    if (rodnet::started_by_mpi_launcher())
      GTEST_SKIP() << "a launcher's process keeps the launcher's options";
    const char *inherited = std::getenv("OMPI_MCA_orte_tmpdir_base");
    if (inherited != nullptr &&
        std::string(inherited).find("rodnet-mpi-") == std::string::npos)
      GTEST_SKIP() << "the user chose Open MPI's session base";
    EXPECT_EQ(inherited, nullptr) << inherited;
    const char    *tmpdir = std::getenv("TMPDIR");
    const fs::path base(tmpdir != nullptr && tmpdir[0] != '\0' ? tmpdir :
                                                                 "/tmp");
    // Other users' bases cannot be read: error codes, not exceptions.
    unsigned int    n_sessions = 0;
    std::error_code error;
    for (const auto &entry : fs::directory_iterator(base, error))
      if (entry.path().filename().string().rfind("rodnet-mpi-", 0) == 0)
        for (const auto &inside : fs::directory_iterator(entry.path(), error))
          n_sessions +=
            inside.path().filename().string().rfind("ompi.", 0) == 0;
    EXPECT_GE(n_sessions, 1u)
      << "no Open MPI session in " << base << "/rodnet-mpi-*";
  }
} // namespace
