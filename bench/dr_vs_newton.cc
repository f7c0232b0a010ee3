// Dynamic relaxation against Newton: accuracy against wall time on three
// problems, and how far each method can be pushed before it fails.
//
// Newton: discrete elastic rods (RodModel, "simple" hinges) solved by
// StaticSolver (full Newton steps, relative tolerance 1e-9). Dynamic
// relaxation (DR): the bending-active element (DrModel) relaxed by
// DynamicRelaxation (time step 1, mass scaling 1, residual tolerance 1e-6).
// Each method runs the same physical problem at several resolutions; the
// time is the wall time from the model's construction to the final
// equilibrium, median (min-max) of the repeats, one thread.
//
// Studies (--study, comma-separated; default all):
//
// cantilever: a rod of length 1 (EI1 = 1 in the plane of the load, EA =
//   1.6e5, see unit_rod), clamped at x = 0, tip load P = 1e-3 along e_y in
//   one load step. Error: |w - P L^3/(3EI)| / (P L^3/(3EI)); the geometric
//   nonlinearity adds ~1e-7 at this load (1.1e-5 at P = 1e-2).
// elastica: the same rod under a dead compressive tip load P = 3 (units
//   EI/L^2; buckling at pi^2/4) with a transverse imperfection 1e-5 P along
//   e_y, in one load step (DR) or six (Newton, switching onto the buckled
//   branch along the lowest eigenmode as tests/validation/elastica.cc
//   does; see elastica_settings). Error: max(|x - x_exact|, |delta -
//   delta_exact|) / L against the inextensible elastica
//   (tests/common/elastica_exact.h).
//   Both rod studies run N = 10, 20, ... --rod-max segments for each method
//   and then DR at N = 20 with residual tolerances 1e-2 ... 1e-8: DR's
//   error is that of the mesh or that of its termination criterion,
//   whichever is larger.
// gridshell: scenes/gridshell.prm (Newton in its 40 steps with branch
//   switching, DR in 5 steps as tests/validation/gridshell.cc), with 2, 4
//   and 8 segments per lath. Errors against the finest Newton run (16
//   segments, untimed): the crown rise (z of n_2_2), and the largest
//   distance between a node of the run and the node of the reference at the
//   same undeformed position, over all nodes of the run.
// stability: DR: the time step above which the relaxation fails, with time
//   step cuts disabled (min_time_step_fraction = 1), for mass scalings 1, 4
//   and 100 on the cantilever and elastica (N = 20), P1 (N = 50) and the
//   gridshell (4 segments), against the bound sqrt(2 mass_scaling) the
//   masses are designed for. Newton: the largest single load step, n_steps =
//   1, 2, 4, ... with step cutting disabled (min_step_fraction = 1), that
//   converges (for the elastica: to the buckled state) for the elastica
//   (N = 40) and P1 (N = 100), with each line search; and, since for the
//   elastica that is not monotone, every n_steps = 1 ... 64 with full
//   steps. The message of the first failure beyond the limit is printed
//   with whether the returned state is finite.
//
// Rods of N segments: Newton's starts half a segment behind the clamp (the
// two-vertex midpoint clamp), DR's at the clamp (one-node clamp).
//
// Results go to dr_vs_newton_<study>.csv in the current directory;
// bench/dr_vs_newton.gp draws doc/dr_vs_newton_<problem>.png from them.
//
// Usage: dr_vs_newton [--study cantilever,elastica,gridshell,stability]
// [--repeats n] [--threads n] [--rod-max N] (finest rod mesh of cantilever
// and elastica, from 10 doubling; default 160) [--gridshell-reference n]
// (segments per lath of the reference run; default 16)
#include <deal.II/base/parameter_handler.h>

#include <core/dr_model.h>
#include <core/rod_model.h>
#include <geometry/rod_generators.h>
#include <io/scene.h>
#include <materials/linear_elastic_rod.h>
#include <solvers/relaxation/dynamic_relaxation.h>
#include <solvers/statics/static_solver.h>

