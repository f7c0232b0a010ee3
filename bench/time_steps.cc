// Time-step study of the integrators of TimeIntegrator (doc/dynamics.md):
//
// - period: the cantilever of tests/common/cantilever_swing.h (N = 50),
//   started at rest in its first discrete mode (tip at 0.01 L), 4.5
//   periods; error of the zero-crossing period against the period of that
//   mode (the generalized eigenproblem of the same discrete rod, so the
//   error is the time stepping's alone), against the step and the wall
//   time, for newmark, midpoint and backward euler;
// - creep: a standard-linear-solid cantilever (N = 20, E2 = 0.3 E1,
//   t_r = 20 s, so t_c = 26 s >> the bending period 1.79 s) under a
//   constant tip load 3e-3 EI/L^2 from t = 0, to 10 t_c; largest relative
//   error of the tip deflection against delta_1 E1 J(t) at t_c, 3 t_c,
//   10 t_c, with delta_1 the static deflection of the same discrete rod of
//   modulus E1 (so that the error is that of the time stepping alone; the
//   rod is linear at this load), for quasi-static, backward euler and
//   newmark (the last two with
//   inertia: the sudden load also starts a vibration, which backward Euler
//   damps and Newmark keeps);
// - stability: the large-amplitude swing (N = 20, tip load 2 EI/L^2,
//   amplitude ~0.5 L), 10 periods, steps per period from 400 down to 6, for
//   each dynamic integrator: whether the run completes, the energy drift,
//   the steps halved, and the solver's message where it stops.
//
// Usage: time_steps [--study period,creep,stability] [--repeats n]
// [--threads n]. Writes time_steps_<study>.csv into the current directory;
// charts: gnuplot bench/time_steps.gp (from that directory).
#include <materials/standard_linear_solid.h>

#include "options.h"
#include "timing.h"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <tests/common/cantilever_swing.h>

namespace
{
  using namespace rodnet;
  using namespace rodnet::testing;

