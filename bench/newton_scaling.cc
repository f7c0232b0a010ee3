// Cost of one Newton iteration against the number of vertices.
//
// A straight rod of length 1 along x (circular section r = 5e-3, E = 1e8,
// G = E/3), clamped at x = 0 (midpoint clamp), with a small transverse tip
// load F = 1e-4 * 3 EI / L^3 in -z (tip deflection 1e-4 L). One Newton
// iteration from u = 0 is
//   assemble: RodModel::assemble(u, 1, &r, &K) on the constrained system,
//   solve:    the Newton solver's direct solver (TangentFactorization:
//             band LU or Amesos KLU, --linear-solver), its numeric
//             factorization and the triangular solves (its one-time set-up,
//             KLU's symbolic analysis, counts in "setup"),
// timed separately, median (min-max), for N = 1e2 ... 1e6 vertices
// (N - 1 segments, about 4 N DoFs). The cost is linear in N when the time
// per vertex stays constant; the program prints the ratios of consecutive
// per-vertex times and the exponent p of t ~ N^p between 1e4 and the largest
// N. As a check that the iteration did solve the linear problem, it prints
// the tip deflection against P L^3 / (3 EI).
//
// Usage: newton_scaling [--threads n] [--repeats n] [--max-vertices n]
// [--linear-solver auto|klu|band] (defaults 1, 5, 100000 and auto; N = 1e6
// gets 3 repeats). The default stops at
// 1e5 because building the model is quadratic in N: RodNetwork::add_rod
// compares every pair of vertices for coincidence, 15 s at 1e5 and an
// estimated 25 min at 1e6 (see doc/performance.md).
#include <core/rod_generators.h>
#include <core/rod_model.h>
#include <materials/cross_section.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/tangent_factorization.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <cmath>
#include <fstream>
#include <iostream>
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

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 5),
              bench::number("--max-vertices", max_vertices),
              bench::text("--linear-solver", linear_solver)};
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
    VectorType u  = model.create_vector();
    VectorType r  = model.create_vector();
    VectorType du = model.create_vector();
    MatrixType K;
    model.initialize_matrix(K);
    const auto direct = TangentFactorization::create(K, linear_solver);
    result.solver     = direct->name();
    result.setup      = bench::now() - start;

    std::vector<double> assemble, factorize, solve, total;
    // One warm-up iteration, then the timed ones; each starts from u = 0.
    for (unsigned int rep = 0; rep <= repeats; ++rep)
      {
        const double t0 = bench::now();
        model.assemble(u, 1.0, &r, &K);
        const double t1 = bench::now();
        direct->factorize();
        const double t2 = bench::now();
        direct->solve(r, du);
        const double t3 = bench::now();
        if (rep > 0)
          {
            assemble.push_back(t1 - t0);
            factorize.push_back(t2 - t1);
            solve.push_back(t3 - t2);
            total.push_back(t3 - t0);
          }
      }
    result.assemble  = bench::statistics(assemble);
    result.factorize = bench::statistics(factorize);
    result.solve     = bench::statistics(solve);
    result.total     = bench::statistics(total);

    // Backward error of the linear solve, |K du - r| / |r|: small while the
    // tip is off means the system is ill-conditioned, not the solve wrong.
    VectorType Kdu = model.create_vector();
    K.vmult(Kdu, du);
    Kdu.add(-1.0, r);
    result.relative_residual = Kdu.l2_norm() / r.l2_norm();

    u.add(-1.0, du);
    const double deflection = -model.configuration().position(u, tip)[2];
    result.tip_ratio        = deflection / (F / (3 * stiffness.EI1));
    return result;
  }

  /// The benchmark proper, run once the command line is read and MPI is
  /// up.
  void
  benchmark(const Options &options)
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
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("newton_scaling", argc, argv, benchmark);
}
