#include <io/probe_plot.h>
#include <io/scene_runner.h>
#include <io/vtu_output.h>

#include <filesystem>

namespace rodnet
{
  namespace
  {
    /// What both solution methods do with a converged step: a row of
    /// probes.csv, a row of the summary, and the VTU files.
    class StepRecorder
    {
    public:
      StepRecorder(const Scene              &scene,
                   const std::string        &output_directory,
                   const std::vector<Probe> &probes,
                   const RodModel           *vtu_model,
                   RunSummary               &summary)
          : scene(scene)
          , csv(csv_path(output_directory))
          , table(csv, probes)
          , summary(summary)
      {
        if (scene.write_vtu && vtu_model != nullptr)
          vtu = std::make_unique<VtuOutput>(*vtu_model, output_directory);
        for (const Probe &p : probes)
          summary.probe_names.push_back(p.name);
      }

      /// Records step @p step; @p u is the state for the VTU files in the
      /// layout of the RodModel given to the constructor.
      void
      record(const unsigned int         step,
             const double               load_factor,
             const std::vector<double> &values,
             const VectorType          *u)
      {
        table.add_row(step, load_factor, values);
        std::vector<double> row{load_factor};
        row.insert(row.end(), values.begin(), values.end());
        summary.rows.push_back(row);
        summary.converged_steps = step;
        if (vtu && u != nullptr && step % scene.vtu_interval == 0)
          vtu->write(step, load_factor, *u);
      }

      void
      finish(const std::string &output_directory) const
      {
        if (scene.plot && !summary.probe_names.empty() && !summary.rows.empty())
          plot_probes(csv, output_directory + "/probes.png", "rodnet probes");
      }

    private:
      /// probes.csv in @p directory, created if needed.
      static std::string
      csv_path(const std::string &directory)
      {
        std::filesystem::create_directories(directory);
        return directory + "/probes.csv";
      }

      const Scene               &scene;
      const std::string          csv;
      ProbeTable                 table;
      RunSummary                &summary;
      std::unique_ptr<VtuOutput> vtu;
    };

    RunSummary
    run_newton(const Scene       &scene,
               const std::string &output_directory,
               std::ostream      *log)
    {
      std::unique_ptr<RodModel> model  = scene.build_model();
      const std::vector<Probe>  probes = scene.probes(*model);

      StaticSolver::Parameters parameters = scene.solver;
      for (const Probe &p : probes)
        if (p.kind == Probe::Kind::eigenvalue)
          parameters.track_lowest_eigenvalue = true;

      RunSummary   summary;
      StepRecorder recorder(scene,
                            output_directory,
                            probes,
                            model.get(),
                            summary);
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
                       recorder.record(info.step,
                                       info.load_factor,
                                       evaluate_probes(probes,
                                                       *model,
                                                       solution,
                                                       info.load_factor,
                                                       info.lowest_eigenvalue),
                                       &solution);
                     });
        }
      catch (const SolverFailure &e)
        {
          summary.failure = e.what();
        }
      summary.critical_load_factor = solver.critical_load_factor();
      recorder.finish(output_directory);
      return summary;
    }

    RunSummary
    run_dynamic_relaxation(const Scene       &scene,
                           const std::string &output_directory,
                           std::ostream      *log)
    {
      const DrScene            dr     = scene.build_dr_model();
      const DrModel           &model  = *dr.model;
      const std::vector<Probe> probes = scene.probes(model);
      // The VTU files are those of the rod model of the same scene: its
      // vertices take the element's node positions (twists stay zero).
      std::unique_ptr<RodModel> rods;
      VectorType                rod_state;
      if (scene.write_vtu)
        {
          rods      = scene.build_model();
          rod_state = rods->create_vector();
        }

      RunSummary   summary;
      StepRecorder recorder(scene,
                            output_directory,
                            probes,
                            rods.get(),
                            summary);
      if (log != nullptr)
        *log << "rodnet (dynamic relaxation): " << model.network().rods().size()
             << " rod(s), " << model.n_dofs() << " DoFs, " << model.n_elements()
             << " elements" << std::endl;

      DrVector          u = model.create_vector();
      DynamicRelaxation solver(model, scene.relaxation, log);
      try
        {
          solver.run(u,
                     [&](const DynamicRelaxation::StepInfo &info,
                         const DrVector                    &solution) {
                       if (rods)
                         {
                           const RodNetwork &net = model.network();
                           for (unsigned int v = 0; v < net.n_vertices(); ++v)
                             {
                               const Vector3 d =
                                 model.position(solution, v) - net.vertex(v);
                               for (unsigned int c = 0; c < 3; ++c)
                                 rod_state[rods->layout().vertex_dof(v, c)] =
                                   d[c];
                             }
                           rod_state.compress(dealii::VectorOperation::insert);
                         }
                       recorder.record(info.step,
                                       info.load_factor,
                                       evaluate_probes(probes,
                                                       model,
                                                       solution,
                                                       info.load_factor),
                                       rods ? &rod_state : nullptr);
                     });
        }
      catch (const SolverFailure &e)
        {
          summary.failure = e.what();
        }
      recorder.finish(output_directory);
      return summary;
    }
  } // namespace

  RunSummary
  run_scene(const Scene       &scene,
            const std::string &output_directory,
            std::ostream      *log)
  {
    return scene.method == SolutionMethod::newton ?
             run_newton(scene, output_directory, log) :
             run_dynamic_relaxation(scene, output_directory, log);
  }
} // namespace rodnet
