#pragma once
// How a caller steers a render of the pipeline (render_job.h): progress, cancelling and
// where warnings go.
#include <atomic>
#include <functional>
#include <string>

namespace glint {

class Cluster;
class Progress;

struct RenderControl {
    /// No progress line on stderr.
    bool quiet = false;
    /// While `*cancel` is non-zero the render stops and throws Interrupted(*cancel): a flag
    /// set by a signal handler, hence a lock-free atomic; null never cancels.
    const std::atomic<int>* cancel = nullptr;
    /// When set, the render advances this instead of a progress line of its own (a job of
    /// several renders or MPI ranks shows one line).
    Progress* progress = nullptr;
    /// The MPI job whose ranks the integrator shares its work with (Integrator::share_work);
    /// null renders as one process.
    Cluster* cluster = nullptr;
    /// Receives each warning (an unused key, a scene's note) before the render starts;
    /// null prints them to stderr as "warning: ...".
    std::function<void(const std::string&)> warn;
};

/// Throws Interrupted when the control's cancel flag is set.
void throw_if_cancelled(const RenderControl& control);

/// Passes `message` to control.warn, or prints it to stderr.
void warn(const RenderControl& control, const std::string& message);

}  // namespace glint
