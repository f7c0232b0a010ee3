// What picture.png costs (io/network_picture.h): the square lattice of
// bench/gridshell_scene.h with n x n cells, 10 segments per beam
// (2 n (n + 1) beams), drawn in the undeformed state from the oblique
// camera (azimuth -60, elevation 35, the automatic view of a flat lattice
// buckled out of its plane): the drawing holds every segment twice
// (undeformed grey, deformed coloured by the displacement), as at the end
// of a run. Times, median (min-max) of the repeats:
//   fields: picture_state (positions and the model's output fields),
//   script: network_picture_script (projection, data blocks),
//   gnuplot: gnuplot drawing the PNG from the script,
// and the sizes of the script and of the PNG.
//
// Usage: network_picture [--cells n] [--repeats n] (defaults 80 and 5).
#include <io/gnuplot.h>
#include <io/network_picture.h>
#include <io/scene.h>

#include <algorithm>
#include <bench/gridshell_scene.h>
#include <bench/options.h>
#include <bench/timing.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace rodnet;

int
main(int argc, char **argv)
{
  rodnet::MPISession mpi(argc, argv);
  unsigned int       cells = 80, repeats = 5;
  bench::parse(argc,
               argv,
               {bench::number("--cells", cells, 1),
                bench::number("--repeats", repeats, 1)});

  const Scene                     scene = bench::gridshell(cells, 10);
  const std::unique_ptr<RodModel> model = scene.build_model();
  const VectorType                u     = model->create_vector();
  PictureOptions                  options;
  options.azimuth   = -60;
  options.elevation = 35;
  std::printf("square lattice of %u x %u cells, 10 segments per beam: %u "
              "segments\n",
              cells,
              cells,
              model->network().n_segments());

  PictureState state;
  bench::print_time("fields", bench::time_repeats(repeats, [&] {
                      state = picture_state(*model, u);
                    }));
  const std::string png = "network_picture_bench.png";
  std::string       script;
  bench::print_time("script", bench::time_repeats(repeats, [&] {
                      script = network_picture_script(model->network(),
                                                      state,
                                                      options,
                                                      png,
                                                      "bench");
                    }));
  bench::print_time("gnuplot", bench::time_repeats(repeats, [&] {
                      const std::string failure =
                        draw_with_gnuplot(script, png);
                      if (!failure.empty())
                        throw std::runtime_error(failure);
                    }));
  std::printf("script %.3g MB (%ld lines), PNG %.3g kB\n",
              script.size() / 1e6,
              static_cast<long>(std::count(script.begin(), script.end(), '\n')),
              std::filesystem::file_size(png) / 1e3);
  return 0;
}
