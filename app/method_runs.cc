#include <app/method_runs.h>
#include <core/every_entry.h>
#include <core/motion.h>
#include <solvers/stability/lowest_eigenpairs.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace rodnet
{
  namespace
  {
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
          // Probes and output read DoFs anywhere: gathered once.
          const EveryEntry every_entry(solution);
          recorder.record(info.step,
                          info.load_factor,
                          info.load_factor,
                          evaluate_probes(probes,
                                          model,
                                          *every_entry,
                                          info.load_factor,
                                          lowest_eigenvalue_of(info, solution)),
                          *every_entry,
                          checks_of(info));
        };
    }

    /// The columns of probes.csv after the probes in a continuation run.
    const std::vector<std::string> continuation_columns = {
      "arclength",
      "branch",
      "negative_eigenvalues",
      "stable",
      "in_range",
      "jump"};

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

    /// TimeIntegrator's parameters of @p scene; refuses the probes that
    /// ask for the lowest eigenvalue, which time stepping does not track.
    TimeIntegrator::Parameters
    time_stepping_parameters(const Scene &scene, const ProbeList &probes)
    {
      refuse_eigenvalue_probes(probes,
                               "the lowest eigenvalue is tracked by Newton "
                               "load stepping only, not by time stepping");
      TimeIntegrator::Parameters parameters   = scene.time_stepping;
      parameters.strain_limits.fiber_distance = scene.fiber_distances();
      return parameters;
    }

    /// ArclengthContinuation's parameters of @p scene.
    ArclengthContinuation::Parameters
    continuation_parameters(const Scene &scene)
    {
      ArclengthContinuation::Parameters parameters = scene.continuation;
      parameters.strain_limits.fiber_distance      = scene.fiber_distances();
      return parameters;
    }

    /// The parameters of @p Solver that @p scene and @p probes ask for.
    template <class Solver>
    typename Solver::Parameters
    equilibrium_parameters(const Scene &scene, const ProbeList &probes)
    {
      if constexpr (std::is_same_v<Solver, StaticSolver>)
        return static_parameters(scene, probes);
      else
        return continuation_parameters(scene);
    }

    /// The values of the check columns of a Newton load step.
    std::vector<double>
    equilibrium_checks(const StaticSolver::StepInfo &info)
    {
      return {double(info.check.stable), double(info.strain.in_range)};
    }

    /// The values of continuation_columns at the point @p info.
    std::vector<double>
    equilibrium_checks(const ArclengthContinuation::StepInfo &info)
    {
      return {info.arclength,
              double(info.branch),
              double(info.check.negative_eigenvalues),
              double(info.check.stable),
              double(info.strain.in_range),
              double(info.kind == ArclengthContinuation::PointKind::jump)};
    }
  } // namespace


  template <class Solver>
  EquilibriumRun<Solver>::EquilibriumRun(const Scene     &scene,
                                         RodModel        &model,
                                         const ProbeList &probes,
                                         std::ostream    *log)
      : MethodRun(model, probes)
      , parameters(equilibrium_parameters<Solver>(scene, probes))
      , u(model.create_vector())
      , solver(model, parameters, log)
  {
  }


  template <class Solver>
  std::vector<std::string>
  EquilibriumRun<Solver>::check_columns() const
  {
    if constexpr (std::is_same_v<Solver, StaticSolver>)
      return {"stable", "in_range"};
    else
      return continuation_columns;
  }


  template <class Solver>
  void
  EquilibriumRun<Solver>::describe(std::ostream *log) const
  {
    if (log == nullptr)
      return;
    if constexpr (std::is_same_v<Solver, StaticSolver>)
      *log << "rodnet: " << model.network().rods().size() << " rod(s), "
           << model.layout().n_dofs() << " DoFs, "
           << model.layout().hinges().size() << " hinges" << std::endl;
    else
      *log << "rodnet (continuation): " << model.network().rods().size()
           << " rod(s), " << model.layout().n_dofs() << " DoFs" << std::endl;
  }


  template <class Solver>
  void
  EquilibriumRun<Solver>::run(StepRecorder<VectorType> &recorder,
                              RunSummary               &summary)
  {
    // Newton's step 0: the unloaded state, where every run starts; it is
    // not checked (NaN in the check columns). A path records its start.
    if constexpr (std::is_same_v<Solver, StaticSolver>)
      recorder.record(0,
                      0.0,
                      0.0,
                      evaluate_probes(probes,
                                      model,
                                      u,
                                      0.0,
                                      parameters.track_lowest_eigenvalue ?
                                        solver.lowest_eigenvalue(u, 0.0) :
                                        std::nan("")),
                      u,
                      {std::nan(""), std::nan("")});
    solver.run(u,
               record_equilibria<Solver>(
                 recorder,
                 probes,
                 model,
                 summary,
                 [this](const typename Solver::StepInfo &info,
                        const VectorType                &solution) {
                   return lowest_eigenvalue_at(info, solution);
                 },
                 [](const typename Solver::StepInfo &info) {
                   return equilibrium_checks(info);
                 }));
  }


  template <class Solver>
  double
  EquilibriumRun<Solver>::lowest_eigenvalue_at(
    const typename Solver::StepInfo &info,
    const VectorType                &solution)
  {
    if constexpr (std::is_same_v<Solver, StaticSolver>)
      return info.lowest_eigenvalue;
    else
      return lowest_eigenvalue_if_asked(probes,
                                        model,
                                        solution,
                                        info.load_factor,
                                        tangent);
  }


  template <class Solver>
  void
  EquilibriumRun<Solver>::finish(RunSummary &summary) const
  {
    if constexpr (std::is_same_v<Solver, StaticSolver>)
      summary.critical_load_factor = solver.critical_load_factor();
    else if (!solver.bifurcations().empty())
      summary.critical_load_factor = solver.bifurcations().front();
  }


  template class EquilibriumRun<StaticSolver>;
  template class EquilibriumRun<ArclengthContinuation>;


  RelaxationRun::RelaxationRun(const Scene     &scene,
                               DrModel         &model,
                               const ProbeList &probes,
                               std::ostream    *log)
      : MethodRun(model, probes)
      , u(model.create_vector())
      , solver(model, scene.relaxation, log)
  {
  }


  void
  RelaxationRun::describe(std::ostream *log) const
  {
    if (log != nullptr)
      *log << "rodnet (dynamic relaxation): " << model.network().rods().size()
           << " rod(s), " << model.n_dofs() << " DoFs, " << model.n_elements()
           << " elements" << std::endl;
  }


  void
  RelaxationRun::run(StepRecorder<DrVector> &recorder, RunSummary &)
  {
    // Step 0: the unloaded state.
    recorder.record(0, 0.0, 0.0, evaluate_probes(probes, model, u, 0.0), u);
    solver.run(u,
               [&](const DynamicRelaxation::StepInfo &info,
                   const DrVector                    &solution) {
                 recorder.record(
                   info.step,
                   info.load_factor,
                   info.load_factor,
                   evaluate_probes(probes, model, solution, info.load_factor),
                   solution);
               });
  }


  TimeSteppingRun::TimeSteppingRun(const Scene     &scene,
                                   RodModel        &model,
                                   const ProbeList &probes,
                                   std::ostream    *log)
      : MethodRun(model, probes)
      , scene(scene)
      , parameters(time_stepping_parameters(scene, probes))
      , integrator(model,
                   parameters.dynamic() ? scene.inertia() :
                                          std::vector<RodInertia>(),
                   parameters,
                   log)
  {
  }


  std::vector<std::string>
  TimeSteppingRun::check_columns() const
  {
    return time_stepping_columns(parameters.dynamic());
  }


  void
  TimeSteppingRun::describe(std::ostream *log) const
  {
    if (log != nullptr)
      *log << "rodnet (time stepping, " << parameters.integrator
           << "): " << model.network().rods().size() << " rod(s), "
           << model.layout().n_dofs() << " DoFs, t = " << parameters.start_time
           << " to " << parameters.end_time << " s in steps of "
           << parameters.time_step << " s" << std::endl;
  }


  void
  TimeSteppingRun::run(StepRecorder<VectorType> &recorder, RunSummary &summary)
  {
    const TimeStepRecording record(recorder,
                                   probes,
                                   model,
                                   integrator,
                                   summary,
                                   parameters.dynamic());
    VectorType              u, v;
    scene.initial_state(model, u, v);
    // The history begins with the initial state, where the integrator
    // starts: at the start time, or before the preload.
    const double time = parameters.initial_time();
    integrator.start_state(u, v);
    record(0, time, parameters.load_factor(time), u, v, nullptr);
    integrator.run(
      u,
      v,
      [&](const TimeIntegrator::StepInfo &info,
          const VectorType               &state,
          const VectorType               &velocity) {
        record(info.step, info.time, info.load_factor, state, velocity, &info);
      });
  }
} // namespace rodnet
