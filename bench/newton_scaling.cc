// Cost of one Newton iteration against the number of vertices.
//
// A straight rod of length 1 along x (circular section r = 5e-3, E = 1e8,
// G = E/3), clamped at x = 0 (midpoint clamp), with a small transverse tip
// load F = 1e-4 * 3 EI / L^3 in -z (tip deflection 1e-4 L). One Newton
// iteration from u = 0 is
//   assemble: RodModel::assemble(u, 1, &r, &K) on the constrained system,
//   solve:    the Newton solver's direct solver (TangentFactorization:
//             band LU, KLU or MUMPS, --linear-solver), its numeric
//             factorization and the triangular solves (its one-time set-up,
//             KLU's symbolic analysis, counts in "setup"),
// timed separately, median (min-max), for N = 1e2 ... 1e6 vertices
// (N - 1 segments, about 4 N DoFs). The cost is linear in N when the time
// per vertex stays constant; the program prints the ratios of consecutive
// per-vertex times and the exponent p of t ~ N^p between 1e4 and the largest
// N. As a check that the iteration did solve the linear problem, it prints
// the tip deflection against P L^3 / (3 EI).
//
// Then welded square lattices of n x n cells (issue 33): beams of length
// 0.1 in 10 segments, EA = 1e5, EI1 = 400, EI2 = 100, GJ = 67, pinned at
// the four corners, under gravity (0.05 kg/m), n = 10, 20, 40, 57, 80, 111
// up to --max-cells (1e4 to 1.1e6 DoFs). Timed are the first Newton
// iterations (full steps) of the first of two load steps from the flat
// lattice: the states the run goes through, whose tangents are indefinite
// once the net sags far from equilibrium. Per iteration: the residual,
// assemble / factorize / solve and the fill of the factor (its entries
// over those of the tangent; MUMPS stores one triangle, KLU L and U); per
// lattice the time of making the factorization ("analysis": MUMPS's; KLU
// analyses in its first factorize). The median and the largest time per DoF of
// a lattice over those of the previous one show a superlinear jump: with
// KLU's default pivot tolerance (before issue 33) the fill and the time of
// the later iterations grew with the size (doc/performance.md).
//
// Usage: newton_scaling [--threads n] [--repeats n] [--max-vertices n]
// [--linear-solver auto|klu|band|mumps] [--max-cells n] [--iterations n]
// (defaults 1, 5, 100000, auto, 40 and 5; N = 1e6 gets 3 repeats;
// --max-vertices below 100 leaves out the rods, --max-cells below 10 the
// lattices). The rods stop at 1e5 by default because building the model
// is quadratic in N: RodNetwork::add_rod compares every pair of vertices
// for coincidence, 15 s at 1e5 and an estimated 25 min at 1e6 (see
// doc/performance.md).
#include <deal.II/base/parameter_handler.h>

