// Mesh convergence of the two junction examples of Lestringant & Kochmann
// (section 3, Figs. 3-4), for the "simple" and "classic" hinge kernels.
//
// Frame (Fig. 3a): two legs of length 1 at a right angle in the plane
// z = 0, clamped at the origin, welded at the corner; the free tip is moved
// to u_z / L = 1 in 20 load steps and the reaction F L^2/EI read there.
// N = 10 ... 320 segments per leg.
//
// Windmill (Fig. 3b): shaft of length 1 along z, three blades of length
// 1/2 welded at the hub, blade tips pinned, shaft top clamped and turned by
// tau_z = 1.5 rad in 15 load steps; the reaction moment M about e_z (EI = 1)
// at the top. n = 5 ... 80 segments per blade, 2n on the shaft.
//
// Both models are those of tests/validation/junctions.cc
// (tests/common/junction_examples.h); the time includes their construction.
//
// There is no closed form at these amplitudes. The reference of a study is
// the Richardson extrapolation of its two finest "simple" runs with the
// order observed on its three finest "simple" runs, p = log2(|f_{N/4} -
// f_{N/2}| / |f_{N/2} - f_N|); the errors of both kernels are relative to
// it. The time is the wall time from the model's construction to the
// converged final state, median of the repeats after one untimed warm-up.
// "steps" counts converged load steps (more than the nominal count when the
// solver cut a step).
//
// Results go to frame_convergence.csv and windmill_convergence.csv in the
// current directory; bench/junction_convergence.gp draws the charts.
//
// A run that fails (SolverFailure, or NOX giving up on a residual
// evaluation) is reported and ends the refinement of that kernel.
//
// Usage: junction_convergence [--threads n] [--repeats n]
// [--classic-levels n] (number of refinement levels run with the classic
// kernel, from the coarsest; default all) [--frame-max N] [--windmill-max n]
// (finest mesh of each study; 0 skips the study)
#include <core/rod_model.h>
#include <solvers/statics/static_solver.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <cmath>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <tests/common/junction_examples.h>
#include <vector>

using namespace rodnet;
using namespace rodnet::testing;

