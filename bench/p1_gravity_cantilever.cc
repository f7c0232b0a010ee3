// P1 of /work/shared/BENCHMARKS.md: gravity cantilever, large deflection.
//
// A straight rod from (0,0,0) to (1,0,0), circular section r = 5e-3,
// E = 1e8, nu = 0.5 (G = E/3), under its weight q = rho A g = 0.770476 N/m
// in -z, clamped at x = 0 by the midpoint clamp (the first two vertices sit
// at -l/2 and l/2, so the free length is 1). Static equilibrium by
// StaticSolver with load stepping, for N = 50, 100, 200, 500, 1000
// vertices (N - 1 segments); the model is bench/p1_problem.h's, shared with
// the dynamic-relaxation version p1_dynamic_relaxation. The time is the wall
// time from the model's construction to equilibrium, median (min-max) of the
// repeats.
//
// The reference tip (x, z) = (0.5157790, -0.7938299) is that of the
// inextensible elastica. Our rod is extensible, EA = 7854 N: with q L =
// 0.77 N the axial strain is ~1e-4, so the tip differs from the reference
// by O(1e-4) however fine the mesh. The variant "EA x 1e3" scales EA up to
// show that part of the error; it is a check, not the P1 problem.
//
// Each point is set beside the fastest run of DisMech, tuned as a fair user
// would (BENCHMARKS.md, re-measured 2026-12-01), whose tip error in z is no
// larger: the ratio of the two times is printed and written to the CSV.
//
// First, the smallest number of load steps in {1, 2, 4, 8} with which
// every N converges without a step cut is chosen (or --steps n). Results go
// to p1_gravity_cantilever.csv in the current directory; the chart
// doc/p1_error_vs_time.png is drawn from it by bench/p1_error_vs_time.gp.
//
// Usage: p1_gravity_cantilever [--threads n] [--repeats n] [--steps n]
// [--log 1] (the solver's step log, for diagnosis; it is inside the timing)
// [--line-search name] (Newton's line search: "backtrack", "polynomial" or
// "full step", the default) [--linear-solver auto|klu|band] (Newton's direct
// solver, TangentFactorization; default auto) [--only-n n] (one of the N
// above only, e.g. to profile it)
#include <solvers/static_solver.h>

#include <bench/options.h>
#include <bench/p1_problem.h>
#include <bench/timing.h>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

using namespace rodnet;

namespace
{
  using bench::p1::x_exact;
  using bench::p1::z_exact;

