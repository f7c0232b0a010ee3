#ifndef RODNET_IO_RUN_LIMITS_H
#define RODNET_IO_RUN_LIMITS_H

namespace rodnet
{
  /**
   * How long a scene may run and how much it may write: beyond these a run
   * cannot end in reasonable time or buries its outputs (a load step takes
   * a millisecond at the least, a time step about as much; ParaView and a
   * PVD record rewritten at every step slow down with the file count).
   * Scene refuses a scene that would exceed them, naming the entry to
   * change; the runner also stops writing VTU files at max_vtu_files
   * should cut steps make more (with a warning).
   */
  namespace run_limits
  {
    /// Loads/Steps.
    constexpr unsigned int max_load_steps = 100000;
    /// Time steps from the start to the end time, with the preload steps.
    constexpr double max_time_steps = 1e6;
    /// VTU files of one run.
    constexpr unsigned int max_vtu_files = 10000;
    /// picture-NNNNN.png of one run (NetworkPictures keeps fewer frames,
    /// further apart, rather than more).
    constexpr unsigned int max_picture_frames = 100;
  } // namespace run_limits
} // namespace rodnet

#endif
