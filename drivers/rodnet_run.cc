/**
 * @file The driver of rodnet-run, a module (librodnet-run-driver.so) that
 * the launcher drivers/rodnet_launcher.cc loads: runs a scene file,
 * several, or a sweep of one.
 *
 *   rodnet-run SCENE.prm|SCENE.json [--output DIR]
 *   rodnet-run SCENE... [--output DIR]           several scenes, one process
 *   rodnet-run SCENE --sweep Section/Entry=VALUES [--output DIR]
 *   ... --threads N          assembly on N threads
 *   ... --timings            a table of where the time went, at the end
 *   rodnet-run --help       usage, exit codes and every scene entry
 *   rodnet-run --version    the versions of rodnet and deal.II
 *
 * Exit codes: 0 done, 1 bad input (the message names the entry), 2 the
 * solver stopped early (the outputs of the converged steps are kept),
 * 128 + N stopped by signal N between two steps (outputs kept).
 */
#include <deal.II/base/config.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>

#include <app/interrupt.h>
#include <app/scene_runner.h>
#include <app/scene_study.h>
#include <base/mpi_session.h>
#include <base/phase_times.h>
#include <io/output_directory.h>
#include <io/scene.h>
#include <io/scene_help.h>
#include <materials/input_limits.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
  void
  usage(std::ostream &out)
  {
    out << "usage: rodnet-run SCENE.prm|SCENE.json [--output DIR] "
           "[--threads N] [--timings]\n"
           "       rodnet-run SCENE... [--output DIR] [--threads N] "
           "[--timings]\n"
           "       rodnet-run SCENE --sweep Section/Entry=VALUES [--output "
           "DIR]\n"
           "                  [--threads N] [--timings]\n"
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
           "--threads N assembles on N threads (default 1); the results differ "
           "from "
           "one\nthread's by the order of the additions only.\n"
           "--timings ends with a table of where the wall time went: model "
           "build,\nassembly, factorizations, solves, checks, outputs, "
           "each the least and the\nmost over the processes and the "
           "slowest process's rank (doc/performance.md,\n\"Where a run's "
           "time goes\").\n"
           "Several scenes, or a sweep of one entry (VALUES: FROM:TO:COUNT "
           "or a list split\nby ',' or ';'), run in one process into "
           "DIR/<k>_<label>/, with DIR/summary.csv\nand .png (the probes "
           "at each run's end); exit code: the first failed run's.\n"
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

namespace
{
  /// The command line of rodnet-run.
  struct Arguments
  {
    std::vector<std::string> scene_files;
    std::string              output;
    bool                     output_given = false;
    std::string              sweep;
    unsigned int             threads = 1;
    bool                     timings = false;
  };

  /// The number of threads of "--threads @p text": a whole number from 1
  /// to 1024; 0 where @p text is not one.
  unsigned int
  thread_count(const std::string &text)
  {
    if (text.empty() || text.size() > 4 ||
        text.find_first_not_of("0123456789") != std::string::npos)
      return 0;
    const unsigned int n = std::stoul(text);
    return n <= 1024 ? n : 0;
  }

  /// Runs one scene as before studies existed: its outputs in @p output.
  int
  run_one_scene(const std::string &scene_file,
                const std::string &output,
                const bool         output_given)
  {
    const auto refuse_scene = [&scene_file](const std::exception &e) {
      std::cerr << "rodnet-run: error in scene \"" << scene_file
                << "\": " << rodnet::error_message(e) << std::endl;
      return 1;
    };
    std::unique_ptr<rodnet::Scene> scene;
    bool                           created = false;
    try
      {
        scene = rodnet::load_scene(scene_file);
        if (output_given)
          scene->output_directory = output;
        created = rodnet::prepare_output_directory(scene->output_directory);
      }
    catch (const std::exception &e)
      {
        return refuse_scene(e);
      }
    try
      {
        return report(rodnet::run_scene(*scene,
                                        scene->output_directory,
                                        &std::cout),
                      scene->output_directory);
      }
    catch (const std::exception &e)
      {
        // Refused while the model was built: no empty folder stays.
        if (created)
          rodnet::remove_if_empty(scene->output_directory);
        return refuse_scene(e);
      }
  }

  /// Several scenes, or a sweep of one, in this process (run_study()).
  int
  run_many(const Arguments &arguments)
  {
    try
      {
        const bool          sweep = !arguments.sweep.empty();
        const rodnet::Sweep values =
          sweep ? rodnet::parse_sweep(arguments.sweep) : rodnet::Sweep{};
        const std::vector<rodnet::StudyRun> runs =
          sweep ? rodnet::sweep_runs(arguments.scene_files[0], values) :
                  rodnet::scene_runs(arguments.scene_files);
        const std::string output =
          arguments.output_given ?
            arguments.output :
            rodnet::load_scene(arguments.scene_files[0])->output_directory;
        return rodnet::run_study(runs,
                                 sweep ? values.entry : "scene",
                                 output,
                                 std::cout);
      }
    catch (const std::exception &e)
      {
        std::cerr << "rodnet-run: " << rodnet::error_message(e) << std::endl;
        return 1;
      }
  }

  /// On several MPI processes every process runs the scene and rank 0
  /// writes (writes_outputs()): the others' messages are dropped, so that
  /// the user reads one copy.
  void
  quiet_unless_writing()
  {
    if (rodnet::writes_outputs())
      return;
    std::cout.rdbuf(nullptr);
    std::cerr.rdbuf(nullptr);
  }
} // namespace

namespace
{
  /// The exit code of rodnet-run where it ends at the command line
  /// (--help, --version, a refused argument), or -1 where @p arguments,
  /// read from @p argv, name what to run.
  int
  read_arguments(const int argc, char **argv, Arguments &arguments)
  {
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
        if (arg == "--output" || arg == "--sweep")
          {
            if (i + 1 == argc || argv[i + 1][0] == '\0')
              return refuse_arguments(
                arg == "--output" ?
                  "--output needs a directory, e.g. --output my_run" :
                  "--sweep needs Section/Entry=VALUES, e.g. --sweep "
                  "\"Loads/Steps=10:40:4\"");
            (arg == "--output" ? arguments.output : arguments.sweep) =
              argv[++i];
            arguments.output_given =
              arguments.output_given || arg == "--output";
          }
        else if (arg == "--threads")
          {
            arguments.threads = i + 1 < argc ? thread_count(argv[++i]) : 0;
            if (arguments.threads == 0)
              return refuse_arguments(
                "--threads needs a whole number of threads from 1 to 1024, "
                "e.g. --threads 2");
          }
        else if (arg == "--timings")
          arguments.timings = true;
        else if (!arg.empty() && arg[0] != '-')
          arguments.scene_files.push_back(arg);
        else
          return refuse_arguments("unexpected argument \"" + arg + "\"");
      }
    if (arguments.scene_files.empty())
      return refuse_arguments("no scene file given");
    if (!arguments.sweep.empty() && arguments.scene_files.size() > 1)
      return refuse_arguments("--sweep varies one scene; " +
                              std::to_string(arguments.scene_files.size()) +
                              " were given");
    return -1;
  }
} // namespace