#include <array>
#include <bench/options.h>
#include <bench/p1_problem.h>
#include <bench/timing.h>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tests/common/elastica_exact.h>
#include <vector>

using namespace rodnet;

namespace
{
  /// "a,b,c" into the set {a, b, c}, each one of the known studies.
  std::set<std::string>
  studies_in(const std::string &list)
  {
    std::set<std::string> studies;
    std::stringstream     stream(list);
    std::string           study;
    while (std::getline(stream, study, ','))
      {
        if (study != "cantilever" && study != "elastica" &&
            study != "gridshell" && study != "stability")
          throw std::invalid_argument(
            "unknown study " + study +
            "; known: cantilever, elastica, gridshell, stability");
        studies.insert(study);
      }
    return studies;
  }

  struct Options
  {
    std::set<std::string> studies             = {"cantilever",
                                                 "elastica",
                                                 "gridshell",
                                                 "stability"};
    unsigned int          threads             = 1;
    unsigned int          repeats             = 3;
    unsigned int          rod_max             = 160;
    unsigned int          gridshell_reference = 16;

    /// The options of the usage line above.
    std::vector<bench::Option>
    command_line()
    {
      return {{"--study",
               [this](const std::string &list) { studies = studies_in(list); }},
              bench::number("--repeats", repeats, 1),
              bench::number("--threads", threads),
              bench::number("--rod-max", rod_max),
              bench::number("--gridshell-reference", gridshell_reference)};
    }
  };


  enum class Method
  {
    newton,
    dynamic_relaxation
  };

  std::string
  to_string(const Method method)
  {
    return method == Method::newton ? "newton" : "dynamic relaxation";
  }

  /// Solver settings of a problem for both methods.
  struct Settings
  {
    StaticSolver::Parameters      newton;
    DynamicRelaxation::Parameters relaxation;
  };

  /// What a solve produced: every vertex before and after, and the effort.
  struct Outcome
  {
    std::vector<Vector3> initial, current;
    unsigned int         probe      = 0; ///< tip, or the gridshell's crown
    unsigned int         dofs       = 0;
    unsigned int         steps      = 0; ///< converged load steps
    unsigned int         iterations = 0; ///< Newton or DR iterations
  };

  template <class State>
  void
  record_positions(const Model<State> &model, const State &u, Outcome &outcome)
  {
    const RodNetwork &network = model.network();
    for (unsigned int v = 0; v < network.n_vertices(); ++v)
      {
        outcome.initial.push_back(network.vertex(v));
        outcome.current.push_back(model.position(u, v));
      }
  }

  Outcome
  solve(RodModel &model, const StaticSolver::Parameters &parameters)
  {
    Outcome    outcome;
    VectorType u = model.create_vector();
    StaticSolver(model, parameters)
      .run(u, [&](const StaticSolver::StepInfo &info, const VectorType &) {
        ++outcome.steps;
        outcome.iterations += info.iterations;
      });
    outcome.dofs = u.size();
    record_positions(model, u, outcome);
    return outcome;
  }

  Outcome
  solve(const DrModel &model, const DynamicRelaxation::Parameters &parameters)
  {
    Outcome  outcome;
    DrVector u = model.create_vector();
    outcome.iterations =
      DynamicRelaxation(model, parameters)
        .run(u, [&](const auto &, const auto &) { ++outcome.steps; })
        .total_iterations;
    outcome.dofs = u.size();
    record_positions(model, u, outcome);
    return outcome;
  }

  /// The rod of the cantilever and the elastica: L = 1, EI1 = 1 for bending
  /// in the xy plane (about the normal e_z), where the loads act; EA = 4
  /// EI1/r^2 of a round rod with L/r = 200; GJ = 2 EI1/3 (nu = 0.5). EI2 = 2
  /// out of that plane, so that the elastica buckles in it: with EI2 = EI1
  /// Newton's lowest eigenmode may lie in either plane, and its branch
  /// switching then finds no stable state.
  const RodStiffness unit_rod{4 * 200 * 200, 1, 2, 2.0 / 3};

