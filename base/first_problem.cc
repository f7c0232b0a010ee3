#include <deal.II/base/mpi.h>

#include <base/first_problem.h>

namespace rodnet
{
  std::string
  first_problem(const std::string &problem, const MPI_Comm communicator)
  {
    const unsigned int n_processes =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    if (n_processes == 1)
      return problem;
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const unsigned int first =
      dealii::Utilities::MPI::min(problem.empty() ? n_processes : rank,
                                  communicator);
    if (first == n_processes)
      return "";
    return dealii::Utilities::MPI::broadcast(communicator, problem, first);
  }
} // namespace rodnet
