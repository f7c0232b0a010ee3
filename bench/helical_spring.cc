// Convergence of the helical spring of scenes/helical_spring.prm in the
// number of turns (the end effect of the clamps on the coil) and in the
// segments per turn (the discretization), for both hinge kernels: the
// table of k / k_ideal - 1 in doc/validation.md, "Helical spring", with
// k_ideal from Castigliano (tests/common/helical_spring.h), and the ratio
// of k_ideal to VALIDATION.md's pitch-corrected formula.
//
// Usage: helical_spring [--threads n] [--max-turns n] [--max-segments n]
// (turns 2, 4, ... up to --max-turns, default 32; segments per turn 8, 16,
// ... up to --max-segments, default 64)
#include <bench/options.h>
#include <cstdio>
#include <tests/common/helical_spring.h>

using namespace rodnet;
using namespace rodnet::testing;

namespace
{
  struct Options
  {
    unsigned int threads      = 1;
    unsigned int max_turns    = 32;
    unsigned int max_segments = 64;

    std::vector<bench::Option>
    command_line()
    {
      return {bench::number("--threads", threads, 1),
              bench::number("--max-turns", max_turns, 2),
              bench::number("--max-segments", max_segments, 8)};
    }
  };

  void
  benchmark(const Options &options)
  {
    std::printf("k_ideal / k_VALIDATION.md = %.6f\n",
                ideal_spring_stiffness(1) / validation_md_stiffness(1));
    for (const std::string kernel : {"simple", "classic"})
      {
        std::printf("%s kernel: k / k_ideal - 1 per turns (rows) and "
                    "segments per turn (columns)\n%8s",
                    kernel.c_str(),
                    "turns");
        for (unsigned int s = 8; s <= options.max_segments; s *= 2)
          std::printf(" %10u", s);
        std::printf("\n");
        for (unsigned int turns = 2; turns <= options.max_turns; turns *= 2)
          {
            std::printf("%8u", turns);
            for (unsigned int s = 8; s <= options.max_segments; s *= 2)
              std::printf(" %10.2e",
                          helical_spring_stiffness(turns, s, kernel) /
                              ideal_spring_stiffness(turns) -
                            1);
            std::printf("\n");
          }
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("helical_spring", argc, argv, benchmark);
}
