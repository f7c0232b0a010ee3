// The free Moebius band (Starostin & van der Heijden 2007) followed in its
// width: the closed Wunderlich ribbon with a half turn of its frame, held
// against rigid motions only, started in the narrow limit from the clamped
// band of scenes/moebius_band.prm (where the clamps hold nothing,
// tests/validation/moebius_band.cc) and widened by Newton at each width
// (secant predictor, the width step halved where Newton fails). Prints per
// converged state the normalized energy V / (D w) with the half-width w,
// the largest |eta' w| by central differences (1 on the edge singularity)
// and the stability count; doc/ribbons.md, "Validation: the Moebius band".
//
// With --uncoupled 1 the band is widened with eta' uncoupled across its
// closure (Rod::closure_coupling = 0: one-sided differences on both sides,
// eta free to jump there, as beside the clamp of the paper's band), and
// the coupling is then raised to 1 at the last width.
//
// Usage: moebius_free_band [--segments n] [--to w] [--step w] [--report w]
// [--uncoupled 1] (ring segments, default 148; the last half-width,
// default pi/30; the first width step, default 0.005; a half-width to land
// on exactly, default pi/30)
#include <bench/options.h>
#include <cstdio>
#include <functional>
#include <tests/common/moebius_band.h>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads   = 1;
    unsigned int segments  = 148;
    double       to        = M_PI / 30;
    double       step      = 0.005;
    double       report    = M_PI / 30;
    bool         uncoupled = false;

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::number("--segments", segments, 8),
              bench::real("--to", to),
              bench::real("--step", step),
              bench::real("--report", report),
              bench::flag("--uncoupled", uncoupled)};
    }
  };

  /// The free band of half-width @p half_width through @p points, with
  /// D w = 1 (so that its energy is V / (D w)) and eta' coupled across the
  /// closure by @p coupling.
  std::unique_ptr<RodModel>
  band_model(const std::vector<Vector3> &points,
             const double                half_width,
             const double                coupling)
  {
    return moebius::free_band(points, 2 * half_width, 1 / half_width, coupling);
  }

  /// Newton's absolute tolerance at @p segments segments: the rounding
  /// floor of the residual grows as N^2 (4e-10 at 148, 5e-9 at 296).
  double
  tolerance(const unsigned int segments)
  {
    return 2e-9 * std::pow(segments / 148., 2);
  }

  /// A band's state while it is followed in a parameter.
  struct Path
  {
    std::unique_ptr<RodModel> model;
    VectorType                u;
    moebius::NewtonResult     newton;
  };

  /**
   * Follows @p path from the parameter @p from towards @p to (either way
   * up) by Newton at each value: secant predictor, the step @p step halved
   * where Newton fails and grown by half after a quick convergence,
   * landing on @p land exactly. @p build makes the model at a value;
   * @p print reports each converged one. Returns the last value reached.
   */
  double
  follow(Path                                                   &path,
         double                                                  from,
         const double                                            to,
         double                                                  step,
         const double                                            land,
         const unsigned int                                      segments,
         const std::function<std::unique_ptr<RodModel>(double)> &build,
         const std::function<void(double)>                      &print)
  {
    VectorType previous       = path.u;
    double     previous_value = from;
    while (from < to && step > 1e-8 * to)
      {
        double next = std::min(from + step, to);
        if (from < land && next > land)
          next = land;
        VectorType trial = path.u;
        if (previous_value < from)
          {
            const double ratio = (next - from) / (from - previous_value);
            trial.add(ratio, path.u);
            trial.add(-ratio, previous);
          }
        auto       model = build(next);
        const auto result =
          moebius::newton(*model, trial, 0, tolerance(segments), 25);
        if (!result.converged)
          {
            step /= 2;
            continue;
          }
        previous       = path.u;
        previous_value = from;
        path.u         = trial;
        path.model     = std::move(model);
        path.newton    = result;
        from           = next;
        print(from);
        if (result.iterations <= 5)
          step *= 1.5;
      }
    return from;
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

    const std::vector<Vector3> &points   = clamped.centreline;
    const double                coupling = options.uncoupled ? 0 : 1;
    double                      width    = narrow / 2;
    Path                        path;
    path.model  = band_model(points, width, coupling);
    path.u      = moebius::free_state(*path.model, clamped);
    path.newton = moebius::newton(*path.model, path.u, 1e-11, 1e-12);
    if (!path.newton.converged)
      throw std::runtime_error("the narrow free band did not converge");
    std::printf("%10s %9s %12s %10s %9s %6s %9s %10s\n",
                "w",
                "coupling",
                "V/(D w)",
                "/pi",
                "|eta'w|",
                "iter",
                "negative",
                "|r|");
    const auto print = [&](const double w, const double t) {
      const auto band =
        moebius::band_state(*path.model, path.u, options.segments);
      std::printf("%10.6f %9.6f %12.6f %10.6f %9.6f %6u %9u %10.2e\n",
                  w,
                  t,
                  band.energy,
                  band.energy / M_PI,
                  moebius::edge_ratio(band, 2 * w),
                  path.newton.iterations,
                  path.newton.negative_eigenvalues,
                  path.newton.residual);
      std::fflush(stdout);
    };
    print(width, coupling);

    width = follow(
      path,
      width,
      options.to,
      options.step,
      options.report,
      options.segments,
      [&](const double w) { return band_model(points, w, coupling); },
      [&](const double w) { print(w, coupling); });
    if (width < options.to)
      {
        std::printf("stopped: Newton fails beyond w = %.6f\n", width);
        return;
      }
    if (!options.uncoupled)
      return;
    const double reached = follow(
      path,
      0,
      1,
      0.05,
      1,
      options.segments,
      [&](const double t) { return band_model(points, width, t); },
      [&](const double t) { print(width, t); });
    if (reached < 1)
      std::printf("stopped: Newton fails beyond the coupling %.6f\n", reached);
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
