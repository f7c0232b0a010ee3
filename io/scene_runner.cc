#include <io/probe_plot.h>
#include <io/scene_runner.h>
#include <io/vtu_output.h>

#include <filesystem>

namespace rodnet
{
  RunSummary
  run_scene(const Scene       &scene,
            const std::string &output_directory,
            std::ostream      *log)
  {
    std::unique_ptr<RodModel> model  = scene.build_model();
    const std::vector<Probe>  probes = scene.probes(*model);

    StaticSolver::Parameters parameters = scene.solver;
    for (const Probe &p : probes)
      if (p.kind == Probe::Kind::eigenvalue)
        parameters.track_lowest_eigenvalue = true;

    std::filesystem::create_directories(output_directory);
    const std::string          csv = output_directory + "/probes.csv";
    ProbeTable                 table(csv, probes);
    std::unique_ptr<VtuOutput> vtu;
    if (scene.write_vtu)
      vtu = std::make_unique<VtuOutput>(*model, output_directory);

    RunSummary summary;
    for (const Probe &p : probes)
      summary.probe_names.push_back(p.name);

    if (log != nullptr)
      *log << "rodnet: " << model->network().rods().size() << " rod(s), "
           << model->layout().n_dofs() << " DoFs, "
           << model->layout().hinges().size() << " hinges" << std::endl;

    VectorType   u = model->create_vector();
    StaticSolver solver(*model, parameters, log);
    try
      {
        solver.run(u,
                   [&](const StaticSolver::StepInfo &info,
                       const VectorType             &solution) {
                     const std::vector<double> values =
                       evaluate_probes(probes,
                                       *model,
                                       solution,
                                       info.load_factor,
                                       info.lowest_eigenvalue);
                     table.add_row(info.step, info.load_factor, values);
                     std::vector<double> row{info.load_factor};
                     row.insert(row.end(), values.begin(), values.end());
                     summary.rows.push_back(row);
                     summary.converged_steps = info.step;
                     if (vtu && info.step % scene.vtu_interval == 0)
                       vtu->write(info.step, info.load_factor, solution);
                   });
      }
    catch (const SolverFailure &e)
      {
        summary.failure = e.what();
      }
    summary.critical_load_factor = solver.critical_load_factor();

    if (scene.plot && !probes.empty() && !summary.rows.empty())
      plot_probes(csv, output_directory + "/probes.png", "rodnet probes");
    return summary;
  }
} // namespace rodnet
