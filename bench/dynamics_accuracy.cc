// Accuracy against cost of the dynamic integrators (issue 35, doc/dynamics.md
// "Accuracy against cost"): the first bending period of the cantilever of
// tests/common/cantilever_swing.h (EI = rho A = L = 1, A L^2 / I = 1e4,
// midpoint clamp), N segments, started at rest in the first mode (in z) of
// the same discrete rod (tip at 0.01 L), 2.5 periods in steps of T / (2 N):
// space and time refined together, both second order. The period from the
// zero crossings of the tip is compared with the Euler-Bernoulli period
// 2 pi / 1.87510407^2 (the whole discretization's error), and the discrete
// mode's period with it (the error of the space discretization alone).
// Per integrator and N: DoFs, error, wall time per simulated period
// (median of --repeats runs).
//
// Usage: dynamics_accuracy [--segments 10,20,40,80,160,320]
// [--steps-per-segment 2] [--repeats 3] [--threads 1].
// Writes dynamics_accuracy.csv into the current directory; chart:
// gnuplot bench/dynamics_accuracy_cost.gp (from that directory).
#include "options.h"
#include "timing.h"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <tests/common/cantilever_swing.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  struct Options
  {
    unsigned int threads           = 1;
    unsigned int repeats           = 3;
    unsigned int steps_per_segment = 2;
    std::string  segments          = "10,20,40,80,160,320";

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::number("--repeats", repeats, 1),
              bench::number("--steps-per-segment", steps_per_segment, 1),
              bench::text("--segments", segments)};
    }
  };

  /// One run of @p method on the cantilever of @p n segments: its history
  /// and wall time.
  struct Sample
  {
    SwingHistory history;
    double       wall = 0;
  };

  Sample
  run(const unsigned int n,
      const VectorType  &shape,
      const double       amplitude,
      const std::string &method,
      const double       h,
      const double       end_time)
  {
    auto         rod   = cantilever(n, swing_elastic_rod(), 0);
    const double start = bench::now();
    Sample       s;
    s.history = free_vibration(*rod, shape, amplitude, method, h, end_time);
    s.wall    = bench::now() - start;
    return s;
  }

  /**
   * The first bending modes in y and z of the round rod have one
   * frequency, and the eigensolver returns any mix of the two: @p mode
   * without its y components is the mode in z alone (the rod along x
   * bends in y and z independently), which the tip's z crossings measure.
   */
  VectorType
  bending_in_z(const RodModel &model, const VectorType &mode)
  {
    VectorType shape = mode;
    for (unsigned int v = 0; v < model.network().n_vertices(); ++v)
      shape[model.layout().vertex_dof(v, 1)] = 0;
    return shape;
  }

  /**
   * The first Euler-Bernoulli period of the cantilever, 2 pi / beta^2
   * (EI = rho A = L = 1), with beta the first root of cos b cosh b = -1
   * by Newton's method from 1.875: to round-off, where the rounded
   * 1.8751 of cantilever_period() is 4.3e-6 off in the period.
   */
  double
  euler_bernoulli_period()
  {
    double b = 1.875;
    for (unsigned int k = 0; k < 20; ++k)
      b -= (std::cos(b) * std::cosh(b) + 1) /
           (std::cos(b) * std::sinh(b) - std::sin(b) * std::cosh(b));
    return 2 * M_PI / (b * b);
  }

  void
  benchmark(const Options &options)
  {
    const double  exact = euler_bernoulli_period();
    std::ofstream csv("dynamics_accuracy.csv");
    csv.precision(10);
    csv << "integrator,segments,dofs,steps_per_period,error,mode_error,"
           "wall_per_period_median_s,wall_min_s,wall_max_s\n";
    std::printf("integrator      N     DoFs  steps/period  period error  "
                "(space alone)  wall s per period, median (min-max)\n");
    std::istringstream list(options.segments);
    std::string        item;
    while (std::getline(list, item, ','))
      {
        const unsigned int n      = std::stoul(item);
        auto               model  = cantilever(n, swing_elastic_rod(), 0);
        const auto [omega, mode]  = first_mode(*model);
        const VectorType   shape  = bending_in_z(*model, mode);
        const double       period = 2 * M_PI / omega;
        const unsigned int tip    = model->network().rods()[0].vertices.back();
        const double       amplitude =
          0.01 / shape[model->layout().vertex_dof(tip, 2)];
        const unsigned int steps = options.steps_per_segment * n;
        for (const std::string method :
             {"newmark", "midpoint", "backward euler"})
          {
            std::vector<double> walls;
            Sample              s;
            for (unsigned int r = 0; r < options.repeats; ++r)
              {
                s = run(n,
                        shape,
                        amplitude,
                        method,
                        period / steps,
                        2.5 * period);
                walls.push_back(s.wall / 2.5);
              }
            const bench::Statistics wall     = bench::statistics(walls);
            const double            measured = zero_crossing_period(s.history);
            // A run stopped early has no period: an empty CSV field.
            const std::string error =
              s.history.failure.empty() ?
                bench::scientific(std::abs(measured / exact - 1)) :
                "";
            csv << method << ',' << n << ',' << model->layout().n_dofs() << ','
                << steps << ',' << error << ',' << std::abs(period / exact - 1)
                << ',' << wall.median << ',' << wall.min << ',' << wall.max
                << '\n';
            std::printf("%-15s %-5u %-5u %-13u %-13s %.3e      %s%s%s\n",
                        method.c_str(),
                        n,
                        model->layout().n_dofs(),
                        steps,
                        error.empty() ? "-" : error.c_str(),
                        std::abs(period / exact - 1),
                        bench::format_time(wall).c_str(),
                        s.history.failure.empty() ? "" : "; stopped: ",
                        s.history.failure.c_str());
            std::fflush(stdout);
          }
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("dynamics_accuracy", argc, argv, benchmark);
}
