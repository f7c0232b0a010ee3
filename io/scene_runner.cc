#include <deal.II/base/timer.h>

#include <io/interrupt.h>
#include <io/mode_shapes.h>
#include <io/network_picture.h>
#include <io/probe_plot.h>
#include <io/run_limits.h>
#include <io/scene_runner.h>
#include <io/vtu_output.h>
#include <solvers/lowest_eigenpairs.h>

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
    /// The name of the run in the folder @p output_directory: the folder's
    /// own name ("elastica").
    std::string
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
                   const std::string              &abscissa = "load_factor",
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
             const State               &u,
             const std::vector<double> &checks = {})
      {
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
        last = {abscissa, u};
        largest_energy =
          std::max(largest_energy,
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
          options.force_resolution =
            1e-8 * largest_energy / options.length_scale;
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
      auto model = build();
      if (report)
        *log << "  built in " << timer.wall_time() << " s" << std::endl;
      throw_if_stop_requested();
      return model;
    }

    /// Throws std::invalid_argument naming the first probe of @p probes
    /// that asks for the lowest eigenvalue, which @p method (the end of
    /// the message) does not track.
    void
    refuse_eigenvalue_probes(const ProbeList &probes, const std::string &method)
    {
      for (const auto &p : probes)
        if (p->needs_lowest_eigenvalue())
          throw std::invalid_argument("entry \"Output/Probes\", probe \"" +
                                      p->name() + "\": " + method);
    }

    /**
     * The lowest eigenvalue of @p model's constrained tangent at @p u and
     * @p load_factor (assembled into @p tangent) where one of @p probes
     * asks for it (lowest_eigenpairs(): sparse, linear in the DoFs); NaN
     * otherwise.
     */
    double
    lowest_eigenvalue_if_asked(const ProbeList  &probes,
                               const RodModel   &model,
                               const VectorType &u,
                               const double      load_factor,
                               MatrixType       &tangent)
    {
      if (!needs_lowest_eigenvalue(probes))
        return std::nan("");
      if (tangent.m() == 0)
        model.initialize_matrix(tangent);
      model.assemble(u, load_factor, nullptr, &tangent);
      return lowest_eigenpairs(tangent,
                               model.constraints(),
                               1,
                               model.multiplier_dofs())
        .values[0];
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

    /// StaticSolver's parameters of @p scene, tracking the lowest
    /// eigenvalue where one of @p probes asks for it.
    StaticSolver::Parameters
    static_parameters(const Scene &scene, const ProbeList &probes)
    {
      StaticSolver::Parameters parameters = scene.solver;
      if (needs_lowest_eigenvalue(probes))
        parameters.track_lowest_eigenvalue = true;
      parameters.strain_limits.fiber_distance = scene.fiber_distances();
      return parameters;
    }

    /**
     * The observer of a path of equilibria (Solver: StaticSolver or
     * ArclengthContinuation): counts the unstable and out-of-range steps
     * into @p summary and records each converged step in @p recorder with
     * its probes and @p checks_of(info), the values of its check columns.
     * @p lowest_eigenvalue_of(info, solution) is the lowest eigenvalue the
     * probes may ask for (NaN where none does); it is asked after the
     * counts, so that a failing eigen-solver finds the step counted.
     */
    template <class Solver, class LowestEigenvalue, class Checks>
    typename Solver::Observer
    record_equilibria(StepRecorder<VectorType> &recorder,
                      const ProbeList          &probes,
                      const RodModel           &model,
                      RunSummary               &summary,
                      const LowestEigenvalue    lowest_eigenvalue_of,
                      const Checks              checks_of)
    {
      return
        [&recorder, &probes, &model, &summary, lowest_eigenvalue_of, checks_of](
          const typename Solver::StepInfo &info,
          const VectorType                &solution) {
          summary.unstable_steps += !info.check.stable;
          summary.out_of_range_steps += !info.strain.in_range;
          recorder.record(info.step,
                          info.load_factor,
                          info.load_factor,
                          evaluate_probes(probes,
                                          model,
                                          solution,
                                          info.load_factor,
                                          lowest_eigenvalue_of(info, solution)),
                          solution,
                          checks_of(info));
        };
    }

    RunSummary
    run_newton(const Scene       &scene,
               const std::string &output_directory,
               std::ostream      *log)
    {
      const std::unique_ptr<RodModel> model =
        build_with_progress(scene, log, [&] { return scene.build_model(); });
      const ProbeList                probes = scene.probes(*model);
      const StaticSolver::Parameters parameters =
        static_parameters(scene, probes);

      RunSummary               summary;
      StepRecorder<VectorType> recorder(scene,
                                        output_directory,
                                        probes,
                                        *model,
                                        summary,
                                        "load_factor",
                                        {"stable", "in_range"});
      if (log != nullptr)
        *log << "rodnet: " << model->network().rods().size() << " rod(s), "
             << model->layout().n_dofs() << " DoFs, "
             << model->layout().hinges().size() << " hinges" << std::endl;

      VectorType   u = model->create_vector();
      StaticSolver solver(*model, parameters, log);
      run_guarded(summary, [&] {
        // Step 0: the unloaded state, where every run starts; it is not
        // checked (NaN in the check columns).
        recorder.record(0,
                        0.0,
                        0.0,
                        evaluate_probes(probes,
                                        *model,
                                        u,
                                        0.0,
                                        parameters.track_lowest_eigenvalue ?
                                          solver.lowest_eigenvalue(u, 0.0) :
                                          std::nan("")),
                        u,
                        {std::nan(""), std::nan("")});
        solver.run(u,
                   record_equilibria<StaticSolver>(
                     recorder,
                     probes,
                     *model,
                     summary,
                     [](const StaticSolver::StepInfo &info,
                        const VectorType &) { return info.lowest_eigenvalue; },
                     [](const StaticSolver::StepInfo &info) {
                       return std::vector<double>{double(info.check.stable),
                                                  double(info.strain.in_range)};
                     }));
      });
      summary.critical_load_factor = solver.critical_load_factor();
      recorder.finish(output_directory);
      write_requested_modes(scene,
                            *model,
                            recorder,
                            output_directory,
                            summary,
                            log);
      return summary;
    }

    /// The columns of probes.csv after the probes in a continuation run.
    const std::vector<std::string> continuation_columns = {
      "arclength",
      "branch",
      "negative_eigenvalues",
      "stable",
      "in_range",
      "jump"};

    /// The values of continuation_columns at the point @p info.
    std::vector<double>
    continuation_checks(const ArclengthContinuation::StepInfo &info)
    {
      return {info.arclength,
              double(info.branch),
              double(info.check.negative_eigenvalues),
              double(info.check.stable),
              double(info.strain.in_range),
              double(info.kind == ArclengthContinuation::PointKind::jump)};
    }

    RunSummary
    run_continuation(const Scene       &scene,
                     const std::string &output_directory,
                     std::ostream      *log)
    {
      const std::unique_ptr<RodModel> model =
        build_with_progress(scene, log, [&] { return scene.build_model(); });
      const ProbeList                   probes     = scene.probes(*model);
      ArclengthContinuation::Parameters parameters = scene.continuation;
      parameters.strain_limits.fiber_distance      = scene.fiber_distances();

      RunSummary               summary;
      StepRecorder<VectorType> recorder(scene,
                                        output_directory,
                                        probes,
                                        *model,
                                        summary,
                                        "load_factor",
                                        continuation_columns);
      if (log != nullptr)
        *log << "rodnet (continuation): " << model->network().rods().size()
             << " rod(s), " << model->layout().n_dofs() << " DoFs" << std::endl;
      VectorType            u = model->create_vector();
      ArclengthContinuation solver(*model, parameters, log);
      MatrixType            tangent;
      run_guarded(summary, [&] {
        solver.run(u,
                   record_equilibria<ArclengthContinuation>(
                     recorder,
                     probes,
                     *model,
                     summary,
                     [&](const ArclengthContinuation::StepInfo &info,
                         const VectorType                      &solution) {
                       return lowest_eigenvalue_if_asked(probes,
                                                         *model,
                                                         solution,
                                                         info.load_factor,
                                                         tangent);
                     },
                     continuation_checks));
      });
      if (!solver.bifurcations().empty())
        summary.critical_load_factor = solver.bifurcations().front();
      recorder.finish(output_directory);
      write_requested_modes(scene,
                            *model,
                            recorder,
                            output_directory,
                            summary,
                            log);
      return summary;
    }

    RunSummary
    run_dynamic_relaxation(const Scene       &scene,
                           const std::string &output_directory,
                           std::ostream      *log)
    {
      const std::unique_ptr<DrModel> model =
        build_with_progress(scene, log, [&] { return scene.build_dr_model(); });
      const ProbeList probes = scene.probes(*model);

      RunSummary             summary;
      StepRecorder<DrVector> recorder(scene,
                                      output_directory,
                                      probes,
                                      *model,
                                      summary);
      if (log != nullptr)
        *log << "rodnet (dynamic relaxation): "
             << model->network().rods().size() << " rod(s), " << model->n_dofs()
             << " DoFs, " << model->n_elements() << " elements" << std::endl;

      DrVector          u = model->create_vector();
      DynamicRelaxation solver(*model, scene.relaxation, log);
      run_guarded(summary, [&] {
        // Step 0: the unloaded state.
        recorder.record(0,
                        0.0,
                        0.0,
                        evaluate_probes(probes, *model, u, 0.0),
                        u);
        solver.run(u,
                   [&](const DynamicRelaxation::StepInfo &info,
                       const DrVector                    &solution) {
                     recorder.record(info.step,
                                     info.load_factor,
                                     info.load_factor,
                                     evaluate_probes(probes,
                                                     *model,
                                                     solution,
                                                     info.load_factor),
                                     solution);
                   });
      });
      recorder.finish(output_directory);
      return summary;
    }

    /// The check columns of probes.csv in a time-stepping run. Dynamic
    /// steps do not check stability: inertia holds their tangent.
    std::vector<std::string>
    time_stepping_columns(const bool dynamic)
    {
      return dynamic ? std::vector<std::string>{"in_range"} :
                       std::vector<std::string>{"stable", "in_range"};
    }

    /**
     * Records the states of a time-stepping run in a StepRecorder: the
     * probes, with the motion where a motion probe asks for it, and the
     * checks of time_stepping_columns(), counted into the summary.
     */
    class TimeStepRecording
    {
    public:
      TimeStepRecording(StepRecorder<VectorType> &recorder,
                        const ProbeList          &probes,
                        const RodModel           &model,
                        const TimeIntegrator     &integrator,
                        RunSummary               &summary,
                        const bool                dynamic)
          : recorder(recorder)
          , probes(probes)
          , model(model)
          , integrator(integrator)
          , summary(summary)
          , dynamic(dynamic)
          , motion_probes(first_motion_probe(probes) != nullptr)
      {
      }

      /// Records step @p step at @p time and @p load_factor, the state
      /// @p u moving at @p v; @p info is the integrator's account of the
      /// step, null for the initial state, which is not checked (NaN in
      /// its columns).
      void
      operator()(const unsigned int              step,
                 const double                    time,
                 const double                    load_factor,
                 const VectorType               &u,
                 const VectorType               &v,
                 const TimeIntegrator::StepInfo *info) const
      {
        const std::vector<double> values = checks(info);
        // Scene::probes() allows motion probes in dynamic runs only.
        const Motion motion =
          motion_probes ?
            motion_of(model, integrator.mass_matrix(), u, v, load_factor) :
            Motion();
        recorder.record(
          step,
          time,
          load_factor,
          evaluate_probes(probes, model, u, load_factor, std::nan(""), &motion),
          u,
          values);
      }

    private:
      /// The values of the check columns at the step of @p info, counted
      /// into the summary; NaN where @p info is null.
      std::vector<double>
      checks(const TimeIntegrator::StepInfo *info) const
      {
        std::vector<double> values(time_stepping_columns(dynamic).size(),
                                   std::nan(""));
        if (info != nullptr)
          {
            summary.unstable_steps += !info->stable;
            summary.out_of_range_steps += !info->strain.in_range;
            values.back() = info->strain.in_range;
            if (!dynamic)
              values.front() = info->stable;
          }
        return values;
      }

      StepRecorder<VectorType> &recorder;
      const ProbeList          &probes;
      const RodModel           &model;
      const TimeIntegrator     &integrator;
      RunSummary               &summary;
      const bool                dynamic;
      const bool                motion_probes;
    };

    /// The first line of a time-stepping run on @p log, if any.
    void
    log_time_stepping(std::ostream                     *log,
                      const RodModel                   &model,
                      const TimeIntegrator::Parameters &parameters)
    {
      if (log != nullptr)
        *log << "rodnet (time stepping, " << parameters.integrator
             << "): " << model.network().rods().size() << " rod(s), "
             << model.layout().n_dofs()
             << " DoFs, t = " << parameters.start_time << " to "
             << parameters.end_time << " s in steps of " << parameters.time_step
             << " s" << std::endl;
    }

    RunSummary
    run_time_stepping(const Scene       &scene,
                      const std::string &output_directory,
                      std::ostream      *log)
    {
      const std::unique_ptr<RodModel> model =
        build_with_progress(scene, log, [&] { return scene.build_model(); });
      const ProbeList probes = scene.probes(*model);
      refuse_eigenvalue_probes(probes,
                               "the lowest eigenvalue is tracked by Newton "
                               "load stepping only, not by time stepping");
      TimeIntegrator::Parameters parameters   = scene.time_stepping;
      parameters.strain_limits.fiber_distance = scene.fiber_distances();
      const bool     dynamic                  = parameters.dynamic();
      TimeIntegrator integrator(*model,
                                dynamic ? scene.inertia() :
                                          std::vector<RodInertia>(),
                                parameters,
                                log);

      RunSummary               summary;
      StepRecorder<VectorType> recorder(scene,
                                        output_directory,
                                        probes,
                                        *model,
                                        summary,
                                        "time",
                                        time_stepping_columns(dynamic));
      log_time_stepping(log, *model, parameters);
      const TimeStepRecording record(recorder,
                                     probes,
                                     *model,
                                     integrator,
                                     summary,
                                     dynamic);
      VectorType              u, v;
      scene.initial_state(*model, u, v);
      run_guarded(summary, [&] {
        // The history begins with the initial state, where the integrator
        // starts: at the start time, or before the preload.
        const double time = parameters.initial_time();
        integrator.start_state(u, v);
        record(0, time, parameters.load_factor(time), u, v, nullptr);
        integrator.run(u,
                       v,
                       [&](const TimeIntegrator::StepInfo &info,
                           const VectorType               &state,
                           const VectorType               &velocity) {
                         record(info.step,
                                info.time,
                                info.load_factor,
                                state,
                                velocity,
                                &info);
                       });
      });
      // The preload's rows stay in probes.csv; the plot shows the motion,
      // whose time scale is usually far shorter.
      recorder.finish(output_directory,
                      std::make_pair(parameters.start_time,
                                     parameters.end_time));
      return summary;
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
          return run_newton(scene, output_directory, log);
        case SolutionMethod::dynamic_relaxation:
          return run_dynamic_relaxation(scene, output_directory, log);
        case SolutionMethod::time_stepping:
          return run_time_stepping(scene, output_directory, log);
        case SolutionMethod::continuation:
          return run_continuation(scene, output_directory, log);
      }
    throw std::logic_error("run_scene: unknown solution method");
  }
} // namespace rodnet
