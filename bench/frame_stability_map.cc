// Stability map of the dynamic integrators on the free-flying frame
// (tests/common/free_frame.h, N = 10 segments a leg; doc/dynamics.md,
// "Stability map on the frame"): for backward euler, newmark, midpoint and
// generalized alpha (its default rho_inf = 0.8) and time steps from 0.2 s down,
// the error of the tip's position relative to the corner, largest over t = 1,
// 2, ..., end, against a midpoint run of step h_ref (converged: its difference
// to h_ref / 2 is printed), divided by the leg length; where a run stops, the
// time and the solver's message. Wall time of each run (one run: the map is
// about accuracy, not speed).
//
// Usage: frame_stability_map [--end 6] [--reference-step 0.0025]
// [--threads 1]. Writes
// frame_stability_map.csv into the current directory; chart: gnuplot -e
// "csv='frame_stability_map.csv'; out='doc/frame_stability_map.png'"
// bench/frame_stability_map.gp.
#include <solvers/solver_failure.h>
#include <solvers/time/time_integrator.h>

#include "options.h"
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <tests/common/free_frame.h>
#include <vector>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  struct Options
  {
    unsigned int threads        = 1;
    double       end            = 6;
    double       reference_step = 0.0025;

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::real("--end", end),
              bench::real("--reference-step", reference_step)};
    }
  };

  /// A run: the tip relative to the corner at t = 1, 2, ...; the time
  /// reached and the solver's message where it stopped; wall time.
  struct Run
  {
    std::vector<Vector3> samples;
    double               reached = 0, seconds = 0;
    std::string          failure;
  };

  Run
  fly(const std::string &integrator, const double h, const double end)
  {
    FreeFrame                  frame = free_frame(10);
    TimeIntegrator::Parameters p;
    p.integrator         = integrator;
    p.time_step          = h;
    p.end_time           = end;
    p.load_factor        = triangle_pulse;
    p.relative_tolerance = 1e-10;
    p.progress_interval  = 0;
    TimeIntegrator integrator_(*frame.model,
                               std::vector<RodInertia>(2, frame_inertia),
                               p);
    Run            run;
    VectorType     u = frame.model->create_vector(),
               v     = frame.model->create_vector();
    const auto start = std::chrono::steady_clock::now();
    try
      {
        integrator_.run(u,
                        v,
                        [&](const TimeIntegrator::StepInfo &info,
                            const VectorType               &x,
                            const VectorType &) {
                          run.reached    = info.time;
                          const double k = std::round(info.time);
                          if (k >= 1 && std::abs(info.time - k) < 1e-9)
                            run.samples.push_back(
                              frame.model->position(x, frame.tip) -
                              frame.model->position(x, frame.corner));
                        });
      }
    catch (const SolverFailure &e)
      {
        run.failure = e.what();
      }
    run.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    return run;
  }

  /// Largest distance between the samples both runs have, over L.
  double
  error(const Run &run, const Run &reference)
  {
    double e = 0;
    for (std::size_t k = 0;
         k < std::min(run.samples.size(), reference.samples.size());
         ++k)
      e = std::max(e, (run.samples[k] - reference.samples[k]).norm());
    return e / frame_leg;
  }

  void
  map_integrators(const Options &options)
  {
    const Run reference = fly("midpoint", options.reference_step, options.end);
    const Run half = fly("midpoint", options.reference_step / 2, options.end);
    std::printf("reference: midpoint, h = %g, its difference to h/2: %.3e\n",
                options.reference_step,
                error(reference, half));
    std::ofstream csv("frame_stability_map.csv");
    csv << "integrator,h,error,reached,seconds,stopped\n";
    for (const std::string integrator :
         {"backward euler", "newmark", "midpoint", "generalized alpha"})
      for (const double h : {0.2, 0.1, 0.05, 0.02, 0.01, 0.005})
        {
          const Run  run     = fly(integrator, h, options.end);
          const bool stopped = !run.failure.empty();
          std::printf("%-17s h = %-6g error %.3e  %s%s\n",
                      integrator.c_str(),
                      h,
                      error(run, reference),
                      stopped ? "stopped: " : "",
                      run.failure.c_str());
          csv << '"' << integrator << "\"," << h << ',' << error(run, reference)
              << ',' << run.reached << ',' << run.seconds << ','
              << (stopped ? 1 : 0) << '\n';
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("frame_stability_map",
                              argc,
                              argv,
                              map_integrators);
}