  /// A straight rod of @p n segments along e_x, clamped at x = 0 (from
  /// half a segment behind it for Newton's midpoint clamp).
  std::unique_ptr<RodNetwork>
  straight_rod(const unsigned int n, const bool midpoint_clamp)
  {
    auto network = std::make_unique<RodNetwork>();
    network->add_rod(generators::straight(Vector3::Zero(),
                                          Vector3::UnitX(),
                                          n,
                                          midpoint_clamp),
                     false,
                     Vector3::UnitZ(),
                     "simple");
    network->create_triangulation();
    return network;
  }

  /// The straight rod for Newton under the tip force @p force.
  std::unique_ptr<RodModel>
  newton_rod(const unsigned int n, const Vector3 &force)
  {
    auto               network = straight_rod(n, true);
    const unsigned int tip     = network->rods()[0].vertices.back();
    auto               model   = std::make_unique<RodModel>(
      std::move(network),
      std::vector<std::shared_ptr<const RodMaterial>>{
                        std::make_shared<LinearElasticRod>(unit_rod)});
    model->clamp_end("clamp", 0, true);
    model->add_point_force(tip, force);
    model->finalize();
    return model;
  }

  /// The same for dynamic relaxation.
  std::unique_ptr<DrModel>
  dr_rod(const unsigned int n, const Vector3 &force)
  {
    auto model = std::make_unique<DrModel>(straight_rod(n, false),
                                           std::vector<RodStiffness>{unit_rod});
    model->clamp_end("clamp", 0, true);
    model->add_point_force(model->network().rods()[0].vertices.back(), force);
    model->finalize();
    return model;
  }

  /// The straight rod under @p force solved by @p method.
  Outcome
  loaded_rod(const Method       method,
             const unsigned int n,
             const Vector3     &force,
             const Settings    &settings)
  {
    Outcome outcome;
    if (method == Method::newton)
      {
        const std::unique_ptr<RodModel> model = newton_rod(n, force);
        outcome                               = solve(*model, settings.newton);
        outcome.probe = model->network().rods()[0].vertices.back();
      }
    else
      {
        const auto rod = dr_rod(n, force);
        outcome        = solve(*rod, settings.relaxation);
        outcome.probe  = rod->network().rods()[0].vertices.back();
      }
    return outcome;
  }

  constexpr double cantilever_load = 1e-3;
  constexpr double elastica_load   = 3;

  Settings
  cantilever_settings()
  {
    Settings s;
    s.newton.n_steps = 1;
    return s;
  }

  Settings
  elastica_settings()
  {
    Settings s;
    // Branch switching finds the buckled state only from a load shortly
    // past P_cr = 2.47: 6 steps (P = 2.5) do; 4 and 8 steps (P = 2.25 -> 3,
    // 2.625) stay on the straight, unstable branch.
    s.newton.n_steps                 = 6;
    s.newton.branch_switch_amplitude = 0.1;
    return s;
  }

  /// The tip loads: P along e_y; P along -e_x with the imperfection 1e-5 P
  /// along e_y (smaller ones are within DR's residual tolerance, which then
  /// accepts the straight state).
  Vector3
  cantilever_force()
  {
    return Vector3(0, cantilever_load, 0);
  }

  Vector3
  elastica_force()
  {
    return Vector3(-elastica_load, 1e-5 * elastica_load, 0);
  }

  Outcome
  cantilever(const Method method, const unsigned int n, const Settings &s)
  {
    return loaded_rod(method, n, cantilever_force(), s);
  }

  Outcome
  elastica(const Method method, const unsigned int n, const Settings &s)
  {
    return loaded_rod(method, n, elastica_force(), s);
  }

