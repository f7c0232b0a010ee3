#include <app/interrupt.h>

#include <csignal>
#include <string>

namespace rodnet
{
  namespace
  {
    /// Written by the signal handler, read between steps: sig_atomic_t is
    /// the only type a handler may write portably.
    volatile std::sig_atomic_t requested_by = 0;

    extern "C" void
    record_signal(const int signal)
    {
      requested_by = signal;
    }
  } // namespace

  void
  stop_cleanly_on_signals()
  {
    struct sigaction action = {};
    action.sa_handler       = record_signal;
    sigemptyset(&action.sa_mask);
    // One-shot: the second signal finds the default action again.
    // SA_RESTART: a signal that arrives during a system call (writing an
    // output file, waiting for a child) must not fail that call with EINTR
    // and turn a clean stop into an error.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
  }

  int
  stop_signal()
  {
    return requested_by;
  }

  StopRequested::StopRequested(const int signal_)
      : std::runtime_error("stopped by signal " + std::to_string(signal_))
      , signal(signal_)
  {
  }

  void
  throw_if_stop_requested()
  {
    if (requested_by != 0)
      throw StopRequested(requested_by);
  }
} // namespace rodnet