  struct Options
  {
    unsigned int threads       = 1;
    unsigned int repeats       = 5;
    unsigned int steps         = 0; ///< 0: choose
    bool         log           = false;
    std::string  line_search   = "full step";
    std::string  linear_solver = "auto";
    unsigned int only_n        = 0; ///< 0: every N

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 5),
              bench::number("--steps", steps),
              bench::flag("--log", log),
              bench::text("--line-search", line_search),
              bench::text("--linear-solver", linear_solver),
              bench::number("--only-n", only_n)};
    }
  };

  struct Outcome
  {
    bool         converged  = false;
    unsigned int steps_done = 0; ///< converged steps, > n_steps after cuts
    unsigned int iterations = 0;
    Vector3      tip;
  };

  /// Builds the model and solves; everything here is inside the timing.
  Outcome
  solve(const unsigned int n_vertices,
        const unsigned int n_steps,
        const double       ea_scale,
        const Options     &options)
  {
    const std::unique_ptr<RodModel> model =
      bench::p1::rod_model(n_vertices, ea_scale);
    StaticSolver::Parameters parameters;
    parameters.n_steps              = n_steps;
    parameters.newton.line_search   = options.line_search;
    parameters.newton.linear_solver = options.linear_solver;
    Outcome    outcome;
    VectorType u = model->create_vector();
    try
      {
        StaticSolver(*model, parameters, options.log ? &std::cout : nullptr)
          .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
            ++outcome.steps_done;
            outcome.iterations += info.iterations;
          });
        outcome.converged = true;
      }
    catch (const SolverFailure &)
      {
        return outcome;
      }
    outcome.tip = model->configuration().position(u, bench::p1::tip(*model));
    return outcome;
  }

  const unsigned int sizes[] = {50, 100, 200, 500, 1000};

  /// The smallest step count in {1, 2, 4, 8} that every N solves without a
  /// step cut.
  unsigned int
  choose_steps(const double ea_scale, const Options &options)
  {
    for (const unsigned int n_steps : {1u, 2u, 4u, 8u})
      {
        bool robust = true;
        for (const unsigned int n : sizes)
          {
            if (options.only_n > 0 && n != options.only_n)
              continue;
            const Outcome o = solve(n, n_steps, ea_scale, options);
            std::cout << "  trial: N " << n << ", " << n_steps
                      << " step(s): " << (o.converged ? "converged" : "failed")
                      << ", " << o.steps_done << " converged step(s), "
                      << o.iterations << " Newton iterations\n";
            robust = robust && o.converged && o.steps_done == n_steps;
          }
        if (robust)
          return n_steps;
      }
    throw std::runtime_error("no step count up to 8 converges without cuts");
  }

  /// DisMech's runs of BENCHMARKS.md, tuned as a fair user would (large
  /// time step, no line search, free length exactly 1), re-measured
  /// 2026-12-01: N, time inside the process (s), tip error in z.
  struct PeerPoint
  {
    unsigned int n;
    double       time, error;
  };
  const PeerPoint dismech_tuned[] = {{50, 0.061, 5.0e-4},
                                     {200, 0.047, 1.6e-6},
                                     {1000, 0.212, 3.3e-5}};

  /// The time of DisMech's fastest tuned run whose tip error is at most
  /// @p error (10% allowed: the errors are quoted to two digits), NaN if
  /// none is that accurate: our time is set beside that one.
  double
  dismech_time_at(const double error)
  {
    double t = NAN;
    for (const PeerPoint &p : dismech_tuned)
      if (p.error <= 1.1 * error && !(t <= p.time))
        t = p.time;
    return t;
  }

  /// "tuned DisMech as accurate 0.047 s: 18.0x", or that no run of it is.
  std::string
  peer_ratio(const double dismech_time, const double our_time)
  {
    if (std::isnan(dismech_time))
      return "no tuned DisMech run as accurate";
    char text[80];
    std::snprintf(text,
                  sizeof(text),
                  "tuned DisMech as accurate %.3f s: %.1fx",
                  dismech_time,
                  dismech_time / our_time);
    return text;
  }

  /// The benchmark proper, run once the command line is read and MPI is
  /// up.
  void
  benchmark(const Options &options)
  {
    std::ofstream csv("p1_gravity_cantilever.csv");
    csv << "variant,N,load_steps,newton_iterations,time_median_s,"
           "time_min_s,time_max_s,x_tip,z_tip,z_error,x_error,"
           "dismech_tuned_time_s,dismech_tuned_ratio\n";
    csv.precision(8);

    for (const double ea_scale : {1.0, 1e3})
      {
        const std::string variant = ea_scale == 1.0 ? "P1" : "EA x 1e3";
        std::cout << "\n"
                  << variant << ": choosing the number of load "
                  << "steps\n";
        const unsigned int n_steps =
          options.steps > 0 ? options.steps : choose_steps(ea_scale, options);
        std::cout << variant << ": " << n_steps << " load step(s), "
                  << options.threads << " thread(s), median (min-max) of "
                  << options.repeats << " repeats\n";
        for (const unsigned int n : sizes)
          {
            if (options.only_n > 0 && n != options.only_n)
              continue;
            Outcome                   outcome;
            const std::vector<double> times =
              bench::time_repeats(options.repeats, [&] {
                outcome = solve(n, n_steps, ea_scale, options);
              });
            if (!outcome.converged)
              throw std::runtime_error("N = " + std::to_string(n) +
                                       " did not converge");
            const bench::Statistics t = bench::statistics(times);
            const double z_error      = std::abs(outcome.tip[2] - z_exact);
            const double x_error      = std::abs(outcome.tip[0] - x_exact);
            const double dismech      = dismech_time_at(z_error);
            char         line[400];
            std::snprintf(line,
                          sizeof(line),
                          "  N %5u  iterations %3u  time %-30s  tip "
                          "(%.7f, %.7f)  z error %.2e  x error %.2e  "
                          "%s\n",
                          n,
                          outcome.iterations,
                          bench::format_time(t).c_str(),
                          outcome.tip[0],
                          outcome.tip[2],
                          z_error,
                          x_error,
                          peer_ratio(dismech, t.median).c_str());
            std::cout << line << std::flush;
            csv << variant << ',' << n << ',' << n_steps << ','
                << outcome.iterations << ',' << t.median << ',' << t.min << ','
                << t.max << ',' << outcome.tip[0] << ',' << outcome.tip[2]
                << ',' << z_error << ',' << x_error << ',' << dismech << ','
                << dismech / t.median << '\n';
          }
      }
    std::cout << "\nwrote p1_gravity_cantilever.csv" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("p1_gravity_cantilever", argc, argv, benchmark);
}
