#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/core/parallel.h>
#include <glint/core/progress.h>
#include <glint/denoise/film_denoiser.h>
#include <glint/denoise/svgf.h>
#include <glint/scene/build.h>
#include <glint/view/progressive_session.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace glint {
namespace {

std::pair<std::unique_ptr<Integrator>, ProgressiveIntegrator*> make_progressive(
    const RenderSettings& settings) {
    std::unique_ptr<Integrator> integrator = make_integrator(settings);
    auto* progressive = dynamic_cast<ProgressiveIntegrator*>(integrator.get());
    if (!progressive) {
        throw Error(fmt::format(
            "{}: integrator '{}' cannot render pass by pass in the viewer (these can: {})",
            settings.where_of("integrator"), settings.integrator,
            fmt::join(ProgressiveSession::progressive_integrators(settings), ", ")));
    }
    return {std::move(integrator), progressive};
}

}  // namespace

ProgressiveSession::ProgressiveSession(SceneDesc desc, RenderSettings settings,
                                       SessionOptions options)
    : m_desc(std::move(desc)),
      m_settings(std::move(settings)),
      m_options(options),
      m_camera(m_desc.camera ? *m_desc.camera : Params("camera", "default camera")),
      m_film(m_settings.width, m_settings.height, options.aovs),
      m_history(options.temporal_max_length) {
    if (m_options.reduced_scale < 1) throw Error("the reduced scale must be at least 1");
    std::tie(m_integrator, m_progressive) = make_progressive(m_settings);
    m_scene = build_scene(m_desc, m_settings);
    if (m_options.realtime) {
        m_view_camera = make_camera_for(Vec2i(m_settings.width, m_settings.height));
        const std::size_t pixels = static_cast<std::size_t>(m_settings.width) * m_settings.height;
        m_mean.assign(pixels, Rgb(0.0f));
        m_moment_sums.assign(pixels, Vec2(0.0f));
        set_temporal(m_options.temporal);
    } else if (m_options.temporal) {
        throw Error("temporal mode needs the session's realtime buffers");
    }
}

void ProgressiveSession::set_temporal(bool on) {
    if (!m_options.realtime) throw Error("temporal mode needs the session's realtime buffers");
    m_temporal = on;
    m_history.reset();
}

void ProgressiveSession::set_camera(Params camera) {
    m_camera = std::move(camera);
    m_camera_changed = true;
}

void ProgressiveSession::set_lights(const LightEdits& lights) {
    m_lights = lights;
    m_rebuild = true;
}

void ProgressiveSession::set_integrator(const std::string& name) {
    RenderSettings settings = m_settings;
    settings.integrator = name;
    auto [integrator, progressive] = make_progressive(settings);
    m_settings = std::move(settings);
    m_integrator = std::move(integrator);
    m_progressive = progressive;
    m_restart = true;
    m_history.reset();
}

std::unique_ptr<Camera> ProgressiveSession::make_camera_for(Vec2i resolution) const {
    std::unique_ptr<Camera> camera = make_camera(m_camera, resolution);
    camera->set_samples_per_pixel(m_settings.spp);  // as build_scene sets it
    return camera;
}

void ProgressiveSession::restart() {
    m_film.clear();
    m_passes = 0;
    m_reduced.reset();
    m_reduced_due = m_options.reduced_scale > 1;
    std::fill(m_mean.begin(), m_mean.end(), Rgb(0.0f));
    std::fill(m_moment_sums.begin(), m_moment_sums.end(), Vec2(0.0f));
}

void ProgressiveSession::ensure_geometry() {
    if (!m_options.realtime || m_geometry) return;
    m_geometry =
        trace_geometry_buffer(*m_scene, *m_view_camera, m_settings.width, m_settings.height);
}

