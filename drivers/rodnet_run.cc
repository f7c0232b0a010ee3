/**
 * @file rodnet-run: runs a scene file.
 *
 *   rodnet-run SCENE.prm|SCENE.json [--output DIR]
 *   rodnet-run --help       usage, exit codes and every scene entry
 *   rodnet-run --version    the versions of rodnet and deal.II
 *
 * Exit codes: 0 done, 1 bad input (the message names the entry), 2 the
 * solver stopped early (the outputs of the converged steps are kept),
 * 128 + N stopped by signal N between two steps (outputs kept).
 */
#include <deal.II/base/config.h>
#include <deal.II/base/mpi.h>

#include <io/interrupt.h>
#include <io/scene.h>
#include <io/scene_file.h>
#include <io/scene_help.h>
#include <io/scene_runner.h>
#include <materials/input_limits.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <unistd.h>

namespace
{
  void
  usage(std::ostream &out)
  {
    out << "usage: rodnet-run SCENE.prm|SCENE.json [--output DIR]\n"
           "       rodnet-run --help | --version\n";
  }

  /// `rodnet-run --help`, which doc/scene_reference.txt holds.
  void
  help(std::ostream &out)
  {
    usage(out);
    out << "\n"
           "Runs the scene and writes into DIR (default: the scene's "
           "Output/Directory)\nprobes.csv, probes.png and solution.pvd with "
           "one .vtu per step.\n"
           "Exit codes: 0 done; 1 bad input (the message names the entry); "
           "2 the solver\nstopped early; 128 + N stopped by signal N after "
           "the step in progress (130\nfor Ctrl-C, 143 for SIGTERM; a second "
           "signal kills). After 2 and 128 + N the\noutputs of the steps done "
           "are complete.\n"
           "\n"
           "A .prm scene sets entries in subsections:\n"
           "    subsection Loads\n"
           "      set Steps = 20\n"
           "    end\n"
           "and a .json scene is the same tree: {\"Loads\": {\"Steps\": "
           "\"20\"}}. Below is every\nentry as \"Name = default\", what it "
           "takes in parentheses, and its help with\nthe unit in brackets "
           "([-]: none). Every number must be finite and at most\n"
           "1e100 in magnitude. Vertices are [rod:]start|end|mid|<index> or "
           "@<name>.\n";
    static_assert(rodnet::max_input_magnitude == 1e100,
                  "the help states the limit");
    rodnet::print_scene_entries(out);
  }

  int
  refuse_arguments(const std::string &message)
  {
    std::cerr << "rodnet-run: " << message << "\n";
    usage(std::cerr);
    return 1;
  }

  /// Creates @p directory if needed; throws std::invalid_argument saying
  /// why it cannot hold the outputs.
  void
  prepare_output_directory(const std::string &directory)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory))
      throw std::invalid_argument(
        "cannot create the output directory \"" + directory +
        "\": " + (error ? error.message() : "a file of that name exists") +
        "; give another with --output DIR (or Output/Directory)");
    if (access(directory.c_str(), W_OK) != 0)
      throw std::invalid_argument("cannot write into the output directory \"" +
                                  directory + "\": " + std::strerror(errno) +
                                  "; give another with --output DIR (or "
                                  "Output/Directory)");
  }

  /// The line after a run and the exit code of @p summary.
  int
  report(const rodnet::RunSummary &summary, const std::string &directory)
  {
    if (!std::isnan(summary.critical_load_factor))
      std::cout << "critical load factor: " << summary.critical_load_factor
                << std::endl;
    std::string outputs;
    for (const std::string &name : summary.outputs)
      outputs += (outputs.empty() ? " " : ", ") + name;
    std::cout << "outputs in " << directory << "/:" << outputs << std::endl;
    if (summary.stopped_by != 0)
      {
        // Steps are recorded one after the other: step 0 or, after a
        // preload, step 1 first.
        const unsigned int last = summary.converged_steps;
        const std::string  steps =
          summary.rows.empty() ?
             "no step recorded" :
             "outputs of steps " +
              std::to_string(last + 1 - summary.rows.size()) + ".." +
              std::to_string(last) + " kept";
        std::cerr << "rodnet-run: interrupted at step " << last << ": " << steps
                  << std::endl;
        return 128 + summary.stopped_by;
      }
    if (!summary.failure.empty())
      {
        std::cerr << "rodnet-run: the solver stopped after "
                  << summary.converged_steps
                  << " converged steps: " << summary.failure << std::endl;
        return 2;
      }
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  // Progress lines must reach a redirected stdout (a file, a pipe) as they
  // are written, not when a block fills: flush after every output.
  std::cout << std::unitbuf;
  std::string scene_file, output;
  bool        output_given = false;
  for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h")
        {
          help(std::cout);
          return 0;
        }
      if (arg == "--version")
        {
          std::cout << "rodnet " << RODNET_VERSION << " (deal.II "
                    << DEAL_II_PACKAGE_VERSION << ", Trilinos "
                    << DEAL_II_TRILINOS_VERSION_MAJOR << "."
                    << DEAL_II_TRILINOS_VERSION_MINOR << ")" << std::endl;
          return 0;
        }
      if (arg == "--output")
        {
          if (i + 1 == argc || argv[i + 1][0] == '\0')
            return refuse_arguments("--output needs a directory, e.g. "
                                    "--output my_run");
          output       = argv[++i];
          output_given = true;
        }
      else if (!arg.empty() && arg[0] != '-' && scene_file.empty())
        scene_file = arg;
      else
        return refuse_arguments("unexpected argument \"" + arg + "\"");
    }
  if (scene_file.empty())
    return refuse_arguments("no scene file given");

  const auto refuse_scene = [&scene_file](const std::exception &e) {
    std::cerr << "rodnet-run: error in scene \"" << scene_file
              << "\": " << rodnet::error_message(e) << std::endl;
    return 1;
  };
  std::unique_ptr<rodnet::Scene> scene;
  try
    {
      dealii::ParameterHandler prm;
      rodnet::Scene::declare_parameters(prm);
      rodnet::read_scene_file(prm, scene_file);
      const std::string directory =
        std::filesystem::path(scene_file).parent_path().string();
      scene =
        std::make_unique<rodnet::Scene>(prm,
                                        directory.empty() ? "." : directory);
      if (output_given)
        scene->output_directory = output;
      prepare_output_directory(scene->output_directory);
    }
  catch (const std::exception &e)
    {
      return refuse_scene(e);
    }

  // MPI (for Trilinos) only now: starting it takes a second, which a
  // refused scene need not wait for.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 1)
    {
      std::cerr << "rodnet-run: runs on one MPI process for now\n";
      return 1;
    }
  // After MPI_Init, which installs handlers of its own.
  rodnet::stop_cleanly_on_signals();
  try
    {
      return report(rodnet::run_scene(*scene,
                                      scene->output_directory,
                                      &std::cout),
                    scene->output_directory);
    }
  catch (const std::exception &e)
    {
      return refuse_scene(e);
    }
}