  /// scenes/gridshell.prm with @p segments per lath for @p method; DR in
  /// 5 load steps (from 2 it may settle in another vault).
  Scene
  gridshell_scene(const unsigned int segments, const Method method)
  {
    std::ifstream     file(RODNET_SOURCE_DIR "/scenes/gridshell.prm");
    std::stringstream text;
    text << file.rdbuf();
    AssertThrow(file, dealii::ExcMessage("cannot read scenes/gridshell.prm"));
    // Later entries override the file's.
    text << "subsection Geometry\n  set Segments = " << segments
         << "\nend\nsubsection Solver\n  set Method = " << to_string(method)
         << "\nend\n";
    if (method == Method::dynamic_relaxation)
      text << "subsection Loads\n  set Steps = 5\nend\n";
    dealii::ParameterHandler prm;
    Scene::declare_parameters(prm);
    prm.parse_input_from_string(text.str());
    return Scene(prm, RODNET_SOURCE_DIR "/scenes");
  }

  Outcome
  gridshell(const Scene &scene)
  {
    Outcome outcome;
    if (scene.method == SolutionMethod::newton)
      {
        const std::unique_ptr<RodModel> model = scene.build_model();
        outcome                               = solve(*model, scene.solver);
        outcome.probe = model->network().named_vertex("n_2_2");
      }
    else
      {
        const auto dr = scene.build_dr_model();
        outcome       = solve(*dr, scene.relaxation);
        outcome.probe = dr->network().named_vertex("n_2_2");
      }
    return outcome;
  }

  /// One point of an accuracy study.
  struct Point
  {
    std::string       series; ///< method, and how it was refined
    unsigned int      n;
    double            tolerance; ///< DR residual or Newton relative
    Outcome           outcome;
    bench::Statistics time;
  };

  /// Wall times of @p repeats runs of @p work. Runs under a second get
  /// bench::time_repeats' untimed warm-up; for longer ones its effects
  /// (page faults, lazy allocations) are far below the noise and the first
  /// run counts as a sample, which keeps a full run of the program within
  /// ten minutes.
  std::vector<double>
  timed(const unsigned int repeats, const std::function<void()> &work)
  {
    const double start = bench::now();
    work();
    std::vector<double> samples{bench::now() - start};
    if (samples[0] < 1)
      return bench::time_repeats(repeats, work);
    while (samples.size() < repeats)
      {
        const double t = bench::now();
        work();
        samples.push_back(bench::now() - t);
      }
    return samples;
  }

  /// Times @p work into @p point; false (with the message printed) if it
  /// fails.
  bool
  measure(const std::function<Outcome()> &work,
          const unsigned int              repeats,
          Point                          &point)
  {
    try
      {
        point.time =
          bench::statistics(timed(repeats, [&] { point.outcome = work(); }));
        return true;
      }
    catch (const std::exception &e)
      {
        std::cout << "  " << point.series << " N " << point.n << ": failed ("
                  << e.what() << ")\n";
      }
    return false;
  }

  /// Writes the points of a study and prints them; @p error gives the
  /// error of a point and @p node_error the largest node error (NaN where
  /// the study has none).
  void
  report(const std::string                            &study,
         const std::vector<Point>                     &points,
         const std::function<double(const Outcome &)> &value,
         const std::function<double(const Outcome &)> &error,
         const std::function<double(const Outcome &)> &node_error)
  {
    const std::string name = "dr_vs_newton_" + study + ".csv";
    std::ofstream     csv(name);
    csv.precision(10);
    csv << "series,N,tolerance,dofs,load_steps,iterations,time_median_s,"
           "time_min_s,time_max_s,value,error,node_error\n";
    for (const Point &p : points)
      {
        const Outcome &o = p.outcome;
        csv << p.series << ',' << p.n << ',' << p.tolerance << ',' << o.dofs
            << ',' << o.steps << ',' << o.iterations << ',' << p.time.median
            << ',' << p.time.min << ',' << p.time.max << ',' << value(o) << ','
            << error(o) << ',' << node_error(o) << '\n';
        std::printf(
          "  %-28s N %4u  tol %.0e  dofs %5u  steps %2u  "
          "iterations %7u  time %-26s  value %.8f  error %.2e%s\n",
          p.series.c_str(),
          p.n,
          p.tolerance,
          o.dofs,
          o.steps,
          o.iterations,
          bench::format_time(p.time).c_str(),
          value(o),
          error(o),
          std::isnan(node_error(o)) ?
            "" :
            ("  node error " + std::to_string(node_error(o))).c_str());
      }
    std::cout << "  wrote " << name << std::endl;
  }

