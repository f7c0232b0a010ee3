#include <deal.II/base/timer.h>

#include <app/interrupt.h>
#include <app/scene_runner.h>
#include <app/scene_study.h>
#include <base/mpi_session.h>
#include <io/output_directory.h>
#include <io/probe_plot.h>
#include <io/scene_file.h>
#include <io/scene_help.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace rodnet
{
  namespace
  {
    std::string
    trim(const std::string &text)
    {
      const auto begin = text.find_first_not_of(" \t");
      if (begin == std::string::npos)
        return "";
      return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
    }

    std::vector<std::string>
    split(const std::string &text, const char separator)
    {
      std::vector<std::string> parts;
      std::stringstream        stream(text);
      std::string              part;
      while (std::getline(stream, part, separator))
        parts.push_back(trim(part));
      if (!text.empty() && text.back() == separator)
        parts.emplace_back();
      return parts;
    }

    /// @p text as a finite number, or throws naming @p what.
    double
    number(const std::string &text, const std::string &what)
    {
      std::size_t used = 0;
      double      value;
      try
        {
          value = std::stod(text, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      if (used == 0 || used != text.size() || !std::isfinite(value))
        throw std::invalid_argument(what + " \"" + text +
                                    "\" is not a finite number");
      return value;
    }

    /// FROM:TO:COUNT as COUNT values (shortest exact text of each).
    std::vector<std::string>
    range_values(const std::string &text)
    {
      const std::vector<std::string> parts = split(text, ':');
      if (parts.size() != 3)
        throw std::invalid_argument("the range \"" + text +
                                    "\" is not FROM:TO:COUNT");
      const double from  = number(parts[0], "FROM");
      const double to    = number(parts[1], "TO");
      const double count = number(parts[2], "COUNT");
      if (count < 1 || count > 10000 || count != std::floor(count) ||
          (count == 1 && from != to))
        throw std::invalid_argument(
          "COUNT of \"" + text +
          "\" must be a whole number from 2 to 10000 (1 if FROM = TO)");
      std::vector<std::string> values;
      for (unsigned int k = 0; k < count; ++k)
        {
          const double value =
            count == 1 ? from : from + (to - from) * k / (count - 1);
          char buffer[32];
          std::snprintf(buffer, sizeof(buffer), "%.12g", value);
          values.emplace_back(buffer);
        }
      return values;
    }

    /// "Loads/Steps=3" for a folder name: characters other than letters,
    /// digits and "._=-" become '_'.
    std::string
    folder_label(const std::string &label)
    {
      std::string folder = label;
      for (char &c : folder)
        if (!std::isalnum(static_cast<unsigned char>(c)) &&
            std::string("._=-").find(c) == std::string::npos)
          c = '_';
      return folder;
    }

    /// A CSV field: quoted when it holds a comma, a quote or a line break.
    std::string
    csv_field(const std::string &text)
    {
      if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      return quoted + "\"";
    }

    /// What a finished run leaves in the summary.
    struct RunOutcome
    {
      std::string status = "not run";
      /// rodnet-run's exit code for the run alone; none if not run.
      std::optional<int>  exit_code;
      unsigned int        converged_steps = 0;
      double              wall_time       = 0;
      std::string         folder;
      std::vector<double> last_values; // per summary probe column, NaN if none
      double              load_factor = std::nan("");
      double              stable      = std::nan("");
    };

    /// The summary table over the runs done so far: CSV and PNG.
    class StudySummary
    {
    public:
      StudySummary(const std::vector<StudyRun> &runs,
                   const std::string           &parameter_name,
                   const std::string           &directory)
          : runs(runs)
          , parameter_name(parameter_name)
          , directory(directory)
          , outcomes(runs.size())
      {
      }

      /// Records run @p k, which ended with @p exit_code, from its
      /// @p summary (nullptr: it was refused).
      void
      record(const unsigned int k,
             const std::string &status,
             const int          exit_code,
             const RunSummary  *summary,
             const double       wall_time,
             const std::string &folder)
      {
        RunOutcome &outcome = outcomes[k];
        outcome.status      = status;
        outcome.exit_code   = exit_code;
        outcome.wall_time   = wall_time;
        outcome.folder      = folder;
        if (summary == nullptr)
          return;
        outcome.converged_steps = summary->converged_steps;
        outcome.load_factor     = summary->final_load_factor;
        outcome.stable          = summary->final_stable;
        length_scale            = std::max(length_scale, summary->length_scale);
        for (std::size_t p = 0; p < summary->probe_names.size(); ++p)
          {
            const std::size_t column =
              probe_column(summary->probe_names[p], summary->probe_units[p]);
            outcome.last_values.resize(probe_names.size(), std::nan(""));
            if (!summary->rows.empty())
              outcome.last_values[column] = summary->rows.back()[p + 1];
          }
      }

      /// Writes summary.csv and summary.png (the probes against the
      /// parameter) again.
      void
      write() const
      {
        if (!writes_outputs())
          return;
        const std::string csv_path = directory + "/summary.csv";
        {
          std::ofstream csv(csv_path);
          csv << "run," << csv_field(parameter_name);
          for (const std::string &name : probe_names)
            csv << ',' << csv_field(name);
          csv << ",load_factor,stable,finished,exit_code,status,"
                 "converged_steps,wall_time_s,folder\n";
          csv.precision(12);
          for (std::size_t k = 0; k < runs.size(); ++k)
            write_row(csv, k);
        }
        if (!probe_names.empty())
          plot(csv_path);
      }

    private:
      /// A number of the summary, blank if there is none.
      static std::string
      optional_number(const double value)
      {
        std::ostringstream text;
        text.precision(12);
        if (!std::isnan(value))
          text << value;
        return text.str();
      }

      /// Writes the row of run @p k into @p csv.
      void
      write_row(std::ostream &csv, const std::size_t k) const
      {
        const RunOutcome &o = outcomes[k];
        csv << k + 1 << ',' << csv_field(runs[k].value);
        for (std::size_t c = 0; c < probe_names.size(); ++c)
          csv << ','
              << optional_number(c < o.last_values.size() ? o.last_values[c] :
                                                            std::nan(""));
        csv << ',' << optional_number(o.load_factor) << ','
            << optional_number(o.stable) << ','
            << (o.exit_code && *o.exit_code == 0) << ','
            << (o.exit_code ? std::to_string(*o.exit_code) : "") << ','
            << csv_field(o.status) << ',' << o.converged_steps << ','
            << o.wall_time << ',' << csv_field(o.folder) << '\n';
      }

      /// Plots the summary @p csv_path: against the swept value where
      /// every value is a number (labelled with the entry's unit),
      /// otherwise against the run's number, each tic labelled with the
      /// value or the scene.
      void
      plot(const std::string &csv_path) const
      {
        const bool numbers =
          std::all_of(runs.begin(), runs.end(), [](const StudyRun &run) {
            return !std::isnan(run.parameter);
          });
        ProbePlotOptions options;
        options.title    = "rodnet study: probes at each run's last step";
        options.abscissa = numbers ? 1 : 0;
        if (!numbers)
          options.tic_labels = 1;
        options.n_probes = probe_names.size() + 1; // and the load factor
        options.units    = {numbers ? entry_unit(parameter_name) : ""};
        options.units.insert(options.units.end(),
                             probe_units.begin(),
                             probe_units.end());
        options.units.push_back("-");
        options.length_scale = length_scale;
        options.row_name     = "run's end";
        options.warn_if_flat = false;
        plot_probes(csv_path, directory + "/summary.png", options);
      }

      /// The summary column of a probe, added when first seen.
      std::size_t
      probe_column(const std::string &name, const std::string &unit)
      {
        const auto found =
          std::find(probe_names.begin(), probe_names.end(), name);
        if (found != probe_names.end())
          return found - probe_names.begin();
        probe_names.push_back(name);
        probe_units.push_back(unit);
        return probe_names.size() - 1;
      }

      const std::vector<StudyRun> &runs;
      const std::string            parameter_name;
      const std::string            directory;
      std::vector<RunOutcome>      outcomes;
      std::vector<std::string>     probe_names, probe_units;
      /// The largest length scale of the models run.
      double length_scale = 0;
    };

    /// "007" for run 7 of a study of 100 to 999 runs: folders sort in order.
    std::string
    run_number(const std::size_t k, const std::size_t n_runs)
    {
      const std::string number = std::to_string(k);
      const std::size_t width  = std::to_string(n_runs).size();
      return std::string(width - std::min(width, number.size()), '0') + number;
    }
    /// Every scene of @p runs, loaded before any runs: a typo in the last
    /// must not wait for the others. Throws std::invalid_argument naming
    /// the run whose scene is refused.
    std::vector<std::unique_ptr<Scene>>
    load_study_scenes(const std::vector<StudyRun> &runs)
    {
      std::vector<std::unique_ptr<Scene>> scenes;
      for (const StudyRun &run : runs)
        try
          {
            scenes.push_back(load_scene(run.scene_file, run.settings));
          }
        catch (const std::exception &e)
          {
            throw std::invalid_argument("run \"" + run.label + "\" (scene \"" +
                                        run.scene_file +
                                        "\"): " + error_message(e));
          }
      return scenes;
    }

    /// How one run of a study ended: its summary, its status in
    /// summary.csv and its exit code (as rodnet-run's for the scene).
    struct StudyRunOutcome
    {
      RunSummary  result;
      std::string status;
      int         exit_code = 0;
    };

    /// Runs @p scene into @p directory; bad input refuses the run, not the
    /// study.
    StudyRunOutcome
    run_study_scene(const Scene       &scene,
                    const std::string &directory,
                    std::ostream      &log)
    {
      StudyRunOutcome outcome;
      try
        {
          prepare_output_directory(directory);
          RunSummary &result = outcome.result;
          result             = run_scene(scene, directory, &log);
          outcome.exit_code = result.stopped_by != 0 ? 128 + result.stopped_by :
                              !result.failure.empty() ? 2 :
                                                        0;
          outcome.status =
            result.stopped_by != 0 ? "interrupted" :
            result.failure.empty() ? "done" :
                                     "stopped early: " + result.failure;
        }
      catch (const std::exception &e)
        {
          outcome.exit_code = 1;
          outcome.status    = "refused: " + error_message(e);
        }
      return outcome;
    }
  } // namespace

  Sweep
  parse_sweep(const std::string &text)
  {
    const auto equals = text.find('=');
    if (equals == std::string::npos)
      throw std::invalid_argument(
        "--sweep \"" + text +
        "\" is not Section/Entry=VALUES (VALUES: FROM:TO:COUNT or a list "
        "separated by ',' or ';')");
    Sweep sweep;
    sweep.entry              = trim(text.substr(0, equals));
    const std::string values = trim(text.substr(equals + 1));
    if (sweep.entry.empty() || values.empty())
      throw std::invalid_argument("--sweep \"" + text +
                                  "\" needs an entry and values");
    if (values.find(';') == std::string::npos &&
        values.find(':') != std::string::npos)
      sweep.values = range_values(values);
    else
      sweep.values =
        split(values, values.find(';') != std::string::npos ? ';' : ',');
    for (const std::string &value : sweep.values)
      if (value.empty())
        throw std::invalid_argument("--sweep \"" + text +
                                    "\" has an empty value");
    return sweep;
  }

  std::unique_ptr<Scene>
  load_scene(const std::string &file, const std::vector<EntrySetting> &settings)
  {
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    read_scene_file(prm, file);
    for (const auto &[path, value] : settings)
      {
        const std::vector<std::string> names = split(path, '/');
        for (std::size_t depth = 0; depth + 1 < names.size(); ++depth)
          prm.enter_subsection(names[depth]);
        std::string refusal;
        try
          {
            prm.set(names.back(), value);
          }
        catch (const dealii::ParameterHandler::ExcEntryUndeclared &)
          {
            refusal = "a scene has no entry \"" + path +
                      "\" (Section/Entry, as `rodnet-run --help` lists them)";
          }
        catch (const std::exception &e)
          {
            refusal = "cannot set \"" + path + "\" to \"" + value +
                      "\": " + error_message(e);
          }
        for (std::size_t depth = 0; depth + 1 < names.size(); ++depth)
          prm.leave_subsection();
        if (!refusal.empty())
          throw std::invalid_argument(refusal);
      }
    const std::string directory =
      std::filesystem::path(file).parent_path().string();
    return std::make_unique<Scene>(prm, directory.empty() ? "." : directory);
  }

  std::vector<StudyRun>
  sweep_runs(const std::string &scene_file, const Sweep &sweep)
  {
    const std::string     entry_name = split(sweep.entry, '/').back();
    std::vector<StudyRun> runs;
    for (const std::string &value : sweep.values)
      {
        StudyRun run;
        run.scene_file   = scene_file;
        run.settings     = {{sweep.entry, value}};
        run.label        = entry_name + "=" + value;
        run.value        = value;
        std::size_t used = 0;
        try
          {
            const double number = std::stod(value, &used);
            if (used == value.size())
              run.parameter = number;
          }
        catch (const std::exception &)
          {
            // Not a number (a vector, a name): the summary numbers the runs.
          }
        runs.push_back(run);
      }
    return runs;
  }

  std::vector<StudyRun>
  scene_runs(const std::vector<std::string> &scene_files)
  {
    std::vector<StudyRun> runs;
    for (const std::string &file : scene_files)
      {
        StudyRun run;
        run.scene_file = file;
        run.label      = std::filesystem::path(file).stem().string();
        run.value      = run.label;
        runs.push_back(run);
      }
    return runs;
  }

  int
  run_study(const std::vector<StudyRun> &runs,
            const std::string           &parameter_name,
            const std::string           &output_directory,
            std::ostream                &log)
  {
    const std::vector<std::unique_ptr<Scene>> scenes = load_study_scenes(runs);
    prepare_output_directory(output_directory);

    StudySummary summary(runs, parameter_name, output_directory);
    int          exit_code = 0;
    for (std::size_t k = 0; k < runs.size(); ++k)
      {
        if (stop_signal() != 0)
          return 128 + stop_signal();
        const std::string folder =
          run_number(k + 1, runs.size()) + "_" + folder_label(runs[k].label);
        const std::string directory = output_directory + "/" + folder;
        log << "run " << k + 1 << "/" << runs.size() << ": " << runs[k].label
            << " -> " << directory << "/" << std::endl;
        dealii::Timer         timer;
        const StudyRunOutcome run = run_study_scene(*scenes[k], directory, log);
        summary.record(k,
                       run.status,
                       run.exit_code,
                       run.exit_code == 1 ? nullptr : &run.result,
                       timer.wall_time(),
                       folder);
        summary.write();
        if (run.exit_code != 0)
          log << "run " << k + 1 << ": " << run.status << std::endl;
        if (run.result.stopped_by != 0)
          return run.exit_code;
        if (exit_code == 0)
          exit_code = run.exit_code;
      }
    log << "summary of " << runs.size() << " runs in " << output_directory
        << "/: summary.csv, summary.png" << std::endl;
    return exit_code;
  }
} // namespace rodnet
