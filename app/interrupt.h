#ifndef RODNET_APP_INTERRUPT_H
#define RODNET_APP_INTERRUPT_H

#include <stdexcept>

namespace rodnet
{
  /**
   * Makes SIGINT and SIGTERM request a clean stop instead of killing the
   * process: the handler only records the signal, and run_scene() looks at
   * it between steps, ends the run there with every output of the steps
   * so far complete, and reports it (RunSummary::interrupted_by). A second
   * signal of the same kind kills as usual, for a run stuck inside a step.
   */
  void
  stop_cleanly_on_signals();

  /// The signal that requested a stop, 0 if none did.
  int
  stop_signal();

  /// Thrown between steps once a stop was requested.
  class StopRequested : public std::runtime_error
  {
  public:
    explicit StopRequested(int signal);

    /// The signal that requested the stop.
    const int signal;
  };

  /// Throws StopRequested if a signal requested a stop.
  void
  throw_if_stop_requested();
} // namespace rodnet

#endif
