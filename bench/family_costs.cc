// The cost of a stencil of each element family of the welded lattice
// (bench/welded_lattice.h), with its gradient and Hessian, relative to a
// hinge's: the weights ElementFamily::relative_cost() gives the partition
// of the stencils over processes (balanced_share(), doc/performance.md).
// Each family's stencils are evaluated in a loop at a state of small random
// displacements, the median (min-max) of --repeats loops, on one process.
//
//   family_costs [--cells n] [--repeats n] [--threads n]
#include <deal.II/base/mpi.h>

#include <core/rod_model.h>

#include <bench/options.h>
#include <bench/timing.h>
#include <bench/welded_lattice.h>
#include <cstdio>
#include <random>

namespace
{
  using namespace rodnet;

  struct Options
  {
    unsigned int threads = 1;
    unsigned int repeats = 5;
    unsigned int cells   = 20;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 3),
              bench::number("--cells", cells, 1)};
    }
  };

  /// Seconds per stencil of @p family with its Hessian at @p state.
  bench::Statistics
  seconds_per_stencil(const ElementFamily &family,
                      const StencilState  &state,
                      const unsigned int   repeats)
  {
    LocalContribution   local;
    std::vector<double> samples = bench::time_repeats(repeats, [&] {
      for (unsigned int s = 0; s < family.n_stencils(); ++s)
        family.evaluate(s, state, Derivatives::hessian, local);
    });
    for (double &t : samples)
      t /= family.n_stencils();
    return bench::statistics(samples);
  }

  void
  benchmark(const Options &options)
  {
    const auto   model = bench::welded_lattice(options.cells);
    VectorType   u     = model->create_vector();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> noise(-1e-4, 1e-4);
    for (const auto i : u.locally_owned_elements())
      u[i] = noise(random);
    u.compress(dealii::VectorOperation::insert);
    const ModelState   saved = model->state();
    const StencilState state{u, saved.configuration, saved.committed, 0, 1};
    std::printf("welded lattice %u x %u, %u repeats: microseconds per "
                "stencil with its Hessian\n",
                options.cells,
                options.cells,
                options.repeats);
    std::vector<std::pair<std::string, bench::Statistics>> rows;
    double                                                 hinge = 0;
    for (const auto &family : model->element_families())
      if (family->n_stencils() > 0)
        {
          rows.emplace_back(family->name(),
                            seconds_per_stencil(*family,
                                                state,
                                                options.repeats));
          if (family->name() == "hinges")
            hinge = rows.back().second.median;
        }
    for (const auto &[name, s] : rows)
      std::printf("  %-18s %8.3f (%.3f-%.3f)  %6.2f of a hinge's\n",
                  name.c_str(),
                  1e6 * s.median,
                  1e6 * s.min,
                  1e6 * s.max,
                  hinge > 0 ? s.median / hinge : 0.0);
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("family_costs", argc, argv, benchmark);
}