#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <io/scene.h>
#include <materials/cross_section.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/newton/tangent_factorization.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <bench/welded_lattice.h>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads       = 1;
    unsigned int repeats       = 5;
    unsigned int max_vertices  = 100000;
    std::string  linear_solver = "auto";
    unsigned int max_cells     = 40;
    unsigned int iterations    = 5;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 5),
              bench::number("--max-vertices", max_vertices),
              bench::text("--linear-solver", linear_solver),
              bench::number("--max-cells", max_cells),
              bench::number("--iterations", iterations, 1)};
    }
  };

  /// Peak resident memory of the process (VmHWM) in MB.
  double
  peak_memory_mb()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("VmHWM:", 0) == 0)
        return std::stod(line.substr(6)) / 1024.;
    return std::nan("");
  }

  /// The wall times of the parts of one Newton iteration.
  struct IterationTimes
  {
    double assemble, factorize, solve;
  };

  /// Newton iterations on a model from u = 0: their vectors, tangent and
  /// factorization, and the time of each part of an iteration. The
  /// factorization refers to K: the object stays where it is made.
  struct TimedNewton
  {
    TimedNewton(RodModel &model, const std::string &linear_solver)
        : model(model)
        , u(model.create_vector())
        , r(model.create_vector())
        , du(model.create_vector())
    {
      model.initialize_matrix(K);
      const double start = bench::now();
      direct             = TangentFactorization::create(K, linear_solver);
      analysis           = bench::now() - start;
    }

    TimedNewton(TimedNewton &&) = delete;

    /// Assembles the residual r and the tangent K at u and @p load_factor,
    /// factorizes K and solves K du = r, timing each part.
    IterationTimes
    iterate(const double load_factor)
    {
      const double t0 = bench::now();
      model.assemble(u, load_factor, &r, &K);
      const double t1 = bench::now();
      direct->factorize();
      const double t2 = bench::now();
      direct->solve(r, du);
      const double t3 = bench::now();
      return {t1 - t0, t2 - t1, t3 - t2};
    }

    RodModel                             &model;
    VectorType                            u, r, du;
    MatrixType                            K;
    std::unique_ptr<TangentFactorization> direct;
    /// The time of making the factorization: MUMPS's analysis (KLU's
    /// comes with its first factorize()).
    double analysis;
  };

  struct Result
  {
    unsigned int      n_dofs;
    double            setup;
    bench::Statistics assemble, factorize, solve, total;
    std::string       solver;
    double            tip_ratio;
    double            relative_residual;
  };

  Result
  run_case(const unsigned int n_vertices,
           const unsigned int repeats,
           const std::string &linear_solver)
  {
    const double       start = bench::now();
    const double       E     = 1e8;
    const RodStiffness stiffness =
      stiffness_from_section(E, E / 3, circle_section(5e-3));
    const double F = 1e-4 * 3 * stiffness.EI1;

    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3::Zero(),
                                          Vector3::UnitX(),
                                          n_vertices - 1,
                                          true),
                     false,
                     Vector3::UnitY(),
                     "simple");
    network->create_triangulation();
    RodModel model(std::move(network),
                   {std::make_shared<LinearElasticRod>(stiffness)});
    model.clamp_end("clamp", 0, true);
    const unsigned int tip = model.network().rods()[0].vertices.back();
    model.add_point_force(tip, Vector3(0, 0, -F));
    model.finalize();

    Result result;
    result.n_dofs = model.layout().n_dofs();
    TimedNewton newton(model, linear_solver);
    result.solver = newton.direct->name();
    result.setup  = bench::now() - start;

    std::vector<double> assemble, factorize, solve, total;
    // One warm-up iteration, then the timed ones; each starts from u = 0.
    for (unsigned int rep = 0; rep <= repeats; ++rep)
      {
        const IterationTimes t = newton.iterate(1.0);
        if (rep > 0)
          {
            assemble.push_back(t.assemble);
            factorize.push_back(t.factorize);
            solve.push_back(t.solve);
            total.push_back(t.assemble + t.factorize + t.solve);
          }
      }
    result.assemble  = bench::statistics(assemble);
    result.factorize = bench::statistics(factorize);
    result.solve     = bench::statistics(solve);
    result.total     = bench::statistics(total);

    // Backward error of the linear solve, |K du - r| / |r|: small while the
    // tip is off means the system is ill-conditioned, not the solve wrong.
    VectorType Kdu = model.create_vector();
    newton.K.vmult(Kdu, newton.du);
    Kdu.add(-1.0, newton.r);
    result.relative_residual = Kdu.l2_norm() / newton.r.l2_norm();

    newton.u.add(-1.0, newton.du);
    const double deflection = -model.configuration().position(newton.u, tip)[2];
    result.tip_ratio        = deflection / (F / (3 * stiffness.EI1));
    return result;
  }

  /// The straight rods of the header, N = 1e2 ... --max-vertices.
  void
  rod_benchmark(const Options &options)
  {
    std::cout << "One Newton iteration (assemble + direct solve), clamped "
                 "straight rod, small tip load; "
              << options.threads << " thread(s); median (min-max) in s of "
              << options.repeats
              << " repeats (3 for the largest N if it is 1e6)\n";

    std::vector<unsigned int> sizes;
    for (unsigned int n = 100; n <= options.max_vertices; n *= 10)
      sizes.push_back(n);
    std::vector<Result> results;
    for (const unsigned int n : sizes)
      {
        const unsigned int repeats =
          n >= 1000000 ? std::min(3u, options.repeats) : options.repeats;
        results.push_back(run_case(n, repeats, options.linear_solver));
        const Result &r = results.back();
        char          line[400];
        std::snprintf(
          line,
          sizeof(line),
          "N %8u  DoFs %8u  setup %.3g s  linear solver %s\n"
          "  assemble  %-28s per vertex %.3g us\n"
          "  factorize %-28s per vertex %.3g us\n"
          "  solve     %-28s per vertex %.3g us\n"
          "  total     %-28s per vertex %.3g us\n"
          "  tip deflection / (P L^3 / 3EI) = %.6f  |K du - r|/|r| = %.1e  "
          "peak memory %.0f MB\n",
          n,
          r.n_dofs,
          r.setup,
          r.solver.c_str(),
          bench::format_time(r.assemble).c_str(),
          1e6 * r.assemble.median / n,
          bench::format_time(r.factorize).c_str(),
          1e6 * r.factorize.median / n,
          bench::format_time(r.solve).c_str(),
          1e6 * r.solve.median / n,
          bench::format_time(r.total).c_str(),
          1e6 * r.total.median / n,
          r.tip_ratio,
          r.relative_residual,
          peak_memory_mb());
        std::cout << line << std::flush;
      }

    std::cout << "\nLinearity: ratio of per-vertex times to those at the "
                 "previous N (1 = linear)\n";
    for (unsigned int i = 1; i < results.size(); ++i)
      {
        auto ratio = [&](const bench::Statistics Result::*field) {
          return ((results[i].*field).median / sizes[i]) /
                 ((results[i - 1].*field).median / sizes[i - 1]);
        };
        char line[200];
        std::snprintf(line,
                      sizeof(line),
                      "  N %8u / %8u: assemble %.2f  factorize %.2f  "
                      "solve %.2f  total %.2f\n",
                      sizes[i],
                      sizes[i - 1],
                      ratio(&Result::assemble),
                      ratio(&Result::factorize),
                      ratio(&Result::solve),
                      ratio(&Result::total));
        std::cout << line;
      }
    if (sizes.size() >= 4)
      {
        const std::size_t a = 2, b = sizes.size() - 1;
        auto exponent = [&](const bench::Statistics Result::*field) {
          return std::log((results[b].*field).median /
                          (results[a].*field).median) /
                 std::log(double(sizes[b]) / sizes[a]);
        };
        char line[200];
        std::snprintf(line,
                      sizeof(line),
                      "  exponent p of t ~ N^p from N = %u to %u: assemble "
                      "%.3f  factorize %.3f  solve %.3f  total %.3f\n",
                      sizes[a],
                      sizes[b],
                      exponent(&Result::assemble),
                      exponent(&Result::factorize),
                      exponent(&Result::solve),
                      exponent(&Result::total));
        std::cout << line;
      }
  }
  /// One Newton iteration of a lattice: its residual before, its times
  /// and the fill of its factor.
  struct LatticeIteration
  {
    double residual, assemble, factorize, solve, fill;

    double
    total() const
    {
      return assemble + factorize + solve;
    }
  };

  /// The first @p iterations full Newton steps of the first load step
  /// (load factor 0.5) of the lattice of @p cells cells; fewer where the
  /// state leaves what the model can assemble (a segment turned by 180
  /// degrees), which is printed. @p analysis: the time of making the
  /// factorization.
  std::vector<LatticeIteration>
  lattice_iterations(RodModel          &model,
                     const unsigned int iterations,
                     const std::string &linear_solver,
                     double            &analysis)
  {
    TimedNewton newton(model, linear_solver);
    analysis = newton.analysis;
    std::vector<LatticeIteration> result;
    try
      {
        for (unsigned int k = 0; k < iterations; ++k)
          {
            const IterationTimes t = newton.iterate(0.5);
            LatticeIteration     it;
            it.residual  = newton.r.l2_norm();
            it.assemble  = t.assemble;
            it.factorize = t.factorize;
            it.solve     = t.solve;
            it.fill =
              newton.direct->factor_entries() / newton.K.n_nonzero_elements();
            result.push_back(it);
            newton.u.add(-1.0, newton.du);
          }
      }
    catch (const std::exception &e)
      {
        std::cout << "  stopped after " << result.size()
                  << " iterations: " << e.what() << "\n";
      }
    return result;
  }

  /// Prints a lattice case's iterations and returns the median and the
  /// largest time per iteration.
  std::pair<double, double>
  report_lattice(const unsigned int                   cells,
                 const double                         n_dofs,
                 const double                         setup,
                 const double                         analysis,
                 const std::vector<LatticeIteration> &iterations)
  {
    std::vector<double> totals;
    char                line[300];
    std::snprintf(line,
                  sizeof(line),
                  "lattice %3u x %-3u DoFs %8.0f  setup %.3g s  analysis "
                  "%.3g s\n",
                  cells,
                  cells,
                  n_dofs,
                  setup,
                  analysis);
    std::cout << line;
    for (std::size_t k = 0; k < iterations.size(); ++k)
      {
        const LatticeIteration &it = iterations[k];
        totals.push_back(it.total());
        std::snprintf(line,
                      sizeof(line),
                      "  iteration %zu  |r| %9.3e  assemble %.3g  factorize "
                      "%.3g  solve %.3g  total %.3g s  fill %.2f\n",
                      k + 1,
                      it.residual,
                      it.assemble,
                      it.factorize,
                      it.solve,
                      it.total(),
                      it.fill);
        std::cout << line;
      }
    if (totals.empty())
      return {std::nan(""), std::nan("")};
    const bench::Statistics t = bench::statistics(totals);
    std::snprintf(line,
                  sizeof(line),
                  "  per iteration: median %.3g s (%.3g us per DoF), largest "
                  "%.3g s (%.3g us per DoF); peak memory %.0f MB\n",
                  t.median,
                  1e6 * t.median / n_dofs,
                  t.max,
                  1e6 * t.max / n_dofs,
                  peak_memory_mb());
    std::cout << line << std::flush;
    return {t.median, t.max};
  }

  /// The lattices of the header, n = 10 ... --max-cells.
  void
  lattice_benchmark(const Options &options)
  {
    std::cout << "\nNewton iterations of the welded lattice under gravity, "
                 "the first "
              << options.iterations << " of its first load step; linear solver "
              << options.linear_solver << "; times in s\n";
    std::vector<double> dofs, median, largest;
    for (const unsigned int cells : {10u, 20u, 40u, 57u, 80u, 111u})
      {
        if (cells > options.max_cells)
          break;
        const double start = bench::now();
        const auto   model = bench::welded_lattice(cells);
        const double setup = bench::now() - start;
        double       analysis;
        const auto   iterations = lattice_iterations(*model,
                                                   options.iterations,
                                                   options.linear_solver,
                                                   analysis);
        dofs.push_back(model->layout().n_dofs());
        const auto [m, l] =
          report_lattice(cells, dofs.back(), setup, analysis, iterations);
        median.push_back(m);
        largest.push_back(l);
      }
    std::cout << "\nLinearity: time per DoF against the previous lattice "
                 "(1 = linear)\n";
    for (std::size_t i = 1; i < dofs.size(); ++i)
      {
        char line[200];
        std::snprintf(line,
                      sizeof(line),
                      "  DoFs %8.0f / %8.0f: median iteration %.2f  largest "
                      "%.2f\n",
                      dofs[i],
                      dofs[i - 1],
                      (median[i] / dofs[i]) / (median[i - 1] / dofs[i - 1]),
                      (largest[i] / dofs[i]) / (largest[i - 1] / dofs[i - 1]));
        std::cout << line;
      }
  }


  /// The benchmark proper, run once the command line is read and MPI is
  /// up: the rods, then the lattices.
  void
  benchmark(const Options &options)
  {
    if (options.max_vertices >= 100)
      rod_benchmark(options);
    if (options.max_cells >= 10)
      lattice_benchmark(options);
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("newton_scaling", argc, argv, benchmark);
}