void ProgressiveSession::move_history(std::unique_ptr<Camera> camera) {
    if (!m_options.realtime) return;
    if (!m_temporal || !m_geometry) {
        m_view_camera = std::move(camera);
        m_geometry.reset();
        return;
    }
    const std::size_t pixels = m_mean.size();
    std::vector<Rgb> shown(pixels);
    std::vector<Vec2> moments(pixels);
    std::vector<float> lengths(pixels);
    const float inverse = m_passes > 0 ? 1.0f / static_cast<float>(m_passes) : 0.0f;
    parallel_for_indices(pixels, [&](std::size_t i) {
        shown[i] = m_history.blend(i, m_mean[i], m_passes);
        moments[i] = m_history.blend_moments(i, m_moment_sums[i] * inverse, m_passes);
        lengths[i] = m_history.blended_length(i, m_passes);
    });
    GeometryBuffer geometry =
        trace_geometry_buffer(*m_scene, *camera, m_settings.width, m_settings.height);
    const std::vector<HistoryTaps> taps = reproject(geometry, *camera, *m_geometry, *m_view_camera);
    m_history.move(taps, shown, moments, lengths);
    m_geometry = std::move(geometry);
    m_view_camera = std::move(camera);
}

void ProgressiveSession::record_pass() {
    if (!m_options.realtime) return;
    ensure_geometry();
    const Image image = m_film.resolve();
    const float k = static_cast<float>(m_passes);
    parallel_for_indices(m_mean.size(), [&](std::size_t i) {
        // R, G, B come first, then the AOVs when the film has them.
        const float* rgb = &image.pixels[i * image.channels.size()];
        const Rgb mean(rgb[0], rgb[1], rgb[2]);
        // The pass's own value, from the means before and after it.
        const Rgb pass = mean * k - m_mean[i] * (k - 1.0f);
        m_moment_sums[i] += svgf_moments(pass, m_geometry->albedo[i]);
        m_mean[i] = mean;
    });
}

PassKind ProgressiveSession::render_next(Progress& progress) {
    if (m_rebuild) {
        SceneDesc desc = m_lights ? m_lights->apply(m_desc) : m_desc;
        desc.camera = m_camera;
        m_scene = build_scene(desc, m_settings);
        m_progressive->scene_changed(SceneChange::lights_or_objects);
        m_rebuild = m_camera_changed = false;
        m_history.reset();
        m_geometry.reset();
        if (m_options.realtime)
            m_view_camera = make_camera_for(Vec2i(m_settings.width, m_settings.height));
        restart();
    }
    if (m_camera_changed) {
        const Vec2i size(m_settings.width, m_settings.height);
        m_scene->set_camera(make_camera_for(size));
        m_progressive->scene_changed(SceneChange::camera);
        m_camera_changed = false;
        move_history(make_camera_for(size));
        restart();
        // The reprojected history fills the new view at once: no reduced pass.
        if (has_history()) m_reduced_due = false;
    }
    if (m_restart) {
        m_restart = false;
        restart();
    }
    try {
        if (m_reduced_due) {
            const int scale = m_options.reduced_scale;
            const Vec2i size((m_settings.width + scale - 1) / scale,
                             (m_settings.height + scale - 1) / scale);
            Film film(size.x, size.y, false);
            m_scene->set_camera(make_camera_for(size));
            try {
                m_last = m_progressive->render_pass(*m_scene, film, 0, progress);
            } catch (...) {
                m_scene->set_camera(make_camera_for(Vec2i(m_settings.width, m_settings.height)));
                throw;
            }
            m_scene->set_camera(make_camera_for(Vec2i(m_settings.width, m_settings.height)));
            m_reduced = film.resolve();
            m_reduced_due = false;
            return PassKind::reduced;
        }
        if (m_passes >= m_settings.spp) return PassKind::none;
        m_last = m_progressive->render_pass(*m_scene, m_film, m_passes, progress);
        ++m_passes;
        record_pass();
        return PassKind::full;
    } catch (...) {
        // A pass cut short leaves some pixels with one sample more than others.
        m_restart = true;
        throw;
    }
}

Image ProgressiveSession::image() const {
    if (has_history() && !showing_reduced()) {
        Image image = make_image(m_settings.width, m_settings.height, {"R", "G", "B"});
        parallel_for_indices(m_mean.size(), [&](std::size_t i) {
            const Rgb c = m_history.blend(i, m_mean[i], m_passes);
            for (int ch = 0; ch < 3; ++ch) image.pixels[3 * i + ch] = c[ch];
        });
        return image;
    }
    if (!showing_reduced()) return m_film.resolve();
    const int scale = m_options.reduced_scale;
    Image image = make_image(m_settings.width, m_settings.height, {"R", "G", "B"});
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = m_reduced->at(x / scale, y / scale, c);
        }
    }
    return image;
}

