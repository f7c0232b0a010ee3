#ifndef RODNET_APP_SCENE_RUNNER_H
#define RODNET_APP_SCENE_RUNNER_H

#include <io/scene.h>

#include <cmath>
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
    /// The unit of each probe ("m", "rad", "-"), in the order of the names.
    std::vector<std::string> probe_units;
    /// What the first entry of every row is: "load_factor" for load
    /// stepping, "time" for time stepping.
    std::string abscissa = "load_factor";
    /// Per recorded step (step 0, the unloaded or initial state, and every
    /// converged step): the abscissa, then the probe values.
    std::vector<std::vector<double>> rows;
    /// The load factor of the last recorded step (NaN if none).
    double final_load_factor = std::nan("");
    /// Whether the last recorded step is a stable equilibrium: 1, 0, or
    /// NaN where it was not checked (dynamic relaxation and dynamic time
    /// stepping, step 0).
    double final_stable = std::nan("");
    /// The model's length scale (Model::length_scale(), m).
    double length_scale = 0;
    /// Converged steps whose equilibrium is unstable (probes.csv column
    /// "stable" 0; Newton and quasi-static runs).
    unsigned int unstable_steps = 0;
    /// Converged steps with a strain past the rod model's range (column
    /// "in_range" 0).
    unsigned int out_of_range_steps = 0;
    /// Empty if the run completed; the solver's message otherwise.
    std::string failure;
    /// The signal that stopped the run between two steps (see
    /// stop_cleanly_on_signals()), 0 if none did.
    int stopped_by = 0;
    /// The files written into the output directory: "probes.csv", and
    /// "probes.png", "solution.pvd" (with its .vtu files) and
    /// "picture.png" if written.
    std::vector<std::string> outputs;
  };

  /**
   * Runs a scene: prints its size to @p log, builds the model, steps the
   * load (or the time), and after every step writes the VTU/PVD files and
   * a row of probes.csv into @p output_directory (created if needed), and
   * finally probes.png (plot_probes()) and picture.png, the last state
   * (io/network_picture.h; picture-NNNNN.png of steps on request). Step 0 is
   * the unloaded state of load stepping and continuation and the initial state
   * of time stepping (before its preload, if any); time stepping also records
   * every preload step (at times up to the start time). The rows of rod models
   * end with the solver's checks of the state: "stable" (Newton and
   * quasi-static runs) and "in_range" (1 or 0; the warnings on @p log say
   * where), after the continuation's "arclength", "branch" and
   * "negative_eigenvalues".
   * Rotation probes are continuous over the steps (unwrap_rotations()). A
   * solver failure ends the run with RunSummary::failure set, a stop
   * signal with RunSummary::stopped_by set; everything written before
   * stays, complete. Bad input throws std::invalid_argument before any
   * step (also VTU files that would not fit on the disk), except a "Load
   * factor" expression that is not finite at some time, which throws when
   * the run gets there.
   */
  RunSummary
  run_scene(const Scene       &scene,
            const std::string &output_directory,
            std::ostream      *log);
} // namespace rodnet

#endif
