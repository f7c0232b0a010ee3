#ifndef RODNET_APP_SCENE_STUDY_H
#define RODNET_APP_SCENE_STUDY_H

#include <io/scene.h>

#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /// An entry of a scene set to a value: the path "Section/Entry" (or
  /// "Section/Subsection/Entry") and the value as a scene file writes it.
  using EntrySetting = std::pair<std::string, std::string>;

  /// A parameter sweep: one entry and the values it takes, run after run.
  struct Sweep
  {
    std::string              entry;
    std::vector<std::string> values;
  };

  /**
   * Reads a sweep "Section/Entry=VALUES" (rodnet-run --sweep). VALUES is
   * FROM:TO:COUNT, COUNT values evenly spaced from FROM to TO, or a list
   * of values separated by ';' or, when there is no ';', by ',' (so that
   * "0,0,-9.81;0,0,-19.62" sweeps a vector entry). Throws
   * std::invalid_argument saying what is malformed.
   */
  Sweep
  parse_sweep(const std::string &text);

  /**
   * Reads the scene file @p file (.prm or .json), sets @p settings in it,
   * and checks the whole (Scene's constructor). Throws
   * std::invalid_argument naming the entry for an unknown entry or an
   * inadmissible value; relative mesh files are found next to @p file.
   */
  std::unique_ptr<Scene>
  load_scene(const std::string               &file,
             const std::vector<EntrySetting> &settings = {});

  /// One run of a study: a scene file and what is set in it.
  struct StudyRun
  {
    std::string               scene_file;
    std::vector<EntrySetting> settings;
    /// Names the run's output folder "<k>_<label>".
    std::string label;
    /// The summary's parameter column: the swept value as given, or the
    /// scene's name.
    std::string value;
    /// That value as a number, the abscissa of the summary's plot; NaN
    /// where it is not one (a vector, a scene), and the plot is against
    /// the runs' numbers, each labelled with its value.
    double parameter = std::nan("");
  };

  /// The runs of a sweep of @p scene_file: one per value of @p sweep,
  /// labelled "<Entry>=<value>", the value (if a number) as parameter.
  std::vector<StudyRun>
  sweep_runs(const std::string &scene_file, const Sweep &sweep);

  /// One run per scene file of @p scene_files, labelled by the file's name
  /// without extension, numbered from 1.
  std::vector<StudyRun>
  scene_runs(const std::vector<std::string> &scene_files);

  /**
   * Runs a study in one process: every scene is loaded and checked first
   * (a bad one throws std::invalid_argument before anything runs); then,
   * one after the other, each run writes its outputs into
   * @p output_directory/<k>_<label>/, and after every run the summary
   * `summary.csv` (run, @p parameter_name, the probes at the last recorded
   * step, load_factor and stable there, finished (1 where the run's exit
   * code is 0), exit_code, status, converged_steps, wall_time_s, folder)
   * and its plot `summary.png` are written again into @p output_directory,
   * so that a stopped study keeps what it did. The plot's abscissa is
   * labelled with the unit of the entry @p parameter_name (entry_unit());
   * runs that did not finish get their own marker. Progress goes to
   * @p log.
   *
   * A run whose solver stops early is recorded as such and the study goes
   * on; a stop signal (Ctrl-C) ends the study after the step in progress.
   * Returns the exit code of rodnet-run: 0 when every run completed,
   * 128 + N when stopped by signal N, otherwise 2 (a solver stopped early)
   * or 1 (a scene was refused while running), that of the first run that
   * did not complete.
   */
  int
  run_study(const std::vector<StudyRun> &runs,
            const std::string           &parameter_name,
            const std::string           &output_directory,
            std::ostream                &log);
} // namespace rodnet

#endif
