#ifndef RODNET_IO_SCENE_RUNNER_H
#define RODNET_IO_SCENE_RUNNER_H

#include <io/scene.h>

#include <ostream>
#include <string>
#include <vector>

namespace rodnet
{
  /// What a scene run produced.
  struct RunSummary
  {
    unsigned int converged_steps = 0;
    /// Load factor where the lowest eigenvalue crossed zero (NaN if none).
    double                   critical_load_factor = std::nan("");
    std::vector<std::string> probe_names;
    /// Per converged step: load factor, then the probe values.
    std::vector<std::vector<double>> rows;
    /// Empty if the run completed; the solver's message otherwise.
    std::string failure;
  };

  /**
   * Runs a scene: builds the model, steps the load, and after every
   * converged step writes the VTU/PVD files and a row of probes.csv into
   * @p output_directory (created if needed), and finally probes.png. A
   * solver failure ends the run with RunSummary::failure set; everything
   * written before stays. Bad input throws before any step.
   */
  RunSummary
  run_scene(const Scene       &scene,
            const std::string &output_directory,
            std::ostream      *log);
} // namespace rodnet

#endif
