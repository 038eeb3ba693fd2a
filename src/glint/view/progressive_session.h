#pragma once
// The viewer's render loop without a window: it owns the scene, the integrator and the film,
// counts the passes accumulated since the last change, and restarts when the camera, a
// light or the integrator changes. The first pass after a change renders at reduced
// resolution, so that the window shows the new view at once; then full passes accumulate
// until the target (settings.spp), after which the image equals `glint render --spp N`
// bit for bit (tile integrators, same seed, no adaptive sampling).
// In temporal mode (SessionOptions::temporal) a camera move does not throw the image away:
// what was shown is reprojected into the new view (reprojection.h) and blended with the passes
// since (temporal_history.h), which, once the camera stops, fade it out, leaving the film's
// image exactly. svgf_image() filters what is shown with the real-time denoiser.
#include <glint/core/params.h>
#include <glint/denoise/svgf.h>
#include <glint/film/film.h>
#include <glint/film/image.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/progressive.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene_desc.h>
#include <glint/view/geometry_buffer.h>
#include <glint/view/light_edits.h>
#include <glint/view/temporal_history.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {

class Progress;

struct SessionOptions {
    /// The first pass after a change renders an image 1/reduced_scale the size on each
    /// side (rounded up), shown enlarged; 1 renders full passes only.
    int reduced_scale = 4;
    /// Whether the film records the first-hit features (AOVs), which denoised_image() needs.
    bool aovs = false;
    /// Whether to keep what temporal mode and svgf_image() need: the geometry buffer of the
    /// view and the luminance moments of each pass (a little work after every pass).
    bool realtime = false;
    /// Temporal mode at the start (needs realtime); set_temporal() changes it.
    bool temporal = false;
    /// The longest history in frames (TemporalHistory): after a stop, the image is the
    /// film's again after at most this many passes plus one.
    int temporal_max_length = 32;
    /// The real-time denoiser's settings (svgf_image()).
    SvgfSettings svgf;
};

/// What render_next() did.
enum class PassKind {
    none,     ///< nothing: the target number of passes is reached
    reduced,  ///< the reduced-resolution pass after a change
    full,     ///< one more full-resolution pass into the film
};

class ProgressiveSession {
public:
    /// Builds the scene and the integrator settings.integrator; settings.spp is the number
    /// of passes after which accumulation stops. Throws glint::Error for a bad scene or an
    /// integrator that cannot render pass by pass.
    ProgressiveSession(SceneDesc desc, RenderSettings settings, SessionOptions options = {});

    /// Changes take effect at the next render_next(), which restarts accumulation.
    /// `camera` is a glint.camera{...} table (CameraController::params()); errors are
    /// thrown by render_next().
    void set_camera(Params camera);
    void set_lights(const LightEdits& lights);
    /// Throws glint::Error when `name` is unknown or not progressive.
    void set_integrator(const std::string& name);
    /// Turns temporal mode on or off (the history is dropped either way); throws
    /// glint::Error without SessionOptions::realtime.
    void set_temporal(bool on);
    bool temporal() const { return m_temporal; }

    /// Applies pending changes, then renders one pass. Passes may be cancelled through
    /// `progress` (Progress::set_cancel_flag): glint::Interrupted propagates, and the next
    /// call starts again from a cleared film.
    PassKind render_next(Progress& progress);

    /// Whether the next render_next() renders the reduced pass (a change is pending, or
    /// none has been shown since the last one).
    bool next_pass_reduced() const {
        if (m_camera_changed && m_temporal && !m_rebuild && !m_restart && m_geometry) return false;
        return m_options.reduced_scale > 1 &&
               (m_reduced_due || m_camera_changed || m_rebuild || m_restart);
    }
    /// Whether the next render_next() renders the first full pass after a move in temporal
    /// mode, which shows the move as the reduced pass does (a viewer lets it finish).
    bool next_pass_shows_move() const {
        return m_temporal && (m_camera_changed || (m_passes == 0 && has_history()));
    }
    /// Full-resolution passes in the film since the last change (its samples per pixel).
    int passes() const { return m_passes; }
    /// The number of passes after which accumulation stops.
    int target() const { return m_settings.spp; }
    /// Whether image() is the reduced pass (no full pass finished since the change).
    bool showing_reduced() const { return m_passes == 0 && m_reduced.has_value(); }
    /// The image to show, full size, linear radiance (R, G, B): the film's, or the reduced
    /// pass enlarged (each of its pixels covers reduced_scale x reduced_scale pixels), or in
    /// temporal mode the film blended with the reprojected history.
    Image image() const;
    /// image() filtered by the real-time denoiser (denoise/svgf.h), guided by the view's
    /// geometry buffer; image() itself while the reduced pass is shown. Throws glint::Error
    /// without SessionOptions::realtime.
    Image svgf_image() const;
    /// Whether pixels show reprojected history (temporal mode after a move).
    bool has_history() const { return m_temporal && !m_history.empty(); }
    /// The film's own image (what `glint render` would write after passes() samples).
    Image film_image() const { return m_film.resolve(); }
    /// The film's image denoised by the network (denoise/network_denoiser.h, the render
    /// settings' denoise_quality) on `threads` threads, R, G, B; for a camera that has
    /// stopped, as it takes seconds. Throws glint::Error without AOVs (SessionOptions::aovs)
    /// or without the weights, and glint::Interrupted when `progress` is cancelled.
    Image denoised_image(Progress& progress, int threads) const;
    /// What the last pass reported (samples, rays, seconds).
    const RenderStats& last_stats() const { return m_last; }

    const RenderSettings& settings() const { return m_settings; }
    const Scene& scene() const { return *m_scene; }
    const std::string& integrator() const { return m_settings.integrator; }

    /// Names of the integrators that render pass by pass with these settings.
    static std::vector<std::string> progressive_integrators(const RenderSettings& settings);

private:
    std::unique_ptr<Camera> make_camera_for(Vec2i resolution) const;
    void restart();
    // The camera moved to `camera` (full resolution): in temporal mode, what was shown
    // becomes the history of the new view.
    void move_history(std::unique_ptr<Camera> camera);
    // After a full pass: the film's mean and the pass's moments (realtime only).
    void record_pass();
    void ensure_geometry();

    SceneDesc m_desc;  // as loaded; light edits are applied to a copy
    RenderSettings m_settings;
    SessionOptions m_options;
    Params m_camera;
    std::optional<LightEdits> m_lights;
    std::unique_ptr<Scene> m_scene;
    std::unique_ptr<Integrator> m_integrator;
    ProgressiveIntegrator* m_progressive = nullptr;  // m_integrator, seen as progressive
    Film m_film;
    std::optional<Image> m_reduced;
    int m_passes = 0;
    bool m_reduced_due = true;
    // What changed since the last pass.
    bool m_camera_changed = false;
    bool m_rebuild = false;
    bool m_restart = false;
    RenderStats m_last;
    // Realtime state: the camera and geometry buffer of the film's view, the history of
    // earlier views, the film's mean after the last pass and the sum of the passes'
    // luminance moments (demodulated, svgf_moments).
    bool m_temporal = false;
    std::unique_ptr<Camera> m_view_camera;
    std::optional<GeometryBuffer> m_geometry;
    TemporalHistory m_history;
    std::vector<Rgb> m_mean;
    std::vector<Vec2> m_moment_sums;
};

}  // namespace glint
