// The free Moebius band (Starostin & van der Heijden 2007) followed in its
// width: the closed Wunderlich ribbon with a half turn of its frame, held
// against rigid motions only, started in the narrow limit from the clamped
// band of scenes/moebius_band.prm (where the clamps hold nothing,
// tests/validation/moebius_band.cc) and widened by Newton at each width
// (secant predictor, the width step halved where Newton fails). Prints per
// converged width the normalized energy V / (D w) with the half-width w,
// the largest |eta' w| (1 on the edge singularity) and the stability count;
// doc/ribbons.md, "Validation: the Moebius band".
//
// Usage: moebius_free_band [--segments n] [--to w] [--step w] [--report w]
// (ring segments, default 148; the last half-width, default pi/30; the
// first width step, default 0.005; a half-width to land on exactly,
// default pi/30)
#include <bench/options.h>
#include <cstdio>
#include <tests/common/moebius_band.h>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads  = 1;
    unsigned int segments = 148;
    double       to       = M_PI / 30;
    double       step     = 0.005;
    double       report   = M_PI / 30;

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::number("--segments", segments, 8),
              bench::real("--to", to),
              bench::real("--step", step),
              bench::real("--report", report)};
    }
  };

  /// The free band of half-width @p half_width through @p points, with
  /// D w = 1 (so that its energy is V / (D w)).
  std::unique_ptr<RodModel>
  band_model(const std::vector<Vector3> &points, const double half_width)
  {
    return moebius::free_band(points, 2 * half_width, 1 / half_width);
  }

  /// Newton's absolute tolerance at @p segments segments: the rounding
  /// floor of the residual grows as N^2 (4e-10 at 148, 5e-9 at 296).
  double
  tolerance(const unsigned int segments)
  {
    return 2e-9 * std::pow(segments / 148., 2);
  }

  void
  benchmark(const Options &options)
  {
    // The clamped band in the narrow limit, D = 1 (h = w / 2).
    constexpr double narrow  = 1e-5;
    const auto       clamped = moebius::solve_clamped(
      options.segments + 1,
      "    set Young's modulus = 9.6e16\n    set Width = 1e-5\n"
            "    set Thickness = 5e-6\n");
    std::printf("clamped band, narrow limit: V / (D w) = %.6f\n",
                clamped.energy / (narrow / 2));

    const std::vector<Vector3> &points = clamped.centreline;
    double                      width  = narrow / 2;
    auto                        model  = band_model(points, width);
    VectorType                  u = moebius::free_state(*model, clamped, true);
    auto                        done = moebius::newton(*model, u, 1e-11, 1e-12);
    if (!done.converged)
      throw std::runtime_error("the narrow free band did not converge");
    std::printf("%10s %12s %10s %9s %6s %9s %10s\n",
                "w",
                "V/(D w)",
                "/pi",
                "|eta'w|",
                "iter",
                "negative",
                "|r|");
    const auto print = [&]() {
      const auto band = moebius::band_state(*model, u, options.segments);
      std::printf("%10.6f %12.6f %10.6f %9.6f %6u %9u %10.2e\n",
                  width,
                  band.energy,
                  band.energy / M_PI,
                  moebius::edge_ratio(band, 2 * width),
                  done.iterations,
                  done.negative_eigenvalues,
                  done.residual);
      std::fflush(stdout);
    };
    print();

    VectorType previous       = u;
    double     previous_width = width;
    double     step           = options.step;
    while (width < options.to && step > 1e-7)
      {
        double next = std::min(width + step, options.to);
        if (width < options.report && next > options.report)
          next = options.report;
        // Secant predictor from the last two widths.
        VectorType trial = u;
        if (previous_width < width)
          trial.add((next - width) / (width - previous_width), u);
        if (previous_width < width)
          trial.add(-(next - width) / (width - previous_width), previous);
        auto trial_model = band_model(points, next);
        auto result      = moebius::newton(*trial_model,
                                      trial,
                                      0,
                                      tolerance(options.segments),
                                      25);
        if (!result.converged)
          {
            step /= 2;
            continue;
          }
        previous       = u;
        previous_width = width;
        u              = trial;
        width          = next;
        model          = std::move(trial_model);
        done           = result;
        print();
        if (result.iterations <= 5)
          step *= 1.5;
      }
    if (width < options.to)
      std::printf("stopped: Newton fails beyond w = %.6f\n", width);
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark<Options>("moebius_free_band",
                                       argc,
                                       argv,
                                       benchmark);
}
