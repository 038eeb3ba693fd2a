#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/film/film.h>
#include <glint/integrator/integrator.h>
#include <glint/render/denoise_step.h>
#include <glint/render/render_checks.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>

namespace glint {
namespace {

// Each debug view some registered integrator offers, with what it needs.
std::vector<DebugView> known_debug_views() {
    std::vector<DebugView> views;
    for (const std::string& name : integrator_names()) {
        for (const DebugView& view : integrator_capabilities(name).debug_views) {
            const bool seen = std::any_of(views.begin(), views.end(),
                                          [&](const DebugView& v) { return v.name == view.name; });
            if (!seen) views.push_back(view);
        }
    }
    std::sort(views.begin(), views.end(),
              [](const DebugView& a, const DebugView& b) { return a.name < b.name; });
    return views;
}

}  // namespace

void check_debug_views(const RenderSettings& settings) {
    if (settings.debug.empty()) return;
    const std::string& where = settings.where_of("debug");
    const std::vector<DebugView> known = known_debug_views();
    const std::vector<std::string> names = integrator_names();
    // An unknown integrator is make_integrator()'s error, later: here it offers no view.
    const IntegratorCapabilities chosen =
        std::find(names.begin(), names.end(), settings.integrator) != names.end()
            ? integrator_capabilities(settings.integrator)
            : IntegratorCapabilities{};
    for (const std::string& view : settings.debug) {
        const auto it = std::find_if(known.begin(), known.end(),
                                     [&](const DebugView& v) { return v.name == view; });
        if (it == known.end()) {
            std::vector<std::string> known_names;
            for (const DebugView& v : known) known_names.push_back(v.name);
            throw Error(fmt::format("{}: unknown debug view '{}' (known: {})", where, view,
                                    fmt::join(known_names, ", ")));
        }
        // The sobel edge mask needs a setting rather than an integrator: one that does not
        // sample adaptively refuses `adaptive` itself (make_integrator).
        const bool met =
            view == "edges" ? settings.adaptive == "sobel" : chosen.has_debug_view(view);
        if (!met) throw Error(fmt::format("{}: debug view '{}' needs {}", where, view, it->needs));
    }
}

bool film_needs_aovs(const RenderSettings& settings) {
    return settings.aovs || settings.denoise;
}

void check_render_settings(const RenderSettings& settings) {
    check_debug_views(settings);
    check_denoise(settings, make_integrator(settings, nullptr)->capabilities());
}

void check_film_memory(const RenderSettings& settings) {
    const bool aovs = film_needs_aovs(settings);
    const bool halves = film_needs_halves(settings);
    check_memory(Film::memory_bytes(settings.width, settings.height, aovs, halves),
                 fmt::format("the film ({}x{}{})", settings.width, settings.height,
                             halves             ? " with AOVs and halves for the denoiser"
                             : settings.denoise ? " with AOVs for the denoiser"
                             : aovs             ? " with AOVs"
                                                : ""));
}

}  // namespace glint
