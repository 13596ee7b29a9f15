#pragma once
// SIGINT/SIGTERM ask a long command (run, sweep, a sweep's point) to stop at its next tick or
// point: the handler stores the signal in g_stop_signal, lock-free and so async-signal-safe, and
// restores the default so that a second Ctrl-C ends the process at once. A handler can only
// reach a static object: this is the one.

#include <atomic>
#include <csignal>

namespace mechsim::apps {

inline std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" inline void mechsim_request_stop(int signal) {
  g_stop_signal.store(signal, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);
}

// While alive: SIGINT and SIGTERM set g_stop_signal (cleared on construction).
struct StopOnSignals {
  StopOnSignals() {
    g_stop_signal.store(0);
    std::signal(SIGINT, mechsim_request_stop);
    std::signal(SIGTERM, mechsim_request_stop);
  }
  ~StopOnSignals() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
};

}  // namespace mechsim::apps