/// main() of rodnet-run, called by the launcher with its command line.
extern "C" __attribute__((visibility("default"))) int
rodnet_run_main(int argc, char **argv)
{
  // Progress lines must reach a redirected stdout (a file, a pipe) as they
  // are written, not when a block fills: flush after every output.
  std::cout << std::unitbuf;
  Arguments arguments;
  if (const int exit_code = read_arguments(argc, argv, arguments);
      exit_code >= 0)
    return exit_code;

  // MPI (for Trilinos) only now: a refused command line need not wait for
  // it. Open MPI's fast options for a process no launcher started.
  rodnet::MPISession mpi(argc, argv, arguments.threads);
  quiet_unless_writing();
  if (arguments.threads > 1)
    std::cout << "rodnet-run: assembling on "
              << dealii::MultithreadInfo::n_threads() << " threads ("
              << dealii::MultithreadInfo::n_cores() << " cores)" << std::endl;
  // After MPI_Init, which installs handlers of its own.
  rodnet::stop_cleanly_on_signals();
  const dealii::Timer run_time;
  const int           exit_code =
    arguments.scene_files.size() == 1 && arguments.sweep.empty() ?
                run_one_scene(arguments.scene_files[0],
                    arguments.output,
                    arguments.output_given) :
                run_many(arguments);
  // Not after bad input (refused before running); the processes agree on
  // that first, since the table is made by all of them together.
  if (arguments.timings &&
      !dealii::Utilities::MPI::logical_or(exit_code == 1, MPI_COMM_WORLD))
    rodnet::phase_times::write_table(std::cout,
                                     run_time.wall_time(),
                                     MPI_COMM_WORLD);
  return exit_code;
}