namespace
{
  struct Options
  {
    unsigned int threads        = 1;
    unsigned int repeats        = 3;
    unsigned int classic_levels = 100;
    unsigned int frame_max      = 320;
    unsigned int windmill_max   = 80;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 1),
              bench::number("--classic-levels", classic_levels),
              bench::number("--frame-max", frame_max),
              bench::number("--windmill-max", windmill_max)};
    }
  };

  struct Outcome
  {
    double       value      = 0;
    unsigned int dofs       = 0;
    unsigned int steps      = 0;
    unsigned int iterations = 0;
  };

  /// Solves @p model in @p n_steps nominal load steps and counts what the
  /// solver did. Throws where the final state is unstable: a value read
  /// there (the windmill's planar branch past the shaft's torsional
  /// buckling, where branch switching found no stable state) is not the
  /// model's answer.
  VectorType
  solve(RodModel &model, const unsigned int n_steps, Outcome &outcome)
  {
    model.finalize();
    VectorType               u = model.create_vector();
    StaticSolver::Parameters parameters;
    parameters.n_steps        = n_steps;
    unsigned int negative_end = 0;
    StaticSolver(model, parameters)
      .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
        ++outcome.steps;
        outcome.iterations += info.iterations;
        negative_end = info.check.negative_eigenvalues;
      });
    if (negative_end > 0)
      throw std::runtime_error("final state unstable (" +
                               std::to_string(negative_end) +
                               " negative eigenvalues)");
    outcome.dofs = u.size();
    return u;
  }

  /// The frame of Fig. 3a (fig3a_frame()) with @p n segments per leg, its
  /// tip moved by u_z = 1: the reaction force there.
  Outcome
  frame(const std::string &kernel, const unsigned int n)
  {
    const std::unique_ptr<RodModel> model = fig3a_frame(kernel, n, 1);
    Outcome                         outcome;
    const VectorType                u = solve(*model, 20, outcome);
    outcome.value = model->reaction(model->support("tip"), u, 1.0)[2];
    return outcome;
  }

  /// The windmill of Fig. 3b (fig3b_windmill()) with @p n segments per
  /// blade, its top turned by 1.5 rad: the moment about e_z there.
  Outcome
  windmill(const std::string &kernel, const unsigned int n)
  {
    const Fig3bWindmill windmill = fig3b_windmill(kernel, n, 1.5);
    Outcome             outcome;
    const VectorType    u = solve(*windmill.model, 15, outcome);
    outcome.value = windmill.model->reaction_moment(windmill.top, u, 1.0)[2];
    return outcome;
  }

  struct Run
  {
    std::string  kernel;
    unsigned int n;
    Outcome      outcome;
    double       time;
  };

  /// log2 of the ratio of successive differences of three values on meshes
  /// halved in size each time.
  double
  observed_order(const double coarse, const double middle, const double fine)
  {
    return std::log2(std::abs(middle - coarse) / std::abs(fine - middle));
  }

  void
  study(const std::string               &name,
        const std::string               &quantity,
        const std::vector<unsigned int> &sizes,
        Outcome (*model)(const std::string &, const unsigned int),
        const Options &options)
  {
    std::cout << "\n"
              << name << ": " << quantity << ", median of " << options.repeats
              << " repeats, " << options.threads << " thread(s)\n";
    std::vector<Run> runs;
    for (const std::string kernel : {"simple", "classic"})
      for (unsigned int level = 0; level < sizes.size(); ++level)
        {
          if (kernel == "classic" && level >= options.classic_levels)
            {
              std::cout << "  " << kernel << " N " << sizes[level]
                        << ": skipped (--classic-levels)\n";
              continue;
            }
          Run run{kernel, sizes[level], {}, 0};
          try
            {
              run.time = bench::statistics(
                           bench::time_repeats(options.repeats,
                                               [&] {
                                                 run.outcome =
                                                   model(kernel, sizes[level]);
                                               }))
                           .median;
            }
          catch (const std::exception &e)
            {
              std::cout << "  " << kernel << " N " << sizes[level]
                        << ": failed (" << e.what() << ")\n";
              break;
            }
          catch (...)
            {
              // NOX throws a C string when a residual evaluation fails.
              std::cout << "  " << kernel << " N " << sizes[level]
                        << ": failed (NOX: residual evaluation failed)\n";
              break;
            }
          std::printf("  %-7s N %4u  dofs %6u  value %.10f  steps %3u  "
                      "Newton iterations %4u  time %.3g s\n",
                      kernel.c_str(),
                      run.n,
                      run.outcome.dofs,
                      run.outcome.value,
                      run.outcome.steps,
                      run.outcome.iterations,
                      run.time);
          std::fflush(stdout);
          runs.push_back(run);
        }

    // Richardson extrapolation on the three finest "simple" runs.
    std::size_t m = 0;
    while (m < runs.size() && runs[m].kernel == "simple")
      ++m;
    AssertThrow(m >= 3,
                dealii::ExcMessage(name + ": fewer than three simple runs"));
    const double f0 = runs[m - 3].outcome.value, f1 = runs[m - 2].outcome.value,
                 f2        = runs[m - 1].outcome.value;
    const double p         = observed_order(f0, f1, f2);
    const double reference = f2 + (f2 - f1) / (std::pow(2.0, p) - 1);
    std::printf("  observed order (simple, N = %u, %u, %u): %.3f; "
                "Richardson reference %.10f\n",
                runs[m - 3].n,
                runs[m - 2].n,
                runs[m - 1].n,
                p,
                reference);

    std::ofstream csv(name + "_convergence.csv");
    csv.precision(10);
    csv << "kernel,N,dofs,value,rel_error,time_s,steps\n";
    for (const Run &run : runs)
      csv << run.kernel << ',' << run.n << ',' << run.outcome.dofs << ','
          << run.outcome.value << ','
          << std::abs(run.outcome.value - reference) / std::abs(reference)
          << ',' << run.time << ',' << run.outcome.steps << '\n';
    std::cout << "  wrote " << name << "_convergence.csv" << std::endl;
  }

  /// The benchmark proper, run once the command line is read and MPI is
  /// up.
  void
  benchmark(const Options &options)
  {
    const auto up_to = [](const unsigned int coarsest,
                          const unsigned int finest) {
      std::vector<unsigned int> sizes;
      for (unsigned int n = coarsest; n <= finest; n *= 2)
        sizes.push_back(n);
      return sizes;
    };
    // The observed order needs three sizes: 10, 20, 40 and 5, 10, 20 at
    // the least.
    if ((options.frame_max > 0 && options.frame_max < 40) ||
        (options.windmill_max > 0 && options.windmill_max < 20))
      throw std::invalid_argument(
        "--frame-max must be 0 or at least 40, --windmill-max 0 or at least "
        "20: the observed order needs three sizes");
    if (options.frame_max > 0)
      study("frame",
            "F L^2/EI at u_z/L = 1, 20 load steps",
            up_to(10, options.frame_max),
            frame,
            options);
    if (options.windmill_max > 0)
      study("windmill",
            "M (EI = 1) at tau_z = 1.5 rad, 15 load steps",
            up_to(5, options.windmill_max),
            windmill,
            options);
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("junction_convergence", argc, argv, benchmark);
}
