// main() of the tests that use Trilinos objects: MPI must be initialized
// before any of them exists.
#include <base/mpi_session.h>

#include <gtest/gtest.h>

int
main(int argc, char **argv)
{
  rodnet::MPISession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