Image ProgressiveSession::svgf_image() const {
    if (!m_options.realtime)
        throw Error("the real-time denoiser needs the session's realtime buffers");
    Image image = this->image();
    if (showing_reduced() || !m_geometry || (m_passes == 0 && !has_history())) return image;
    const std::size_t pixels = m_mean.size();
    std::vector<Rgb> colour(pixels);
    std::vector<Vec2> moments(pixels);
    std::vector<float> lengths(pixels);
    const float inverse = m_passes > 0 ? 1.0f / static_cast<float>(m_passes) : 0.0f;
    const float cap = static_cast<float>(m_history.max_length());
    parallel_for_indices(pixels, [&](std::size_t i) {
        const float* rgb = &image.pixels[i * image.channels.size()];
        colour[i] = Rgb(rgb[0], rgb[1], rgb[2]);
        const Vec2 frame_moments = m_moment_sums[i] * inverse;
        Vec2 m =
            has_history() ? m_history.blend_moments(i, frame_moments, m_passes) : frame_moments;
        const float frames =
            has_history() ? m_history.blended_frames(i, m_passes) : static_cast<float>(m_passes);
        lengths[i] = std::min(frames, has_history() ? cap : frames);
        // The moments give one frame's variance, and SVGF's thresholds are set for colours
        // that average at most a history's worth of frames (the paper's moving average). A
        // still camera's colour averages ever more frames, whose noise falls as 1 / frames:
        // the variance the filter sees falls with it beyond the history's length, so that
        // the filter fades out and the shown image converges to the unfiltered one.
        if (frames > cap) m.y = m.x * m.x + (m.y - m.x * m.x) * (cap / frames);
        moments[i] = m;
    });
    SvgfInput input;
    input.width = m_settings.width;
    input.height = m_settings.height;
    input.colour = colour;
    input.albedo = m_geometry->albedo;
    input.normal = m_geometry->normal;
    // Lamps seen directly pass through, and no pixel takes their light: they are exact, and
    // so much brighter than the surfaces beside them that even weights near zero spread
    // their light (a relative MSE of 0.066 against path's in the Cornell box's first frame
    // after a move, 0.0038 without them). SVGF passes pixels of depth 0 through and leaves
    // them out of every sum.
    std::vector<float> depth = m_geometry->depth;
    for (std::size_t i = 0; i < pixels; ++i)
        if (!m_geometry->emitter.empty() && m_geometry->emitter[i]) depth[i] = 0.0f;
    input.depth = depth;
    input.moments = moments;
    input.history_length = lengths;
    const std::vector<Rgb> filtered = svgf_filter(input, m_options.svgf);
    Image result = make_image(m_settings.width, m_settings.height, {"R", "G", "B"});
    parallel_for_indices(pixels, [&](std::size_t i) {
        for (int ch = 0; ch < 3; ++ch) result.pixels[3 * i + ch] = filtered[i][ch];
    });
    return result;
}

std::vector<std::string> ProgressiveSession::progressive_integrators(
    const RenderSettings& settings) {
    std::vector<std::string> names;
    for (const std::string& name : integrator_names()) {
        RenderSettings candidate = settings;
        candidate.integrator = name;
        try {
            std::vector<std::string> warnings;  // keys of other integrators: not our concern
            const auto integrator = make_integrator(candidate, &warnings);
            if (dynamic_cast<ProgressiveIntegrator*>(integrator.get())) names.push_back(name);
        } catch (const Error&) {
            // An integrator these settings do not suit is simply not offered.
        }
    }
    return names;
}

Image ProgressiveSession::denoised_image(Progress& progress, int threads) const {
    if (!m_film.has_aovs()) throw Error("the viewer's film has no AOVs to denoise with");
    RenderSettings settings = m_settings;
    settings.denoise = true;
    settings.denoiser = "network";
    return denoise_film(m_film, settings, threads, progress);
}

}  // namespace glint
