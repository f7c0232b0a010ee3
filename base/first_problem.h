#ifndef RODNET_BASE_FIRST_PROBLEM_H
#define RODNET_BASE_FIRST_PROBLEM_H

#include <mpi.h>
#include <string>

namespace rodnet
{
  /**
   * Collective over @p communicator: the @p problem of the lowest rank
   * whose @p problem is not empty, on every process (empty on all if
   * none has one). A check or assembly that fails on some processes
   * throws the same error on all of them with it, so that none waits in a
   * collective call for a process that threw, and a user reads the
   * message once per process, the same each time.
   */
  std::string
  first_problem(const std::string &problem, MPI_Comm communicator);
} // namespace rodnet

#endif
