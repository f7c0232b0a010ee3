// --timings on several processes (base/phase_times.h): the table, written
// by rank 0 alone, gives for each phase the least and the most seconds over
// the processes and the rank of the slowest, the process the others wait
// for (none where there is one process). Each process here spends a
// different, known time in one phase.

#include <deal.II/base/mpi.h>

#include <base/phase_times.h>

#include <chrono>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <thread>

using namespace rodnet;

TEST(PhaseTimes, TheTableNamesTheSlowestProcess)
{
  const unsigned int rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int n_processes =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  phase_times::reset();
  {
    // Asleep, not busy: the processes may outnumber the cores. 50 ms
    // between ranks is far beyond a sleep's overshoot.
    const phase_times::Scope phase(phase_times::Phase::outputs);
    std::this_thread::sleep_for(
      std::chrono::duration<double>(0.02 + 0.05 * rank));
  }
  std::stringstream out;
  phase_times::write_table(out, 1.0, MPI_COMM_WORLD);
  const std::string text = out.str();
  if (rank != 0)
    {
      EXPECT_TRUE(text.empty()) << "written by rank 0 alone: " << text;
      return;
    }
  if (n_processes == 1)
    {
      EXPECT_EQ(text.find("slowest"), std::string::npos)
        << "no ranks where there is one process: " << text;
      return;
    }
  EXPECT_NE(text.find("slowest"), std::string::npos) << text;
  const std::regex row(
    R"(\n  outputs +([0-9.]+) +([0-9.]+) +[0-9.]+ % +([0-9]+)\n)");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(text, match, row)) << text;
  // The least is rank 0's 20 ms, the most the last rank's; a sleep lasts at
  // least what it was asked for and, on a machine this test shares, up to
  // 40 ms more; the table rounds to 1 ms.
  EXPECT_GE(std::stod(match[1]), 0.020 - 5e-4) << text;
  EXPECT_LT(std::stod(match[1]), 0.060) << text;
  EXPECT_GE(std::stod(match[2]), 0.02 + 0.05 * (n_processes - 1) - 5e-4)
    << text;
  EXPECT_EQ(std::stoul(match[3]), n_processes - 1) << text;
  // "other" is the rest of each process's second; its slowest is rank 0.
  const std::regex other(R"(\n  other +([0-9.]+) +([0-9.]+) +[0-9.]+ % +0\n)");
  EXPECT_TRUE(std::regex_search(text, other)) << text;
}
