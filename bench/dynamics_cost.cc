// Cost of a dynamic time step against a static Newton iteration (issue 35),
// on the welded square lattice of issue 37: n x n cells of beams of length
// 0.1 in 10 segments, EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67, director
// d1 = e_z (the generator's), pinned at its four corners, mass per length 0.05
// kg/m and twist inertia per length 2.5e-4 kg m (0.05 (I1 + I2) / A),
// consistent mass.
//
// - cost: the lattice in free vibration, started at rest in its lowest
//   mode (largest displacement --amplitude m). Per integrator: the wall
//   time of each time step of TimeIntegrator::run (from one converged step
//   to the next, everything included: predictor, Newton, checks, commit),
//   median over --steps steps after two, and its Newton iterations; against
//   the median of --repeats static Newton iterations of the same model at
//   the same state: one residual and one tangent assembly (constrained), the
//   factorization of the tangent (symbolic analysis kept, as in time
//   stepping) and one solve, the work of an iteration of NewtonSolver.
//   Steps of T / --steps-per-period, T the lowest mode's period.
// - period: the lowest mode's period measured by the zero crossings of
//   the modal coordinate phi.M u over 2.5 periods, against 2 pi / omega of
//   the generalized eigenproblem K phi = omega^2 M phi of the same discrete
//   lattice (so that the error is the time stepping's alone), at the steps
//   per period that the second-order period error predicts for 1 %:
//   (omega h)^2 / 12 for newmark and midpoint, (omega h)^2 / 3 for
//   backward euler; and the wall time of one period (the whole run over
//   2.5).
//
// Usage: dynamics_cost [--study cost,period] [--cells 10,20,35]
// [--period-cells 10,35] [--steps 10] [--repeats 5] [--rotary-inertia auto|0]
// [--steps-per-period 20] [--amplitude 1e-4]
// [--integrators "backward euler,newmark,midpoint"] [--threads 1]
// [--cpu-clock 0|1]: with --cpu-clock 1 the cost study times the process's
// CPU time instead of the wall time (one thread: the same work, without the
// waits of a machine shared with other jobs).
#include <deal.II/base/parameter_handler.h>

#include <core/mass_matrix.h>
#include <io/scene.h>
#include <solvers/time/time_integrator.h>

