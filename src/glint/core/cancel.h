#pragma once
// Stopping long work from outside: the CLI's SIGINT/SIGTERM handler raises a flag, and every
// long phase (tile loops through Progress, photon emission, the radiosity solve, the MLT
// bootstrap, the denoiser) polls it with throw_if_cancelled() once per chunk of work, so a
// signal ends any of them within a chunk, and the exception removes every temporary on its
// way out.
#include <atomic>

namespace glint {

/// Points the process at the flag its signal handler writes (the signal's number, 0 while
/// none came); null (the default) never cancels. Set once, before any work starts.
void set_cancel_flag(const std::atomic<int>* flag);

/// The flag set_cancel_flag() gave, or null.
const std::atomic<int>* cancel_flag();

/// Throws glint::Interrupted(signal) when the flag is raised; one relaxed load otherwise.
void throw_if_cancelled();

}  // namespace glint
