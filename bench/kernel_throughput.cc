// K1 of ../shared/BENCHMARKS.md: hinge kernel throughput.
//
// An open rod of N vertices on the helix x = cos t, y = sin t, z = 0.1 t,
// t_i = 2 pi i / 50, circular section of diameter 0.01, E = 1e9 (G = E/3;
// K1 leaves G open and it does not change the cost). The reference frames
// are those of the undeformed helix; the current state is the helix plus
// uniform noise of 1e-3 segment lengths on every coordinate and twists
// uniform in [-0.01, 0.01], set directly as the DoF vector u.
//
// For each N and hinge kernel it times
//  (a) energy + gradient + Hessian assembled into the Trilinos matrix,
//      RodModel::assemble(u, 0, &r, &K): the hinge and the segment (stretch)
//      stencils, the rate counts hinges only;
//  (b) the gradient alone, RodModel::assemble(u, 0, &r, nullptr);
//  (c) the bare loops without global assembly over pre-gathered local DoF
//      vectors: the kernel's evaluate() alone, and evaluate_bending() (the
//      kernel with the material and the chain rule: the local gradient /
//      Hessian of each stencil, as the assembly computes it), and the same
//      for the segments, so that (a) - (c) is the cost of gathering and
//      scattering through deal.II and Trilinos.
// Every figure is the median of the repeats with its range (min-max); the
// rates also go to kernel_throughput.csv in the current directory, from
// which bench/k1_vs_fabsim.gp draws doc/k1_vs_fabsim.png. (a) and (b) are
// set beside the peer's rates at the same N, read from BENCHMARKS.md when
// the program runs (--peers, bench/peer_figures.h) and printed with the date
// of the figure; the rates read go to kernel_throughput_peers.csv.
//
// Usage: kernel_throughput [--threads n] [--repeats n] [--kernel NAME]
// [--vertices N] (defaults 1, 7, both kernels, N = 1e3 and 1e5: the peer
// figures are single-threaded; one kernel and one N for a profile)
// [--peers file] (the peer figures; default ../shared/BENCHMARKS.md beside
// the source tree).
#include <core/rod_model.h>
#include <elements/hinge_kernel.h>
#include <elements/stretch_kernel.h>
#include <materials/cross_section.h>
#include <materials/linear_elastic_rod.h>

#include <bench/options.h>
#include <bench/peer_figures.h>
#include <bench/timing.h>
#include <cmath>
#include <cstdlib>
#include <families/bending_response.h>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace rodnet;

