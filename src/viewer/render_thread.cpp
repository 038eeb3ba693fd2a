#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <viewer/render_thread.h>

#include <tbb/task_arena.h>

namespace glint::viewer {

RenderThread::RenderThread(ProgressiveSession session, int full_pass_budget)
    : m_session(std::move(session)), m_budget(full_pass_budget), m_thread([this] { run(); }) {}

RenderThread::~RenderThread() {
    {
        const std::lock_guard lock(m_mutex);
        m_stop = true;
        cancel_locked();
    }
    m_wake.notify_all();
    m_thread.join();
}

void RenderThread::cancel_locked() {
    m_cancel.store(1);
}

void RenderThread::request_camera(const Params& camera) {
    const std::lock_guard lock(m_mutex);
    m_camera = camera;
    cancel_locked();
    m_wake.notify_all();
}

void RenderThread::request_lights(const LightEdits& lights) {
    const std::lock_guard lock(m_mutex);
    m_lights = lights;
    cancel_locked();
    m_wake.notify_all();
}

void RenderThread::request_integrator(const std::string& name) {
    const std::lock_guard lock(m_mutex);
    m_integrator = name;
    cancel_locked();
    m_wake.notify_all();
}

void RenderThread::allow_passes(int count) {
    const std::lock_guard lock(m_mutex);
    if (m_budget >= 0) m_budget += count;
    m_wake.notify_all();
}

void RenderThread::set_denoise(bool on) {
    const std::lock_guard lock(m_mutex);
    m_denoise = on;
    m_republish = true;
    m_wake.notify_all();
}

void RenderThread::set_temporal(bool on) {
    const std::lock_guard lock(m_mutex);
    m_temporal = on;
    cancel_locked();
    m_wake.notify_all();
}

void RenderThread::set_svgf(bool on) {
    const std::lock_guard lock(m_mutex);
    m_svgf = on;
    m_republish = true;
    m_wake.notify_all();
}

Image RenderThread::shown_image(bool svgf) const {
    return svgf ? m_session.svgf_image() : m_session.image();
}

namespace {

// Denoise after 4, 16, 64, ... passes (powers of 4) and at the target.
bool denoise_due(int passes, int target) {
    const bool power_of_four =
        passes >= 4 && (passes & (passes - 1)) == 0 && (passes & 0x55555555) != 0;
    return passes == target || power_of_four;
}

}  // namespace

bool RenderThread::publish_still() {
    bool denoise = false, svgf = false;
    {
        const std::lock_guard lock(m_mutex);
        denoise = m_denoise;
        svgf = m_svgf;
    }
    Image image;
    if (denoise && m_session.passes() > 0) {
        Progress progress("denoise", 1, true);
        progress.set_cancel_flag(&m_cancel);
        try {
            image = m_session.denoised_image(progress, tbb::this_task_arena::max_concurrency());
        } catch (const Interrupted&) {
            return false;
        } catch (const Error& e) {
            const std::lock_guard lock(m_mutex);
            m_frame.error = e.what();
            ++m_frame.version;
            return true;
        }
    } else {
        image = shown_image(svgf);
    }
    const std::lock_guard lock(m_mutex);
    m_frame.image = std::move(image);
    m_frame.denoised = denoise && m_session.passes() > 0;
    m_frame.svgf = svgf && !m_frame.denoised;
    m_frame.passes = m_session.passes();
    ++m_frame.version;
    return true;
}

bool RenderThread::latest(Frame& frame) const {
    const std::lock_guard lock(m_mutex);
    if (m_frame.version == frame.version) return false;
    frame = m_frame;
    return true;
}

uint64_t RenderThread::version() const {
    const std::lock_guard lock(m_mutex);
    return m_frame.version;
}

void RenderThread::run() {
    bool idle = false;  // the session reached its target, or the last change failed
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            auto changes = [&] { return m_camera || m_lights || m_integrator || m_temporal; };
            // Nothing to do until a change, more budget, or the end. A change may always
            // render its reduced pass: the budget counts full passes only.
            m_wake.wait(lock, [&] {
                return m_stop || changes() || m_republish || (!idle && m_budget != 0);
            });
            if (m_stop) return;
            try {
                if (m_integrator) m_session.set_integrator(*m_integrator);
                m_frame.error.clear();
            } catch (const Error& e) {
                m_frame.error = e.what();
            }
            if (m_temporal) m_session.set_temporal(*m_temporal);
            if (m_camera) m_session.set_camera(*m_camera);
            if (m_lights) m_session.set_lights(*m_lights);
            const bool changed = changes();
            if (changed) idle = false;
            m_camera.reset();
            m_lights.reset();
            m_integrator.reset();
            m_temporal.reset();
            m_cancel.store(0);
            // The denoise toggle changed: show the still image again, denoised or not
            // (nothing to show before the first pass; a change renders anew anyway).
            if (m_republish && !changed) {
                m_republish = false;
                if (m_session.passes() == 0) continue;
                lock.unlock();
                publish_still();
                continue;
            }
            m_republish = false;
        }
        Progress progress("view", 1, true);
        // The reduced pass is short and runs to its end: while the user drags, changes
        // arrive every frame, and cancelling it too would leave the window without a view.
        // So does the first full pass after a move in temporal mode, which shows the move.
        if (!m_session.next_pass_reduced() && !m_session.next_pass_shows_move())
            progress.set_cancel_flag(&m_cancel);
        PassKind kind = PassKind::none;
        try {
            kind = m_session.render_next(progress);
        } catch (const Interrupted&) {
            continue;  // a change is waiting
        } catch (const Error& e) {
            const std::lock_guard lock(m_mutex);
            m_frame.error = e.what();
            ++m_frame.version;
            idle = true;
            continue;
        }
        if (kind == PassKind::none) {
            idle = true;
            continue;
        }
        bool svgf = false;
        {
            const std::lock_guard lock(m_mutex);
            svgf = m_svgf;
        }
        Image image = shown_image(svgf);
        bool denoise_now = false;
        {
            const std::lock_guard lock(m_mutex);
            m_frame.svgf = svgf;
            m_frame.temporal = m_session.has_history();
            if (kind == PassKind::full && m_budget > 0) --m_budget;
            m_frame.image = std::move(image);
            m_frame.passes = m_session.passes();
            m_frame.reduced = kind == PassKind::reduced;
            m_frame.pass_seconds = m_session.last_stats().seconds;
            m_frame.pass_samples = m_session.last_stats().samples;
            m_frame.integrator = m_session.integrator();
            m_frame.denoised = false;
            ++m_frame.version;
            denoise_now = kind == PassKind::full && m_denoise &&
                          denoise_due(m_session.passes(), m_session.target());
        }
        if (denoise_now) publish_still();
    }
}

}  // namespace glint::viewer