  /// Accuracy against time of a straight-rod problem: both methods at
  /// N = 10, 20, ... up to --rod-max, then DR at N = 20 with residual
  /// tolerances from 1e-2 to 1e-9 (where its error is that of the
  /// termination, not of the mesh).
  void
  rod_study(const std::string &study,
            Outcome (*problem)(Method, unsigned int, const Settings &),
            const Settings                               &settings,
            const std::function<double(const Outcome &)> &value,
            const std::function<double(const Outcome &)> &error,
            const Options                                &options)
  {
    std::cout << "\n"
              << study << ": median (min-max) of " << options.repeats
              << " repeats, " << options.threads << " thread(s)\n";
    std::vector<Point> points;
    for (const Method method : {Method::newton, Method::dynamic_relaxation})
      for (unsigned int n = 10; n <= options.rod_max; n *= 2)
        {
          Point point{to_string(method),
                      n,
                      method == Method::newton ?
                        settings.newton.relative_tolerance :
                        settings.relaxation.residual_tolerance,
                      {},
                      {}};
          if (!measure([&] { return problem(method, n, settings); },
                       options.repeats,
                       point))
            break;
          points.push_back(point);
        }
    for (const double tolerance : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8})
      {
        Settings s                      = settings;
        s.relaxation.residual_tolerance = tolerance;
        Point point{"dynamic relaxation N = 20", 20, tolerance, {}, {}};
        if (measure([&] { return problem(Method::dynamic_relaxation, 20, s); },
                    options.repeats,
                    point))
          points.push_back(point);
      }
    report(study, points, value, error, [](const Outcome &) { return NAN; });
  }

  void
  cantilever_study(const Options &options)
  {
    const double exact = cantilever_load / 3;
    const auto   w     = [](const Outcome &o) { return o.current[o.probe][1]; };
    rod_study(
      "cantilever",
      cantilever,
      cantilever_settings(),
      w,
      [&](const Outcome &o) { return std::abs(w(o) - exact) / exact; },
      options);
  }

  /// Tip of the elastica: axial position and distance from the load axis.
  testing::ElasticaTip
  elastica_tip_of(const Vector3 &tip)
  {
    return {tip[0], std::hypot(tip[1], tip[2])};
  }

  void
  elastica_study(const Options &options)
  {
    const testing::ElasticaTip exact = testing::elastica_tip(elastica_load);
    std::cout << "\nexact elastica tip at P = " << elastica_load << ": x "
              << exact.x << ", delta " << exact.delta << "\n";
    rod_study(
      "elastica",
      elastica,
      elastica_settings(),
      [](const Outcome &o) {
        return elastica_tip_of(o.current[o.probe]).delta;
      },
      [&](const Outcome &o) {
        const testing::ElasticaTip tip = elastica_tip_of(o.current[o.probe]);
        return std::max(std::abs(tip.x - exact.x),
                        std::abs(tip.delta - exact.delta));
      },
      options);
  }

  /// Largest distance between a node of @p run and the node of
  /// @p reference at the same undeformed position (nested meshes share
  /// their coarse nodes exactly).
  double
  node_error(const Outcome &run, const Outcome &reference)
  {
    const auto key = [](const Vector3 &x) {
      return std::array<long, 3>{{std::lround(x[0] * 1e8),
                                  std::lround(x[1] * 1e8),
                                  std::lround(x[2] * 1e8)}};
    };
    std::map<std::array<long, 3>, Vector3> deformed;
    for (unsigned int v = 0; v < reference.initial.size(); ++v)
      deformed[key(reference.initial[v])] = reference.current[v];
    double largest = 0;
    for (unsigned int v = 0; v < run.initial.size(); ++v)
      {
        const auto match = deformed.find(key(run.initial[v]));
        AssertThrow(match != deformed.end(),
                    dealii::ExcMessage("a node without reference node"));
        largest = std::max(largest, (run.current[v] - match->second).norm());
      }
    return largest;
  }

  void
  gridshell_study(const Options &options)
  {
    std::cout << "\ngridshell: reference Newton run with "
              << options.gridshell_reference
              << " segments per lath (untimed)\n";
    const double  start = bench::now();
    const Outcome reference =
      gridshell(gridshell_scene(options.gridshell_reference, Method::newton));
    const auto crown = [](const Outcome &o) { return o.current[o.probe][2]; };
    std::printf("  reference: %u DoFs, %u steps, %u Newton iterations, "
                "crown %.8f, %.1f s\n",
                reference.dofs,
                reference.steps,
                reference.iterations,
                crown(reference),
                bench::now() - start);
    std::cout << "gridshell: median (min-max) of " << options.repeats
              << " repeats, " << options.threads << " thread(s)\n";
    std::vector<Point> points;
    for (const Method method : {Method::newton, Method::dynamic_relaxation})
      for (unsigned int segments = 2; segments < options.gridshell_reference;
           segments *= 2)
        {
          const Scene scene = gridshell_scene(segments, method);
          Point       point{to_string(method),
                      segments,
                      method == Method::newton ?
                              scene.solver.relative_tolerance :
                              scene.relaxation.residual_tolerance,
                      {},
                      {}};
          if (measure([&] { return gridshell(scene); }, options.repeats, point))
            points.push_back(point);
        }
    report(
      "gridshell",
      points,
      crown,
      [&](const Outcome &o) { return std::abs(crown(o) - crown(reference)); },
      [&](const Outcome &o) { return node_error(o, reference); });
  }

  /// How a run at the edge of stability ended.
  struct Trial
  {
    bool         converged  = false;
    unsigned int iterations = 0;
    std::string  message;       ///< why it failed
    bool         finite = true; ///< the state left behind
    Vector3      tip;
  };

  /// A failure message if a converged @p trial is not the expected state:
  /// the elastica must have buckled.
  using Check = std::function<std::string(const Trial &)>;

  std::string
  accept_any(const Trial &)
  {
    return "";
  }

  std::string
  buckled(const Trial &trial)
  {
    return elastica_tip_of(trial.tip).delta > 0.1 ?
             "" :
             "converged, but to the straight (unstable) equilibrium, "
             "tip deflection " +
               std::to_string(elastica_tip_of(trial.tip).delta);
  }

  /// Applies @p check to a converged @p trial.
  Trial
  checked(Trial trial, const Check &check)
  {
    if (trial.converged)
      {
        trial.message   = check(trial);
        trial.converged = trial.message.empty();
      }
    return trial;
  }

  /// DR of a stability problem with the given parameters.
  using DrProblem = std::function<Trial(const DynamicRelaxation::Parameters &)>;

  /// Runs DR on @p model; a failure leaves its message and whether the
  /// returned state is finite.
  Trial
  dr_trial(const DrModel &model, const DynamicRelaxation::Parameters &p)
  {
    Trial    trial;
    DrVector u = model.create_vector();
    try
      {
        trial.iterations = DynamicRelaxation(model, p)
                             .run(u, [](const auto &, const auto &) {})
                             .total_iterations;
        trial.converged = true;
      }
    catch (const std::exception &e)
      {
        trial.message = e.what();
      }
    trial.finite = std::isfinite(u.l2_norm());
    trial.tip    = model.position(u, model.network().rods()[0].vertices.back());
    return trial;
  }

  DrProblem
  dr_rod_problem(const Vector3 &force, const unsigned int n)
  {
    return [=](const DynamicRelaxation::Parameters &p) {
      return dr_trial(*dr_rod(n, force), p);
    };
  }

  /// The largest time step with which DR still converges, for each mass
  /// scaling, by doubling and then bisection (to 1%) with time-step cuts
  /// disabled; max_iterations is 20 times the iterations at the defaults.
  void
  dr_stability(const std::string &name,
               const DrProblem   &problem,
               const Check       &check,
               const Settings    &settings,
               std::ofstream     &csv)
  {
    DynamicRelaxation::Parameters p       = settings.relaxation;
    const Trial                   nominal = checked(problem(p), check);
    AssertThrow(nominal.converged,
                dealii::ExcMessage(
                  name + " fails at the default settings: " + nominal.message));
    p.min_time_step_fraction = 1;
    p.max_iterations         = 20 * nominal.iterations;
    for (const double scaling : {1.0, 4.0, 100.0})
      {
        p.mass_scaling     = scaling;
        const double bound = std::sqrt(2 * scaling);
        double       lo = 0, hi = 0; // converges at lo, fails at hi
        Trial        at_lo, at_hi;
        const auto   run = [&](const double dt) {
          p.time_step                       = dt;
          const Trial trial                 = checked(problem(p), check);
          (trial.converged ? lo : hi)       = dt;
          (trial.converged ? at_lo : at_hi) = trial;
        };
        for (double dt = bound; hi == 0 && dt < 64 * bound; dt *= 2)
          run(dt);
        for (double dt = bound / 2; lo == 0 && dt > bound / 64; dt /= 2)
          run(dt);
        while (lo > 0 && hi > 0 && hi - lo > 0.01 * lo)
          run(0.5 * (lo + hi));
        std::printf("  %-20s mass scaling %3g: converges up to dt = %.4g "
                    "(%.3f sqrt(2 s), %u iterations; %u at dt = 1), fails at "
                    "%.4g (%.3f sqrt(2 s)): %s; state %s\n",
                    name.c_str(),
                    scaling,
                    lo,
                    lo / bound,
                    at_lo.iterations,
                    nominal.iterations,
                    hi,
                    hi / bound,
                    at_hi.message.c_str(),
                    at_hi.finite ? "finite" : "NOT FINITE");
        std::fflush(stdout);
        csv << "dynamic relaxation," << name << ",mass scaling " << scaling
            << ',' << lo << ',' << hi << ',' << lo / bound << ',' << hi / bound
            << ',' << at_lo.iterations << ",\"" << at_hi.message << "\","
            << at_hi.finite << '\n';
      }
  }

  /// Newton on @p model: converged or the failure.
  Trial
  newton_trial(RodModel &model, const StaticSolver::Parameters &p)
  {
    Trial      trial;
    VectorType u = model.create_vector();
    try
      {
        StaticSolver(model, p).run(u,
                                   [&](const StaticSolver::StepInfo &info,
                                       const VectorType &) {
                                     trial.iterations += info.iterations;
                                   });
        trial.converged = true;
      }
    catch (const std::exception &e)
      {
        trial.message = e.what();
      }
    trial.finite = std::isfinite(u.l2_norm());
    trial.tip =
      model.configuration().position(u,
                                     model.network().rods()[0].vertices.back());
    return trial;
  }

  /// The fewest load steps (1, 2, 4, ... 256) in which Newton converges
  /// (to the state @p check expects) with step cutting disabled, for each
  /// line search.
  void
  newton_stability(
    const std::string                                            &name,
    const std::function<Trial(const StaticSolver::Parameters &)> &problem,
    const Check                                                  &check,
    StaticSolver::Parameters                                      p,
    std::ofstream                                                &csv)
  {
    p.min_step_fraction = 1;
    for (const std::string line_search :
         {"full step", "backtrack", "polynomial"})
      {
        p.newton.line_search = line_search;
        Trial        failure, success;
        unsigned int steps = 1;
        for (; steps <= 256; steps *= 2)
          {
            p.n_steps         = steps;
            const Trial trial = checked(problem(p), check);
            if (trial.converged)
              {
                success = trial;
                break;
              }
            failure = trial;
          }
        const bool         found = steps <= 256;
        std::ostringstream line;
        line << "  " << name << ", " << line_search << ": ";
        if (found)
          line << "converges in " << steps << " step(s) (load step "
               << 1.0 / steps << ", " << success.iterations
               << " Newton iterations)";
        else
          line << "no convergence in up to 256 steps";
        if (steps > 1)
          line << "; in " << (found ? steps / 2 : 256)
               << " steps: " << failure.message << "; state "
               << (failure.finite ? "finite" : "NOT FINITE");
        std::cout << line.str() << std::endl;
        csv << "newton," << name << ',' << line_search << ','
            << (found ? 1.0 / steps : 0) << ',' << (steps > 1 ? 2.0 / steps : 0)
            << ",,," << success.iterations << ",\"" << failure.message << "\","
            << failure.finite << '\n';
      }
  }

  /// The elastica's success is not monotone in the step count: every
  /// n_steps from 1 to 64 with full Newton steps and step cutting disabled,
  /// and the load P = 3 k / n of the first step past P_cr = pi^2/4.
  void
  elastica_step_scan(StaticSolver::Parameters p)
  {
    p.min_step_fraction = 1;
    std::ostringstream buckled_in, straight_in;
    for (unsigned int steps = 1; steps <= 64; ++steps)
      {
        p.n_steps = steps;
        const Trial trial =
          checked(newton_trial(*newton_rod(40, elastica_force()), p), buckled);
        const double increment = elastica_load / steps;
        const double first_past =
          increment * (std::floor(M_PI * M_PI / 4 / increment) + 1);
        (trial.converged ? buckled_in : straight_in)
          << ' ' << steps << " (" << std::setprecision(3) << first_past << ")";
      }
    std::cout << "  elastica N = 40, full step, n_steps (first load past "
                 "P_cr) reaching the buckled state:"
              << buckled_in.str()
              << "\n  not reaching it (straight, unstable, or failed):"
              << straight_in.str() << std::endl;
  }

  void
  stability_study()
  {
    std::cout << "\nstability: dynamic relaxation, time step limit with "
                 "cuts disabled\n";
    std::ofstream csv("dr_vs_newton_stability.csv");
    csv << "method,problem,setting,stable,failing,stable_relative,"
           "failing_relative,iterations,message,state_finite\n";
    dr_stability("cantilever N = 20",
                 dr_rod_problem(cantilever_force(), 20),
                 accept_any,
                 cantilever_settings(),
                 csv);
    dr_stability("elastica N = 20",
                 dr_rod_problem(elastica_force(), 20),
                 buckled,
                 elastica_settings(),
                 csv);
    dr_stability(
      "P1 N = 50",
      [](const DynamicRelaxation::Parameters &p) {
        return dr_trial(*bench::p1::dr_model(50), p);
      },
      accept_any,
      Settings{},
      csv);
    const Scene shell = gridshell_scene(4, Method::dynamic_relaxation);
    Settings    gs;
    gs.relaxation = shell.relaxation;
    dr_stability(
      "gridshell 4 segments",
      [&](const DynamicRelaxation::Parameters &p) {
        return dr_trial(*shell.build_dr_model(), p);
      },
      accept_any,
      gs,
      csv);

    std::cout << "\nstability: Newton, largest load step with step cutting "
                 "disabled\n";
    newton_stability(
      "elastica N = 40",
      [](const StaticSolver::Parameters &p) {
        return newton_trial(*newton_rod(40, elastica_force()), p);
      },
      buckled,
      elastica_settings().newton,
      csv);
    elastica_step_scan(elastica_settings().newton);
    newton_stability(
      "P1 N = 100",
      [](const StaticSolver::Parameters &p) {
        return newton_trial(*bench::p1::rod_model(100), p);
      },
      accept_any,
      StaticSolver::Parameters{},
      csv);
    std::cout << "  wrote dr_vs_newton_stability.csv" << std::endl;
  }

  /// The benchmark proper, run once the command line is read and MPI is
  /// up.
  void
  benchmark(const Options &options)
  {
    if (options.studies.count("cantilever"))
      cantilever_study(options);
    if (options.studies.count("elastica"))
      elastica_study(options);
    if (options.studies.count("gridshell"))
      gridshell_study(options);
    if (options.studies.count("stability"))
      stability_study();
  }
} // namespace

int
main(int argc, char **argv)
{
  return bench::run_benchmark("dr_vs_newton", argc, argv, benchmark);
}
