#pragma once
// The viewer's worker: runs a ProgressiveSession on a thread of its own (the passes use TBB
// inside), so that the window never waits for a pass. The window asks for changes, which
// cancel the pass in flight, and takes the latest image when it draws.
#include <glint/core/params.h>
#include <glint/film/image.h>
#include <glint/view/light_edits.h>
#include <glint/view/progressive_session.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace glint::viewer {

/// What the window shows: the session's image after a pass, and what it counts.
struct Frame {
    Image image;
    int passes = 0;         ///< full passes in the image (samples per pixel)
    bool reduced = false;   ///< the reduced-resolution pass after a change
    bool denoised = false;  ///< denoised by the network (the camera had stopped)
    bool svgf = false;      ///< filtered by the real-time denoiser
    bool temporal = false;  ///< blended with the reprojected history of earlier views
    uint64_t version = 0;   ///< grows with every frame published
    double pass_seconds = 0.0;
    uint64_t pass_samples = 0;
    std::string integrator;
    std::string error;  ///< the last error of a change (bad integrator, scene that fails)
};

class RenderThread {
public:
    /// Starts rendering `session`, which the thread owns from now on. `full_pass_budget`:
    /// how many full passes it may render before it waits for allow_passes() (-1: no limit,
    /// it stops at the session's target).
    RenderThread(ProgressiveSession session, int full_pass_budget = -1);
    /// Cancels the pass in flight and joins the thread.
    ~RenderThread();
    RenderThread(const RenderThread&) = delete;
    RenderThread& operator=(const RenderThread&) = delete;

    /// Changes, applied before the next pass; each cancels the pass in flight.
    void request_camera(const Params& camera);
    void request_lights(const LightEdits& lights);
    void request_integrator(const std::string& name);
    /// Lets the thread render `count` more full passes (with a budget).
    void allow_passes(int count);
    /// Turns on or off denoising by the network while the camera stands still: after 4, 16,
    /// 64, ... passes and at the target (not every frame, as each takes seconds). Needs a
    /// session made with SessionOptions::aovs. The current image is republished at once.
    void set_denoise(bool on);

    /// Turns temporal mode (reprojected history) on or off; needs a session made with
    /// SessionOptions::realtime. Takes effect before the next pass.
    void set_temporal(bool on);
    /// Turns the real-time denoiser (SVGF) on or off for every frame shown; needs a session
    /// made with SessionOptions::realtime. The current image is republished at once.
    void set_svgf(bool on);

    /// Copies the latest frame into `frame` when it is newer than frame.version.
    bool latest(Frame& frame) const;
    /// The version of the latest frame (see Frame::version).
    uint64_t version() const;

private:
    void run();
    void cancel_locked();
    // Publishes the session's image, denoised when denoising is on; false when a change
    // cancelled the denoiser.
    bool publish_still();
    // The session's image as shown: filtered by SVGF when it is on.
    Image shown_image(bool svgf) const;

    ProgressiveSession m_session;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::atomic<int> m_cancel{0};  // Progress throws Interrupted while it is set
    bool m_stop = false;
    int m_budget;
    std::optional<Params> m_camera;
    std::optional<LightEdits> m_lights;
    std::optional<std::string> m_integrator;
    bool m_denoise = false;
    std::optional<bool> m_temporal;  // a requested change of temporal mode
    bool m_svgf = false;
    bool m_republish = false;  // set_denoise() asks for the still image again
    Frame m_frame;
    std::thread m_thread;  // last: starts once everything above exists
};

}  // namespace glint::viewer
