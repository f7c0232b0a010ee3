// The spin-up of a flexible beam on a hub (Kane, Ryan & Banerjee 1987;
// tests/common/spin_up.h, doc/dynamics.md "Moving supports"): the tip
// deflection in the hub's frame of the rod against KRB's reduced model with
// the centrifugal stiffening and without it, as CSV on standard output:
//   time, rod, stiffened, linear
// Usage: spin_up [segments [time step [end time [integrator [rho_inf]]]]],
// defaults 10, 0.005, 30, newmark, 0.8 (the spectral radius at infinity of
// "generalized alpha"). Chart: bench/spin_up.gp.
#include <cstdlib>
#include <iostream>
#include <string>
#include <tests/common/spin_up.h>

int
main(int argc, char *argv[])
{
  using namespace rodnet::testing::spin_up;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int        n      = argc > 1 ? std::atoi(argv[1]) : 10;
  const double              h      = argc > 2 ? std::atof(argv[2]) : 0.005;
  const double              end    = argc > 3 ? std::atof(argv[3]) : 30;
  const std::string         method = argc > 4 ? argv[4] : "newmark";
  const double              rho    = argc > 5 ? std::atof(argv[5]) : 0.8;
  const RodHistory          rod    = rod_spin_up(n, method, h, end, rho);
  const std::vector<double> stiffened =
    reduced_tip_deflection(rod.time, rod.hub_radius, true);
  const std::vector<double> linear =
    reduced_tip_deflection(rod.time, rod.hub_radius, false);
  std::cout << "time,rod,stiffened,linear\n";
  for (unsigned int i = 0; i < rod.time.size(); ++i)
    std::cout << rod.time[i] << "," << rod.tip[i] << "," << stiffened[i] << ","
              << linear[i] << "\n";
  if (!rod.failure.empty())
    std::cerr << "stopped: " << rod.failure << "\n";
  return rod.failure.empty() ? 0 : 2;
}