  struct Options
  {
    unsigned int threads = 1;
    unsigned int repeats = 3;
    std::string  studies = "period,creep,stability";

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::number("--repeats", repeats, 1),
              bench::text("--study", studies)};
    }
  };

  /// Median wall time of @p repeats runs of @p run, which returns its last
  /// result through @p result.
  template <class Result>
  bench::Statistics
  timed(const unsigned int repeats, Result &result, std::function<Result()> run)
  {
    std::vector<double> samples;
    for (unsigned int r = 0; r < repeats; ++r)
      {
        const double start = bench::now();
        result             = run();
        samples.push_back(bench::now() - start);
      }
    return bench::statistics(samples);
  }

  void
  period_study(const Options &options)
  {
    auto model                = cantilever(50, swing_elastic_rod(), 0);
    const auto [omega, shape] = first_mode(*model);
    const double       period = 2 * M_PI / omega;
    const unsigned int tip    = model->network().rods()[0].vertices.back();
    // Tip deflection 0.01 L: small, the rod is linear to 1e-4.
    const double amplitude = 0.01 / shape[model->layout().vertex_dof(tip, 2)];
    std::printf("period study: period of the discrete first mode %.10g "
                "(Euler-Bernoulli %.10g)\n",
                period,
                cantilever_period());
    std::ofstream csv("time_steps_period.csv");
    csv.precision(10);
    csv << "integrator,steps_per_period,time_step,period,error,time_median_s,"
           "time_min_s,time_max_s\n";
    for (const std::string method : {"newmark", "midpoint", "backward euler"})
      for (const unsigned int n : {10u, 20u, 40u, 80u, 160u, 320u})
        {
          SwingHistory            h;
          const bench::Statistics time =
            timed<SwingHistory>(options.repeats, h, [&] {
              auto rod = cantilever(50, swing_elastic_rod(), 0);
              return free_vibration(*rod,
                                    shape,
                                    amplitude,
                                    method,
                                    period / n,
                                    4.5 * period);
            });
          // A run stopped before its last crossing has no period to
          // report: an empty CSV field and "-".
          const double      measured = zero_crossing_period(h);
          const std::string error =
            h.failure.empty() ?
              bench::scientific(std::abs(measured / period - 1)) :
              "";
          csv << method << ',' << n << ',' << period / n << ','
              << (h.failure.empty() ? bench::scientific(measured) : "") << ','
              << error << ',' << time.median << ',' << time.min << ','
              << time.max << '\n';
          std::printf("  %-15s %4u steps/period: period error %s, %.3f s "
                      "(%.3f-%.3f)%s%s\n",
                      method.c_str(),
                      n,
                      error.empty() ? "-" : error.c_str(),
                      time.median,
                      time.min,
                      time.max,
                      h.failure.empty() ? "" : "; stopped: ",
                      h.failure.c_str());
        }
  }

  void
  creep_study(const Options &options)
  {
    const double P = 3e-3, r = 0.3, t_r = 20;
    const auto   material =
      std::make_shared<StandardLinearSolid>(swing_stiffness, r, t_r);
    const double t_c = material->creep_time();

    // Static deflection of the same discrete rod with the relaxed rigidity.
    double relaxed_tip = 0;
    {
      auto                       model = cantilever(20, swing_elastic_rod(), P);
      TimeIntegrator::Parameters p;
      p.integrator = "quasi-static";
      p.time_step  = 1;
      p.end_time   = 1;
      TimeIntegrator integrator(*model, {}, p);
      VectorType     u = model->create_vector(), v = model->create_vector();
      integrator.run(u, v, nullptr);
      relaxed_tip = model->configuration().position(u, 20)[2];
    }
    std::ofstream csv("time_steps_creep.csv");
    csv.precision(10);
    csv << "integrator,steps_per_creep_time,time_step,error,time_median_s,"
           "time_min_s,time_max_s\n";
    for (const std::string method :
         {"quasi-static", "backward euler", "newmark"})
      for (const unsigned int n : {10u, 20u, 40u, 80u, 160u, 320u})
        {
          std::map<unsigned int, double> tip; // by step
          const auto                     run = [&] {
            auto                       model = cantilever(20, material, P);
            TimeIntegrator::Parameters p;
            p.integrator = method;
            p.time_step  = t_c / n;
            p.end_time   = 10 * t_c;
            TimeIntegrator     integrator(*model, {swing_inertia}, p);
            const unsigned int vertex =
              model->network().rods()[0].vertices.back();
            VectorType u = model->create_vector(), v = model->create_vector();
            std::map<unsigned int, double> deflection;
            integrator.run(u,
                           v,
                           [&](const TimeIntegrator::StepInfo &info,
                               const VectorType               &x,
                               const VectorType &) {
                             deflection[info.step] =
                               model->configuration().position(x, vertex)[2];
                           });
            return deflection;
          };
          const bench::Statistics time =
            timed<std::map<unsigned int, double>>(options.repeats, tip, run);
          double error = 0;
          for (const unsigned int k : {1u, 3u, 10u})
            {
              const double expected =
                relaxed_tip * (1 - r / (1 + r) * std::exp(-double(k)));
              error = std::max(error, std::abs(tip.at(k * n) / expected - 1));
            }
          csv << method << ',' << n << ',' << t_c / n << ',' << error << ','
              << time.median << ',' << time.min << ',' << time.max << '\n';
          std::printf("  %-15s %4u steps/t_c: creep error %.3e, %.3f s "
                      "(%.3f-%.3f)\n",
                      method.c_str(),
                      n,
                      error,
                      time.median,
                      time.min,
                      time.max);
        }
  }

  void
  stability_study()
  {
    const double  T = cantilever_period();
    std::ofstream csv("time_steps_stability.csv");
    csv.precision(10);
    csv << "integrator,steps_per_period,time_step,completed,steps,"
           "energy_drift,time_reached,message\n";
    for (const std::string method : {"newmark", "midpoint", "backward euler"})
      for (const unsigned int n : {400u, 200u, 100u, 50u, 25u, 12u, 6u})
        {
          auto               model = cantilever(20, swing_elastic_rod(), 2.0);
          std::ostringstream log;
          const SwingHistory h =
            released_swing(*model, method, T / n, 10 * T, &log);
          // Halved steps leave a line "... failed (...); halving" each.
          unsigned int halved = 0;
          for (std::size_t at = log.str().find("halving");
               at != std::string::npos;
               at = log.str().find("halving", at + 1))
            ++halved;
          // No step recorded: no drift to report (an empty CSV field).
          const std::string drift =
            h.energy.empty() ? "" : bench::scientific(energy_drift(h));
          const double reached = h.time.empty() ? 0 : h.time.back();
          csv << method << ',' << n << ',' << T / n << ',' << h.failure.empty()
              << ',' << h.time.size() << ',' << drift << ',' << reached << ",\""
              << h.failure << "\"\n";
          std::printf("  %-15s %4u steps/period: %s, %zu steps (%u halved), "
                      "energy drift %s%s%s\n",
                      method.c_str(),
                      n,
                      h.failure.empty() ? "completed" : "STOPPED",
                      h.time.size(),
                      halved,
                      drift.empty() ? "-" : drift.c_str(),
                      h.failure.empty() ? "" : ": ",
                      h.failure.c_str());
        }
  }

  void
  benchmark(const Options &options)
  {
    std::istringstream studies(options.studies);
    std::string        study;
    while (std::getline(studies, study, ','))
      {
        std::printf("== %s ==\n", study.c_str());
        if (study == "period")
          period_study(options);
        else if (study == "creep")
          creep_study(options);
        else if (study == "stability")
          stability_study();
        else
          throw std::invalid_argument("unknown study \"" + study +
                                      "\"; known: period, creep, stability");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("time_steps", argc, argv, benchmark);
}
