#ifndef RODNET_APP_METHOD_RUNS_H
#define RODNET_APP_METHOD_RUNS_H

#include <app/step_recorder.h>
#include <core/dr_model.h>
#include <core/rod_model.h>
#include <io/probes.h>
#include <io/scene.h>
#include <solvers/continuation/arclength_continuation.h>
#include <solvers/relaxation/dynamic_relaxation.h>
#include <solvers/statics/static_solver.h>
#include <solvers/time/time_integrator.h>

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rodnet
{
  /**
   * @name What each solution method adds to the one sequence of a scene's
   * run (run_scene(), app/scene_runner.cc): the model it builds, the check
   * columns of probes.csv, its first line on the log, its run over the
   * steps into a StepRecorder, and what it adds to the summary. The
   * sequence itself (build, probes, recorder, guarded run, plots, mode
   * shapes) is written once.
   */
  /// @{

  /**
   * What the methods share: the model of type @p ModelT (states of type
   * @p VectorT) and the probes; the defaults of a method (load factor as
   * the abscissa, no plot range, no mode shapes, nothing added to the
   * summary after the run), which a method hides where it differs.
   */
  template <class ModelT, class VectorT>
  class MethodRun
  {
  public:
    using ModelType                    = ModelT;
    using Vector                       = VectorT;
    static constexpr bool writes_modes = false;

    /// The model the scene describes for this method.
    static std::unique_ptr<ModelT>
    build(const Scene &scene)
    {
      if constexpr (std::is_same_v<ModelT, DrModel>)
        return scene.build_dr_model();
      else
        return scene.build_model();
    }

    std::string
    abscissa() const
    {
      return "load_factor";
    }

    std::optional<std::pair<double, double>>
    plot_range() const
    {
      return std::nullopt;
    }

    void
    finish(RunSummary &) const
    {
    }

  protected:
    MethodRun(ModelT &model, const ProbeList &probes)
        : model(model)
        , probes(probes)
    {
    }

    ModelT          &model;
    const ProbeList &probes;
  };

  /**
   * The methods that follow equilibria of a RodModel with @p Solver and
   * write mode shapes: Newton load stepping (NewtonRun, StaticSolver) and
   * path following (ContinuationRun, ArclengthContinuation). Defined for
   * these two in method_runs.cc.
   */
  template <class Solver>
  class EquilibriumRun : public MethodRun<RodModel, VectorType>
  {
  public:
    static constexpr bool writes_modes = true;

    EquilibriumRun(const Scene     &scene,
                   RodModel        &model,
                   const ProbeList &probes,
                   std::ostream    *log);

    std::vector<std::string>
    check_columns() const;

    void
    describe(std::ostream *log) const;

    /// Records every converged state: Newton's unloaded state and load
    /// steps, every point of the path.
    void
    run(StepRecorder<VectorType> &recorder, RunSummary &summary);

    /// The critical load factor: the one StaticSolver found, or the path's
    /// first bifurcation, if any.
    void
    finish(RunSummary &summary) const;

  private:
    /// The lowest eigenvalue at the converged @p solution of the step
    /// @p info, for the probes: StaticSolver tracks it where they ask;
    /// along a path it is computed here (NaN where no probe asks).
    double
    lowest_eigenvalue_at(const typename Solver::StepInfo &info,
                         const VectorType                &solution);

    const typename Solver::Parameters parameters;
    VectorType                        u;
    Solver                            solver;
    /// The tangent of lowest_eigenvalue_at() along a path.
    MatrixType tangent;
  };

  extern template class EquilibriumRun<StaticSolver>;
  extern template class EquilibriumRun<ArclengthContinuation>;

  /// Newton load stepping (Solver/Method = newton), StaticSolver.
  using NewtonRun = EquilibriumRun<StaticSolver>;

  /// Path following (Solver/Method = continuation), ArclengthContinuation.
  using ContinuationRun = EquilibriumRun<ArclengthContinuation>;

  /// Dynamic relaxation of the bending-active element (Solver/Method =
  /// dynamic relaxation), on a DrModel.
  class RelaxationRun : public MethodRun<DrModel, DrVector>
  {
  public:
    RelaxationRun(const Scene     &scene,
                  DrModel         &model,
                  const ProbeList &probes,
                  std::ostream    *log);

    std::vector<std::string>
    check_columns() const
    {
      return {};
    }

    void
    describe(std::ostream *log) const;

    /// Records the unloaded state and every load step relaxed.
    void
    run(StepRecorder<DrVector> &recorder, RunSummary &summary);

  private:
    DrVector          u;
    DynamicRelaxation solver;
  };

  /// Time stepping, quasi-static or dynamic (Solver/Method = time
  /// stepping), TimeIntegrator.
  class TimeSteppingRun : public MethodRun<RodModel, VectorType>
  {
  public:
    TimeSteppingRun(const Scene     &scene,
                    RodModel        &model,
                    const ProbeList &probes,
                    std::ostream    *log);

    std::string
    abscissa() const
    {
      return "time";
    }

    std::vector<std::string>
    check_columns() const;

    void
    describe(std::ostream *log) const;

    /// Records the initial state and every time step.
    void
    run(StepRecorder<VectorType> &recorder, RunSummary &summary);

    /// From the start to the end time: the preload's rows stay in
    /// probes.csv, the plot shows the motion, whose time scale is usually
    /// far shorter.
    std::optional<std::pair<double, double>>
    plot_range() const
    {
      return std::make_pair(parameters.start_time, parameters.end_time);
    }

  private:
    const Scene                     &scene;
    const TimeIntegrator::Parameters parameters;
    TimeIntegrator                   integrator;
  };
  /// @}
} // namespace rodnet

#endif