namespace
{
  struct Options
  {
    unsigned int threads = 1;
    unsigned int repeats = 7;
    /// One hinge kernel, or "" for both.
    std::string kernel;
    /// One N, or 0 for 1e3 and 1e5.
    unsigned int vertices = 0;
    std::string  peers    = bench::default_peer_file;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads),
              bench::number("--repeats", repeats, 5),
              bench::text("--kernel", kernel),
              bench::number("--vertices", vertices),
              bench::text("--peers", peers)};
    }
  };

  /// Consumes results so that the compiler keeps the timed loops.
  volatile double sink = 0;

  struct Timings
  {
    bench::Statistics assemble_hessian, assemble_gradient;
    bench::Statistics kernel_hessian, kernel_gradient;
    bench::Statistics local_hessian, local_gradient;
    bench::Statistics segments_hessian, segments_gradient;
  };

  Timings
  run_case(const unsigned int n_vertices,
           const std::string &kernel_name,
           const unsigned int repeats)
  {
    std::vector<Vector3> points;
    for (unsigned int i = 0; i < n_vertices; ++i)
      {
        const double t = 2 * M_PI * i / 50.;
        points.emplace_back(std::cos(t), std::sin(t), 0.1 * t);
      }
    const double segment_length = (points[1] - points[0]).norm();

    auto network = std::make_unique<RodNetwork>();
    // The helix tangent is never parallel to z, so z can fix d1.
    network->add_rod(points, false, Vector3::UnitZ(), kernel_name);
    network->create_triangulation();
    const double E        = 1e9;
    auto         material = std::make_shared<LinearElasticRod>(
      stiffness_from_section(E, E / 3, circle_section(0.005)));
    RodModel model(std::move(network), {material});
    model.finalize();

    VectorType                             u = model.create_vector();
    std::mt19937                           random(20261122);
    std::uniform_real_distribution<double> noise(-1e-3 * segment_length,
                                                 1e-3 * segment_length);
    std::uniform_real_distribution<double> twist(-0.01, 0.01);
    for (unsigned int v = 0; v < model.network().n_vertices(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        u[model.layout().vertex_dof(v, c)] = noise(random);
    for (const SegmentStencil &s : model.layout().segments())
      u[model.layout().twist_dof(s.cell)] = twist(random);
    u.compress(dealii::VectorOperation::insert);

    VectorType r = model.create_vector();
    MatrixType K;
    model.initialize_matrix(K);

    Timings timings;
    timings.assemble_hessian =
      bench::statistics(bench::time_repeats(repeats, [&] {
        sink = sink + model.assemble(u, 0, &r, &K);
      }));
    timings.assemble_gradient =
      bench::statistics(bench::time_repeats(repeats, [&] {
        sink = sink + model.assemble(u, 0, &r, nullptr);
      }));

    // Local DoF vectors gathered once, outside the timing.
    const Configuration       &configuration = model.configuration();
    const auto                &hinges        = model.layout().hinges();
    const auto                &segments      = model.layout().segments();
    std::vector<HingeVector>   hinge_dofs;
    std::vector<SegmentVector> segment_dofs;
    for (const HingeStencil &h : hinges)
      hinge_dofs.push_back(configuration.hinge_dofs(u, h));
    for (const SegmentStencil &s : segments)
      segment_dofs.push_back(configuration.segment_dofs(u, s));
    const HingeKernel &kernel = model.hinge_kernel(0);

    auto kernel_loop = [&](const bool with_hessian) {
      HingeStrains strains;
      double       sum = 0;
      for (unsigned int h = 0; h < hinges.size(); ++h)
        {
          kernel.evaluate(hinge_dofs[h],
                          configuration.hinge_reference(h),
                          strains,
                          with_hessian);
          sum += strains.kappa[0] + strains.gradient(0, 0) +
                 (with_hessian ? strains.hessian[2](0, 0) : 0.);
        }
      sink = sink + sum;
    };
    // The local part of RodModel::assemble: evaluate_bending()
    // (families/bending_response.h), i.e. kernel, material, chain rule
    // (Korner et al. eq. 4.5) and the copy into the local contribution,
    // without gather and scatter.
    auto local_loop = [&](const bool with_hessian) {
      LocalContribution local;
      double            sum = 0;
      for (unsigned int h = 0; h < hinges.size(); ++h)
        {
          const BendingStencil<HingeKernel, HingeReference> stencil{
            kernel,
            hinge_dofs[h],
            configuration.hinge_reference(h),
            *material,
            configuration.voronoi_length(h),
            nullptr,
            Vector3::Zero()};
          evaluate_bending(stencil,
                           0.0,
                           with_hessian ? Derivatives::hessian :
                                          Derivatives::gradient,
                           local);
          sum += local.energy + local.vector[0] +
                 (with_hessian ? local.matrix(0, 0) : 0.);
        }
      sink = sink + sum;
    };
    auto segment_loop = [&](const bool with_hessian) {
      StretchStrain stretch;
      double        sum = 0;
      for (unsigned int s = 0; s < segments.size(); ++s)
        {
          const double l0 = configuration.rest_length(segments[s].cell);
          evaluate_stretch(segment_dofs[s], l0, stretch, with_hessian);
          const MaterialResponse<1> w =
            material->segment_energy(stretch.strain, l0);
          const SegmentVector gradient = w.stress[0] * stretch.gradient;
          sum += w.energy + gradient[0];
          if (with_hessian)
            {
              const SegmentMatrix hessian = w.tangent(0, 0) * stretch.gradient *
                                              stretch.gradient.transpose() +
                                            w.stress[0] * stretch.hessian;
              sum += hessian(0, 0);
            }
        }
      sink = sink + sum;
    };

    timings.kernel_hessian = bench::statistics(
      bench::time_repeats(repeats, [&] { kernel_loop(true); }));
    timings.kernel_gradient = bench::statistics(
      bench::time_repeats(repeats, [&] { kernel_loop(false); }));
    timings.local_hessian = bench::statistics(
      bench::time_repeats(repeats, [&] { local_loop(true); }));
    timings.local_gradient = bench::statistics(
      bench::time_repeats(repeats, [&] { local_loop(false); }));
    timings.segments_hessian = bench::statistics(
      bench::time_repeats(repeats, [&] { segment_loop(true); }));
    timings.segments_gradient = bench::statistics(
      bench::time_repeats(repeats, [&] { segment_loop(false); }));
    return timings;
  }

  /// The line that sets (a) and (b) of @p t at N = @p n beside the peers'
  /// rates at that N, if @p peers has them.
  void
  report_peers(const std::vector<bench::K1PeerFigure> &peers,
               const unsigned int                      n,
               const Timings                          &t)
  {
    const double n_hinges = n - 2;
    for (const bench::K1PeerFigure &peer : peers)
      if (peer.n == n)
        {
          char line[300];
          std::snprintf(line,
                        sizeof(line),
                        "  against %s (one thread, %s): (a) %.2fx its %.3g, "
                        "(b) %.2fx its %.3g\n",
                        peer.code.c_str(),
                        peer.source.c_str(),
                        n_hinges / t.assemble_hessian.median /
                          peer.hessian_rate,
                        peer.hessian_rate,
                        n_hinges / t.assemble_gradient.median /
                          peer.gradient_rate,
                        peer.gradient_rate);
          std::cout << line;
        }
  }

  /// The peers' rates read, for the chart bench/k1_vs_fabsim.gp.
  void
  write_peers(const std::vector<bench::K1PeerFigure> &peers)
  {
    std::ofstream csv("kernel_throughput_peers.csv");
    csv << "N,code,figure,hinges_per_s,date\n";
    for (const bench::K1PeerFigure &peer : peers)
      csv << peer.n << ',' << peer.code << ",assembled_egh,"
          << peer.hessian_rate << ',' << peer.date << '\n'
          << peer.n << ',' << peer.code << ",assembled_gradient,"
          << peer.gradient_rate << ',' << peer.date << '\n';
  }

  /// The benchmark proper, run once the command line is read and MPI is
  /// up.
  void
  benchmark(const Options &options)
  {
    const std::vector<bench::K1PeerFigure> peers =
      bench::read_k1_peers(options.peers);
    write_peers(peers);
    std::cout << "K1 hinge kernel throughput: " << options.threads
              << " thread(s), median (min-max) of " << options.repeats
              << " repeats, rates in hinges/s (N - 2 hinges; the assembled "
                 "figures include the N - 1 segments in the time)\n";
    // Short names of the rows for the CSV, in the order of rows[].
    const char   *keys[] = {"assembled_egh",
                            "assembled_gradient",
                            "kernel_egh",
                            "kernel_gradient",
                            "local_egh",
                            "local_gradient",
                            "segments_egh",
                            "segments_gradient"};
    std::ofstream csv("kernel_throughput.csv");
    csv << "N,kernel,threads,figure,hinges_per_s_median,hinges_per_s_min,"
           "hinges_per_s_max\n";
    const char *rows[] = {"(a) E+g+H assembled into Trilinos matrix",
                          "(b) gradient assembled into vector",
                          "(c) kernel evaluate() with Hessians",
                          "(c) kernel evaluate() gradient only",
                          "(c) local E+g+H: kernel+material+chain",
                          "(c) local E+g: kernel+material+chain",
                          "    segments local E+g+H (time only)",
                          "    segments local E+g (time only)"};
    const std::vector<unsigned int> sizes =
      options.vertices > 0 ? std::vector<unsigned int>{options.vertices} :
                             std::vector<unsigned int>{1000u, 100000u};
    const std::vector<std::string> kernels =
      !options.kernel.empty() ? std::vector<std::string>{options.kernel} :
                                std::vector<std::string>{"simple", "classic"};
    for (const unsigned int n : sizes)
      for (const std::string &kernel : kernels)
        {
          const Timings            t = run_case(n, kernel, options.repeats);
          const bench::Statistics *values[] = {&t.assemble_hessian,
                                               &t.assemble_gradient,
                                               &t.kernel_hessian,
                                               &t.kernel_gradient,
                                               &t.local_hessian,
                                               &t.local_gradient,
                                               &t.segments_hessian,
                                               &t.segments_gradient};
          const double             n_hinges = n - 2;
          std::cout << "\nN = " << n << ", kernel \"" << kernel << "\"\n";
          for (unsigned int i = 0; i < 8; ++i)
            {
              char line[200];
              std::snprintf(line,
                            sizeof(line),
                            "  %-42s time/s %-30s hinges/s %s\n",
                            rows[i],
                            bench::format_time(*values[i]).c_str(),
                            bench::format_rate(n_hinges, *values[i]).c_str());
              std::cout << line;
              // The fastest repeat has the largest rate.
              csv << n << ',' << kernel << ',' << options.threads << ','
                  << keys[i] << ',' << n_hinges / values[i]->median << ','
                  << n_hinges / values[i]->max << ','
                  << n_hinges / values[i]->min << '\n';
            }
          std::cout << "  share of (a) outside the local loops "
                       "(gather, scatter, WorkStream): "
                    << 1 -
                         (t.local_hessian.median + t.segments_hessian.median) /
                           t.assemble_hessian.median
                    << "; of (b): "
                    << 1 - (t.local_gradient.median +
                            t.segments_gradient.median) /
                             t.assemble_gradient.median
                    << std::endl;
          report_peers(peers, n, t);
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("kernel_throughput", argc, argv, benchmark);
}
