#pragma once
// SIGINT and SIGTERM for the `glint` command: recorded by a handler, polled by the work.
#include <atomic>
#include <csignal>

namespace glint::cli {

/// The number of the first SIGINT or SIGTERM received, 0 before. The one global of the
/// program: a signal handler can reach nothing else. The handler only stores to it (a
/// lock-free atomic store is async-signal-safe); the render polls it once per tile through
/// Progress, and the output code before each file and before the renames.
extern std::atomic<int> g_signal;

/// The signals that stop a run cleanly (the work stops, temporaries are removed, exit code
/// 128 + the signal).
inline constexpr int kStoppingSignals[] = {SIGINT, SIGTERM, SIGHUP};

/// Records kStoppingSignals in g_signal, ignores SIGXFSZ (a write past the file-size limit
/// then fails and is cleaned up), and points the library's cancellation flag at g_signal.
void install_signal_handlers();

/// "SIGINT", "SIGTERM", "SIGHUP", for messages.
const char* signal_name(int signal);

/// Throws Interrupted when a signal has arrived.
void throw_if_interrupted();

}  // namespace glint::cli
