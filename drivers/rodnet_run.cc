/**
 * @file rodnet-run: runs a scene file.
 *
 *   rodnet-run SCENE.prm|SCENE.json [--output DIR]
 *   rodnet-run --help          prints every scene entry with unit and help
 *
 * Exit codes: 0 done, 1 bad input (the message names the entry), 2 the
 * solver stopped early (the outputs of the converged steps are kept).
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <io/scene.h>
#include <io/scene_runner.h>

#include <filesystem>
#include <iostream>
#include <string>

namespace
{
  void
  usage(std::ostream &out)
  {
    out << "usage: rodnet-run SCENE.prm|SCENE.json [--output DIR]\n"
           "       rodnet-run --help   (lists every scene entry)\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::string                              scene_file, output;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
        {
          dealii::ParameterHandler prm;
          rodnet::Scene::declare_parameters(prm);
          usage(std::cout);
          std::cout << "\nScene entries (defaults shown):\n\n";
          prm.print_parameters(std::cout,
                               dealii::ParameterHandler::OutputStyle::Text);
          return 0;
        }
      if (arg == "--output" && i + 1 < argc)
        output = argv[++i];
      else if (!arg.empty() && arg[0] != '-' && scene_file.empty())
        scene_file = arg;
      else
        {
          std::cerr << "rodnet-run: unexpected argument \"" << arg << "\"\n";
          usage(std::cerr);
          return 1;
        }
    }
  if (scene_file.empty())
    {
      usage(std::cerr);
      return 1;
    }
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 1)
    {
      std::cerr << "rodnet-run: runs on one MPI process for now\n";
      return 1;
    }

  std::unique_ptr<rodnet::Scene> scene;
  try
    {
      if (!std::filesystem::exists(scene_file))
        throw std::invalid_argument("the scene file does not exist");
      dealii::ParameterHandler prm;
      rodnet::Scene::declare_parameters(prm);
      prm.parse_input(scene_file);
      const std::string directory =
        std::filesystem::path(scene_file).parent_path().string();
      scene =
        std::make_unique<rodnet::Scene>(prm,
                                        directory.empty() ? "." : directory);
      if (!output.empty())
        scene->output_directory = output;
    }
  catch (const std::exception &e)
    {
      std::cerr << "rodnet-run: error in scene \"" << scene_file << "\":\n"
                << rodnet::error_message(e) << std::endl;
      return 1;
    }

  try
    {
      const rodnet::RunSummary summary =
        rodnet::run_scene(*scene, scene->output_directory, &std::cout);
      if (!std::isnan(summary.critical_load_factor))
        std::cout << "critical load factor: " << summary.critical_load_factor
                  << std::endl;
      std::cout << "outputs in " << scene->output_directory
                << "/: probes.csv, probes.png, solution.pvd" << std::endl;
      if (!summary.failure.empty())
        {
          std::cerr << "rodnet-run: the solver stopped after "
                    << summary.converged_steps
                    << " converged steps: " << summary.failure << std::endl;
          return 2;
        }
    }
  catch (const std::exception &e)
    {
      std::cerr << "rodnet-run: error in scene \"" << scene_file << "\":\n"
                << rodnet::error_message(e) << std::endl;
      return 1;
    }
  return 0;
}
