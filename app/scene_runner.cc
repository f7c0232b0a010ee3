#include <deal.II/base/timer.h>

#include <app/interrupt.h>
#include <app/method_runs.h>
#include <app/scene_runner.h>
#include <base/phase_times.h>
#include <io/mode_shapes.h>
#include <io/problem_size.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rodnet
{
  namespace
  {
    /**
     * Writes the mode shapes the scene asks for (Output/Mode shapes) at
     * the last equilibrium @p recorder recorded, and lists their files in
     * @p summary. The run's results are written by then: where the
     * eigen-solver fails, a warning says so and the run goes on to its
     * summary.
     */
    void
    write_requested_modes(const Scene                    &scene,
                          const RodModel                 &model,
                          const StepRecorder<VectorType> &recorder,
                          const std::string              &output_directory,
                          RunSummary                     &summary,
                          std::ostream                   *log)
    {
      const auto &last = recorder.last_recorded();
      if (scene.mode_shapes == 0 || !last)
        return;
      try
        {
          const std::vector<std::string> files =
            write_mode_shapes(model,
                              last->second,
                              last->first,
                              scene.mode_shapes,
                              output_directory,
                              scene.write_vtu);
          summary.outputs.insert(summary.outputs.end(),
                                 files.begin(),
                                 files.end());
          if (log != nullptr)
            *log << "mode shapes at load factor " << last->first
                 << ": modes.csv" << std::endl;
        }
      catch (const std::exception &e)
        {
          std::cerr << "warning: no mode shapes written: " << e.what()
                    << std::endl;
        }
    }

    /**
     * Runs @p build, the construction of a model of @p scene; a big one
     * (over 1e5 DoFs) gets a line before and one after, with the time it
     * took, so that a long build does not look like a hang. A stop signal
     * received meanwhile ends the run after it.
     */
    template <class Build>
    auto
    build_with_progress(const Scene  &scene,
                        std::ostream *log,
                        const Build  &build)
    {
      const bool    report = log != nullptr && scene.size().dofs() > 1e5;
      dealii::Timer timer;
      if (report)
        *log << "building the model ..." << std::endl;
      auto model = [&] {
        const phase_times::Scope phase(phase_times::Phase::model_build);
        return build();
      }();
      if (report)
        *log << "  built in " << timer.wall_time() << " s" << std::endl;
      throw_if_stop_requested();
      return model;
    }

    /**
     * Runs @p solve, the solver's run over the steps; a SolverFailure
     * or a stop request ends it into @p summary (every converged step is
     * recorded by then).
     */
    template <class Solve>
    void
    run_guarded(RunSummary &summary, const Solve &solve)
    {
      try
        {
          solve();
        }
      catch (const SolverFailure &e)
        {
          summary.failure = e.what();
        }
      catch (const StopRequested &e)
        {
          summary.stopped_by = e.signal;
        }
    }

    /// "1 rod(s), 100 segments, 403 DoFs, memory about 200 MB (15 GB
    /// available)".
    std::string
    describe_size(const ProblemSize &size)
    {
      std::ostringstream text;
      text << std::fixed << std::setprecision(0) << size.rods << " rod(s), "
           << size.segments << " segments, " << size.dofs()
           << " DoFs, memory about " << format_bytes(size.memory());
      if (const double available = available_memory(); available > 0)
        text << " (" << format_bytes(available) << " available)";
      return text.str();
    }

    /**
     * Throws std::invalid_argument naming "Output/VTU interval" if the VTU
     * files of the run would not fit on the disk of @p directory. A file
     * takes at most 60 bytes per vertex, its fields uncompressed (measured:
     * 10 bytes compressed at rest).
     */
    void
    check_output_space(const Scene &scene, const std::string &directory)
    {
      const double files = scene.planned_vtu_files();
      if (files == 0)
        return;
      const double          bytes = files * (2000 + 60 * scene.size().vertices);
      std::error_code       error;
      std::filesystem::path existing = std::filesystem::absolute(directory);
      while (!std::filesystem::exists(existing, error) &&
             existing.has_parent_path() && existing != existing.parent_path())
        existing = existing.parent_path();
      const auto space = std::filesystem::space(existing, error);
      if (error || bytes <= space.available)
        return;
      std::ostringstream text;
      text << std::fixed << std::setprecision(0)
           << "entry \"Output/VTU interval\": the " << files
           << " VTU files of the run would take up to " << format_bytes(bytes)
           << ", more than the " << format_bytes(space.available)
           << " free at \"" << existing.string()
           << "\"; raise the interval, set \"Write VTU = false\" or write "
              "elsewhere (--output)";
      throw std::invalid_argument(text.str());
    }

    /**
     * The one sequence of a run, for every solution method @p Method
     * (app/method_runs.h): builds the model, its probes and the method
     * (which may refuse the scene before any file is written), records
     * every converged step (StepRecorder), runs the method guarded (a
     * solver's failure or a stop request ends the run into the summary
     * with every step recorded), then plots probes.csv and writes the
     * mode shapes the scene asks for.
     */
    template <class Method>
    RunSummary
    run_method(const Scene       &scene,
               const std::string &output_directory,
               std::ostream      *log)
    {
      const auto model =
        build_with_progress(scene, log, [&] { return Method::build(scene); });
      const ProbeList probes = scene.probes(*model);
      Method          method(scene, *model, probes, log);

      RunSummary                            summary;
      StepRecorder<typename Method::Vector> recorder(scene,
                                                     output_directory,
                                                     probes,
                                                     *model,
                                                     summary,
                                                     method.abscissa(),
                                                     method.check_columns());
      method.describe(log);
      run_guarded(summary, [&] { method.run(recorder, summary); });
      method.finish(summary);
      recorder.finish(output_directory, method.plot_range());
      if constexpr (Method::writes_modes)
        write_requested_modes(scene,
                              *model,
                              recorder,
                              output_directory,
                              summary,
                              log);
      return summary;
    }
  } // namespace

  RunSummary
  run_scene(const Scene       &scene,
            const std::string &output_directory,
            std::ostream      *log)
  {
    if (log != nullptr)
      for (const std::string &info : scene.geometry_notes.info)
        *log << "rodnet: " << info << std::endl;
    for (const std::string &warning : scene.geometry_notes.warnings)
      std::cerr << "warning: " << warning << std::endl;
    if (log != nullptr)
      *log << "rodnet: " << describe_size(scene.size()) << std::endl;
    check_output_space(scene, output_directory);
    switch (scene.method)
      {
        case SolutionMethod::newton:
          return run_method<NewtonRun>(scene, output_directory, log);
        case SolutionMethod::dynamic_relaxation:
          return run_method<RelaxationRun>(scene, output_directory, log);
        case SolutionMethod::time_stepping:
          return run_method<TimeSteppingRun>(scene, output_directory, log);
        case SolutionMethod::continuation:
          return run_method<ContinuationRun>(scene, output_directory, log);
      }
    throw std::logic_error("run_scene: unknown solution method");
  }
} // namespace rodnet
