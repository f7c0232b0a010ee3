#ifndef RODNET_APP_STEP_RECORDER_H
#define RODNET_APP_STEP_RECORDER_H

#include <app/interrupt.h>
#include <app/scene_runner.h>
#include <base/phase_times.h>
#include <core/model.h>
#include <io/network_picture.h>
#include <io/probe_plot.h>
#include <io/probes.h>
#include <io/run_limits.h>
#include <io/vtu_output.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rodnet
{
  /// The name of the run in the folder @p output_directory: the folder's
  /// own name ("elastica").
  inline std::string
  run_name(const std::string &output_directory)
  {
    std::error_code       error;
    std::filesystem::path folder =
      std::filesystem::absolute(output_directory, error).lexically_normal();
    if (!folder.has_filename())
      folder = folder.parent_path();
    return folder.filename().string();
  }

  /// What every solution method does with a converged step: a row of
  /// probes.csv, a row of the summary, the VTU files and the pictures,
  /// against the load factor or the time (@p abscissa names which).
  /// After each step it ends the run with StopRequested if a signal
  /// asked for that: every file is complete then. The VTU files and
  /// pictures show the states of @p model.
  template <class State>
  class StepRecorder
  {
  public:
    StepRecorder(const Scene                    &scene,
                 const std::string              &output_directory,
                 const ProbeList                &probes,
                 const Model<State>             &model,
                 RunSummary                     &summary,
                 const std::string              &abscissa      = "load_factor",
                 const std::vector<std::string> &check_columns = {})
        : scene(scene)
        , model(model)
        , probes(probes)
        , directory(output_directory)
        , csv(csv_path(output_directory))
        , table(csv, probes, abscissa, check_columns)
        , summary(summary)
        , units{abscissa == "time" ? "s" : "-"}
        , stable_check(
            std::find(check_columns.begin(), check_columns.end(), "stable") -
            check_columns.begin())
    {
      summary.abscissa     = abscissa;
      summary.length_scale = model.length_scale();
      summary.outputs      = {"probes.csv"};
      if (scene.write_vtu)
        vtu = std::make_unique<VtuOutput>(model.network(), output_directory);
      // The field is checked even where Plot = false draws no picture.
      if (scene.picture.enabled)
        pictures = std::make_unique<NetworkPictures>(model, scene.picture);
      if (!scene.plot)
        pictures.reset();
      for (const auto &p : probes)
        {
          summary.probe_names.push_back(p->name());
          summary.probe_units.push_back(p->unit());
          units.push_back(p->unit());
        }
    }

    /// Records step @p step at load factor or time @p abscissa (also the
    /// "time" of the PVD record) and @p load_factor; @p u is the state,
    /// @p values its probes, @p checks the values of the check columns.
    void
    record(const unsigned int         step,
           const double               abscissa,
           const double               load_factor,
           std::vector<double>        values,
           const State               &state,
           const std::vector<double> &checks = {})
    {
      const phase_times::Scope phase(phase_times::Phase::outputs);
      // The outputs read DoFs anywhere (collective on several processes).
      const EveryEntryOf<State> every_entry(state);
      const State              &u = *every_entry;
      continue_probes(probes, previous_values, values);
      previous_values = values;
      table.add_row(step, abscissa, values, checks);
      std::vector<double> row{abscissa};
      row.insert(row.end(), values.begin(), values.end());
      summary.rows.push_back(row);
      summary.converged_steps   = step;
      summary.final_load_factor = load_factor;
      summary.final_stable =
        stable_check < checks.size() ? checks[stable_check] : std::nan("");
      last           = {abscissa, u};
      largest_energy = std::max(largest_energy,
                                std::abs(model.elastic_energy(u, load_factor)));
      if (vtu && step % scene.vtu_interval == 0)
        write_vtu(step, abscissa, u);
      if (pictures)
        pictures->add_frame(picture_state(model, u),
                            step,
                            directory,
                            picture_title(abscissa));
      throw_if_stop_requested();
    }

    /// Plots probes.csv, over @p x_range of the abscissa if given, and
    /// lists the outputs written in the summary.
    void
    finish(const std::string                              &output_directory,
           const std::optional<std::pair<double, double>> &x_range =
             std::nullopt) const
    {
      const phase_times::Scope phase(phase_times::Phase::outputs);
      // Titled by the folder, which names the run ("elastica").
      ProbePlotOptions options;
      options.title        = "rodnet probes: " + run_name(output_directory);
      options.units        = units;
      options.n_probes     = probes.size();
      options.x_range      = x_range;
      options.length_scale = model.length_scale();
      // The solvers accept a residual of 1e-9 (their default relative
      // tolerance) of the loads or internal forces; a rod storing the
      // energy E over the size L carries internal forces of order E/L,
      // so reactions below 1e-8 of that are what an accepted residual
      // leaves (the reactions of a ring held against rigid motions).
      if (options.length_scale > 0)
        options.force_resolution = 1e-8 * largest_energy / options.length_scale;
      // A single state (a run that stopped at its first step) has no
      // plot.
      if (scene.plot && !summary.probe_names.empty() &&
          summary.rows.size() > 1 &&
          plot_probes(csv, output_directory + "/probes.png", options))
        summary.outputs.push_back("probes.png");
      if (vtu_files > 0)
        summary.outputs.push_back("solution.pvd");
      // The natural shape at the last step's load factor, which the
      // activation fields a picture may show follow (a solver may have
      // assembled at another since).
      if (pictures && last)
        model.elastic_energy(last->second, summary.final_load_factor);
      if (pictures && last &&
          pictures->finish(picture_state(model, last->second),
                           output_directory,
                           picture_title(last->first)))
        summary.outputs.push_back("picture.png");
    }

    /// The abscissa and state of the last step recorded, if any.
    const std::optional<std::pair<double, State>> &
    last_recorded() const
    {
      return last;
    }

  private:
    /// "elastica: load factor 1" or "elastica: time 0.5 s".
    std::string
    picture_title(const double abscissa) const
    {
      std::ostringstream text;
      text << run_name(directory) << ": "
           << (summary.abscissa == "time" ? "time " : "load factor ")
           << abscissa << (summary.abscissa == "time" ? " s" : "");
      return text.str();
    }

    /// probes.csv in @p directory, created if needed.
    static std::string
    csv_path(const std::string &directory)
    {
      std::filesystem::create_directories(directory);
      return directory + "/probes.csv";
    }

    /// Writes the VTU file of a step, up to run_limits::max_vtu_files
    /// (Scene refuses runs planned beyond it; cut steps may add some).
    void
    write_vtu(const unsigned int step, const double abscissa, const State &u)
    {
      if (vtu_files < run_limits::max_vtu_files)
        {
          vtu->write(step, abscissa, model, u);
          ++vtu_files;
        }
      else if (!vtu_capped)
        {
          std::cerr << "warning: " << vtu_files
                    << " VTU files written, the most one run writes; the "
                       "steps from "
                    << step << " on get none (raise \"Output/VTU interval\")"
                    << std::endl;
          vtu_capped = true;
        }
    }

    const Scene                     &scene;
    const Model<State>              &model;
    const ProbeList                 &probes;
    const std::string                directory;
    const std::string                csv;
    ProbeTable                       table;
    RunSummary                      &summary;
    std::unique_ptr<VtuOutput>       vtu;
    std::unique_ptr<NetworkPictures> pictures;
    unsigned int                     vtu_files  = 0;
    bool                             vtu_capped = false;
    /// The abscissa's unit, then each probe's.
    std::vector<std::string> units;
    /// The index of the check "stable" among the checks, if there.
    std::size_t stable_check;
    /// The probe values of the step before, for continue_probes().
    std::vector<double>                     previous_values;
    std::optional<std::pair<double, State>> last;
    /// The largest elastic energy of a recorded state (J): the scale of
    /// the internal forces (finish()).
    double largest_energy = 0;
  };
} // namespace rodnet

#endif
