#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/denoise/film_denoiser.h>
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
      m_film(m_settings.width, m_settings.height, options.aovs) {
    if (m_options.reduced_scale < 1) throw Error("the reduced scale must be at least 1");
    std::tie(m_integrator, m_progressive) = make_progressive(m_settings);
    m_scene = build_scene(m_desc, m_settings);
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
}

PassKind ProgressiveSession::render_next(Progress& progress) {
    if (m_rebuild) {
        SceneDesc desc = m_lights ? m_lights->apply(m_desc) : m_desc;
        desc.camera = m_camera;
        m_scene = build_scene(desc, m_settings);
        m_progressive->scene_changed(SceneChange::lights_or_objects);
        m_rebuild = m_camera_changed = false;
        restart();
    }
    if (m_camera_changed) {
        m_scene->set_camera(make_camera_for(Vec2i(m_settings.width, m_settings.height)));
        m_progressive->scene_changed(SceneChange::camera);
        m_camera_changed = false;
        restart();
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
        return PassKind::full;
    } catch (...) {
        // A pass cut short leaves some pixels with one sample more than others.
        m_restart = true;
        throw;
    }
}

Image ProgressiveSession::image() const {
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