#include <Eigen/Eigenvalues>
#include <bench/options.h>
#include <bench/timing.h>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads          = 1;
    unsigned int repeats          = 5;
    unsigned int steps            = 10;
    unsigned int steps_per_period = 20;
    double       amplitude        = 1e-4;
    double       tolerance        = 0; ///< 0: the scene's default
    /// TimeIntegrator::Parameters::modified_newton (0: full Newton).
    bool modified_newton = true;
    /// Time the cost study by the process's CPU time (else wall time).
    bool        cpu_clock    = false;
    std::string studies      = "cost,period";
    std::string cells        = "10,20,35";
    std::string period_cells = "10,35";
    std::string integrators  = "backward euler,newmark,midpoint";
    /// The scene's "Rotary inertia per length" (auto: half the twist
    /// inertia; 0: none), to price the rotary inertia of the sections.
    std::string rotary_inertia = "auto";

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::number("--repeats", repeats, 1),
              bench::number("--steps", steps, 1),
              bench::number("--steps-per-period", steps_per_period, 2),
              bench::real("--amplitude", amplitude),
              bench::real("--tolerance", tolerance),
              bench::flag("--modified-newton", modified_newton),
              bench::flag("--cpu-clock", cpu_clock),
              bench::text("--study", studies),
              bench::text("--cells", cells),
              bench::text("--period-cells", period_cells),
              bench::text("--integrators", integrators),
              bench::text("--rotary-inertia", rotary_inertia)};
    }
  };

  /// Whether read_clock() reads the CPU time (--cpu-clock).
  bool cpu_clock = false;

  /// Seconds, wall or the process's CPU time (--cpu-clock).
  double
  read_clock()
  {
    if (!cpu_clock)
      return bench::now();
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  /// The items of the comma-separated @p list.
  std::vector<std::string>
  items(const std::string &list)
  {
    std::vector<std::string> result;
    std::istringstream       in(list);
    std::string              item;
    while (std::getline(in, item, ','))
      result.push_back(item);
    return result;
  }

  /// The scene of the header with @p cells x @p cells cells.
  Scene
  lattice_scene(const unsigned int cells, const std::string &rotary_inertia)
  {
    const std::string  n = std::to_string(cells);
    std::ostringstream s;
    s << "subsection Geometry\n  set Generator = square lattice\n"
      << "  set Cells = " << n << ", " << n << "\n  set Beam length = 0.1\n"
      << "  set Segments = 10\nend\n"
      << "subsection Material\n  set Mass per length = 0.05\n"
      << "  set Twist inertia per length = 2.5e-4\n"
      << "  set Rotary inertia per length = " << rotary_inertia << "\n"
      << "  subsection linear elastic\n    set Stiffness input = direct\n"
      << "    set EA = 1e5\n    set EI1 = 400\n    set EI2 = 100\n"
      << "    set GJ = 67\n  end\nend\nsubsection Supports\n"
      << "  set Pinned vertices = @n_0_0, @n_" << n << "_0, @n_0_" << n
      << ", @n_" << n << "_" << n << "\nend\nsubsection Solver\n"
      << "  set Method = time stepping\n  subsection Time stepping\n"
      << "    set Time step = 1\n  end\nend\n";
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(s.str());
    return Scene(prm);
  }

  /// The lowest mode of a lattice: omega and phi with phi.M phi = 1.
  struct Mode
  {
    double     omega;
    VectorType shape;
  };

  /**
   * The lowest eigenpair of K phi = omega^2 M phi (K the constrained
   * tangent at u = 0, M the constrained consistent mass) by block inverse
   * iteration with Rayleigh-Ritz on 4 vectors: the block converges as
   * (omega_1 / omega_5)^2 per iteration, whatever the multiplicity of the
   * lowest modes; stopped at a change of omega^2 below 1e-12. The massless
   * rows (junction quaternions) follow statically, as in the dynamics.
   */
  Mode
  lowest_mode(const RodModel &model, const std::vector<RodInertia> &inertia)
  {
    MatrixType K, M;
    model.initialize_matrix(K);
    model.assemble(model.create_vector(), 0.0, nullptr, &K, true);
    assemble_mass_matrix(model, inertia, MassKind::consistent, M, true);
    const auto solver = TangentFactorization::create(K, "auto");
    solver->factorize();
    const unsigned int      b = 4;
    std::vector<VectorType> x(b, model.create_vector()), y = x;
    for (unsigned int j = 0; j < b; ++j)
      for (unsigned int i = 0; i < M.m(); ++i)
        x[j][i] = std::sin(0.37 * (j + 1) * i + j);
    double lambda = 0, change = 1;
    for (unsigned int it = 0; it < 200 && change > 1e-12; ++it)
      {
        VectorType mx = model.create_vector();
        for (unsigned int j = 0; j < b; ++j)
          {
            M.vmult(mx, x[j]);
            solver->solve(mx, y[j]);
          }
        Eigen::MatrixXd kr(b, b), mr(b, b);
        VectorType      ky = model.create_vector(), my = ky;
        for (unsigned int j = 0; j < b; ++j)
          {
            K.vmult(ky, y[j]);
            M.vmult(my, y[j]);
            for (unsigned int i = 0; i < b; ++i)
              {
                kr(i, j) = y[i] * ky;
                mr(i, j) = y[i] * my;
              }
          }
        const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(
          kr,
          mr);
        for (unsigned int j = 0; j < b; ++j)
          {
            x[j] = 0;
            for (unsigned int i = 0; i < b; ++i)
              x[j].add(ritz.eigenvectors()(i, j), y[i]);
          }
        change = std::abs(ritz.eigenvalues()[0] / lambda - 1);
        lambda = ritz.eigenvalues()[0];
      }
    VectorType mx = model.create_vector();
    M.vmult(mx, x[0]);
    x[0] /= std::sqrt(x[0] * mx);
    return {std::sqrt(lambda), x[0]};
  }

  /// @p mode scaled so that its largest DoF is @p amplitude.
  VectorType
  initial_state(const Mode &mode, const double amplitude)
  {
    VectorType u = mode.shape;
    u *= amplitude / u.linfty_norm();
    return u;
  }

  /// The parts of a static Newton iteration, as NewtonSolver does one:
  /// residual, tangent, numeric factorization, solve; medians (min-max).
  struct Iteration
  {
    bench::Statistics whole, residual, tangent, factorize, solve;
  };

  /// Median times of @p repeats static Newton iterations of @p model at
  /// @p u, after one that makes the symbolic analysis.
  Iteration
  newton_iteration(const RodModel    &model,
                   const VectorType  &u,
                   const unsigned int repeats)
  {
    MatrixType K;
    model.initialize_matrix(K);
    VectorType                r = model.create_vector(), du = r;
    TangentFactorizationCache cache;
    std::vector<double>       parts[5];
    for (unsigned int k = 0; k <= repeats; ++k)
      {
        const double t0 = read_clock();
        model.assemble(u, 0.0, &r, nullptr, true);
        const double t1 = read_clock();
        model.assemble(u, 0.0, nullptr, &K, true);
        const double t2     = read_clock();
        const auto   solver = cache.get(K, "auto");
        solver->factorize();
        const double t3 = read_clock();
        solver->solve(r, du);
        const double t4 = read_clock();
        parts[0].push_back(t1 - t0);
        parts[1].push_back(t2 - t1);
        parts[2].push_back(t3 - t2);
        parts[3].push_back(t4 - t3);
        parts[4].push_back(t4 - t0);
      }
    // The first iteration is a warm-up (the symbolic analysis).
    for (auto &p : parts)
      p.erase(p.begin());
    return {bench::statistics(parts[4]),
            bench::statistics(parts[0]),
            bench::statistics(parts[1]),
            bench::statistics(parts[2]),
            bench::statistics(parts[3])};
  }

  /// What a dynamic run gives: its step times, Newton iterations, the
  /// modal coordinate per step, and the solver's message if it stopped.
  struct Run
  {
    std::vector<double> step_time, iterations, time, modal;
    double              wall = 0;
    std::string         failure;
  };

  /// Free vibration of the lattice of @p scene from @p u0 at rest with
  /// @p integrator, steps @p h to @p end_time, Newton to the relative
  /// --tolerance (0: the scene's) and --modified-newton of @p options.
  Run
  free_vibration(const Scene       &scene,
                 const Mode        &mode,
                 const VectorType  &u0,
                 const std::string &integrator,
                 const double       h,
                 const double       end_time,
                 const Options     &options)
  {
    const auto                 model = scene.build_model();
    TimeIntegrator::Parameters p     = scene.time_stepping;
    p.integrator                     = integrator;
    p.time_step                      = h;
    p.end_time                       = end_time;
    p.load_factor                    = [](double) { return 0.0; };
    p.progress_interval              = 0;
    p.modified_newton                = options.modified_newton;
    if (options.tolerance > 0)
      p.relative_tolerance = options.tolerance;
    MatrixType mass;
    assemble_mass_matrix(*model, scene.inertia(), p.mass, mass, true);
    VectorType modal_force = model->create_vector();
    mass.vmult(modal_force, mode.shape);
    Run            run;
    VectorType     u = u0, v = model->create_vector();
    TimeIntegrator stepper(*model, scene.inertia(), p);
    const double   start = bench::now();
    double         last  = read_clock();
    try
      {
        stepper.run(u,
                    v,
                    [&](const TimeIntegrator::StepInfo &info,
                        const VectorType               &x,
                        const VectorType &) {
                      const double now = read_clock();
                      run.step_time.push_back(now - last);
                      run.iterations.push_back(info.iterations);
                      run.time.push_back(info.time);
                      run.modal.push_back(modal_force * x);
                      last = now;
                    });
      }
    catch (const SolverFailure &e)
      {
        run.failure = e.what();
      }
    run.wall = bench::now() - start;
    return run;
  }

  /// Median of @p samples from the third on (the first steps set up the
  /// factorization's analysis and warm the caches).
  double
  steady_median(const std::vector<double> &samples)
  {
    if (samples.size() < 3)
      return std::nan("");
    return bench::statistics({samples.begin() + 2, samples.end()}).median;
  }

  void
  cost_study(const Options &options)
  {
    cpu_clock = options.cpu_clock;
    std::printf("cells  DoFs     integrator      Newton iteration s      "
                "time step s (median, min-max)   ratio  iterations/step\n");
    for (const std::string &c : items(options.cells))
      {
        const Scene scene =
          lattice_scene(std::stoul(c), options.rotary_inertia);
        const auto       model = scene.build_model();
        const Mode       mode  = lowest_mode(*model, scene.inertia());
        const double     h  = 2 * M_PI / mode.omega / options.steps_per_period;
        const VectorType u0 = initial_state(mode, options.amplitude);
        const Iteration  iteration =
          newton_iteration(*model, u0, options.repeats);
        const bench::Statistics &newton = iteration.whole;
        std::printf("%5s  static Newton iteration: residual %s, tangent %s, "
                    "factorize %s, solve %s s\n",
                    c.c_str(),
                    bench::format_time(iteration.residual).c_str(),
                    bench::format_time(iteration.tangent).c_str(),
                    bench::format_time(iteration.factorize).c_str(),
                    bench::format_time(iteration.solve).c_str());
        for (const std::string &integrator : items(options.integrators))
          {
            const Run                 run = free_vibration(scene,
                                           mode,
                                           u0,
                                           integrator,
                                           h,
                                           (options.steps + 2.5) * h,
                                           options);
            const std::vector<double> steady(run.step_time.begin() + 2,
                                             run.step_time.end());
            const bench::Statistics   step = bench::statistics(steady);
            std::printf("%5s  %-8u %-15s %s  %s  %.2f  %.1f%s%s\n",
                        c.c_str(),
                        model->layout().n_dofs(),
                        integrator.c_str(),
                        bench::format_time(newton).c_str(),
                        bench::format_time(step).c_str(),
                        step.median / newton.median,
                        steady_median(run.iterations),
                        run.failure.empty() ? "" : "; stopped: ",
                        run.failure.c_str());
            std::fflush(stdout);
          }
      }
  }

  /// Period from the zero crossings of the modal coordinate (linear
  /// interpolation between steps); NaN with fewer than three.
  double
  zero_crossing_period(const Run &run)
  {
    std::vector<double> crossings;
    for (std::size_t i = 1; i < run.modal.size(); ++i)
      if ((run.modal[i - 1] > 0) != (run.modal[i] > 0))
        crossings.push_back(run.time[i - 1] +
                            (run.time[i] - run.time[i - 1]) * run.modal[i - 1] /
                              (run.modal[i - 1] - run.modal[i]));
    if (crossings.size() < 3)
      return std::nan("");
    return 2 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  }

  void
  period_study(const Options &options)
  {
    std::printf("cells  DoFs     integrator      period s      steps/period  "
                "period error  predicted  wall s per period (median, "
                "min-max)\n");
    for (const std::string &c : items(options.period_cells))
      {
        const Scene scene =
          lattice_scene(std::stoul(c), options.rotary_inertia);
        const auto       model  = scene.build_model();
        const Mode       mode   = lowest_mode(*model, scene.inertia());
        const double     period = 2 * M_PI / mode.omega;
        const VectorType u0     = initial_state(mode, options.amplitude);
        for (const std::string &integrator : items(options.integrators))
          {
            // Steps per period for a 1 % period error: (omega h)^2 / k =
            // 0.01, k = 12 (trapezoidal, midpoint), 3 (backward Euler).
            const double       k = integrator == "backward euler" ? 3 : 12;
            const unsigned int steps =
              std::ceil(2 * M_PI / std::sqrt(0.01 * k));
            const double        h = period / steps;
            std::vector<double> walls;
            Run                 run;
            for (unsigned int r = 0; r < options.repeats; ++r)
              {
                run = free_vibration(scene,
                                     mode,
                                     u0,
                                     integrator,
                                     h,
                                     2.5 * period,
                                     options);
                walls.push_back(run.wall / 2.5);
              }
            const double measured = zero_crossing_period(run);
            const double omega_h  = mode.omega * h;
            std::printf("%5s  %-8u %-15s %.6e  %-12u  %+.3e    %.3e  %s%s%s\n",
                        c.c_str(),
                        model->layout().n_dofs(),
                        integrator.c_str(),
                        period,
                        steps,
                        measured / period - 1,
                        omega_h * omega_h / k,
                        bench::format_time(bench::statistics(walls)).c_str(),
                        run.failure.empty() ? "" : "; stopped: ",
                        run.failure.c_str());
            std::fflush(stdout);
          }
      }
  }

  void
  benchmark(const Options &options)
  {
    for (const std::string &study : items(options.studies))
      {
        std::printf("== %s ==\n", study.c_str());
        if (study == "cost")
          cost_study(options);
        else if (study == "period")
          period_study(options);
        else
          throw std::invalid_argument("unknown study \"" + study +
                                      "\"; known: cost, period");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("dynamics_cost", argc, argv, benchmark);
}
