#pragma once
// Integrators turn a Scene into an image on a Film.
#include <glint/core/arena.h>
#include <glint/core/error.h>
#include <glint/core/sampler.h>
#include <glint/film/film.h>
#include <glint/film/filter.h>
#include <glint/integrator/progressive.h>
#include <glint/integrator/render_stats.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene.h>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace glint {

class Cluster;
class Progress;

/// A debug image an integrator can add (`--debug NAME`; its channel NAME.Y in RenderStats).
struct DebugView {
    std::string name;
    /// What the user must ask for to get it, for the error when the integrator chosen
    /// cannot write it: "needs <needs>".
    std::string needs;
};

/// What an integrator can do. The registry, the render pipeline and the viewer ask this,
/// never an integrator's name, so that a new integrator states its abilities in one place.
struct IntegratorCapabilities {
    /// Renders a crop window alone: its pixels do not depend on the rest of the image
    /// (light paths that splat anywhere on the film do).
    bool crop_windows = false;
    /// Honours `adaptive` (sobel, variance): takes a different number of samples per pixel.
    bool adaptive_sampling = false;
    /// Fills the film's two halves (Film::has_halves(), by each sample's index), which the
    /// denoiser needs. Integrators that splat light paths onto the film cannot.
    bool film_halves = false;
    /// Renders scenes that move: every ray of a path keeps its camera ray's time (Ray::time,
    /// SurfaceInteraction::time). Integrators whose light paths, photons or caches are
    /// made at one time cannot yet, and refuse such scenes.
    bool motion_blur = false;
    /// Follows hero wavelengths when the scene asks for `spectral = true`
    /// (docs/spectral.md); the others render in RGB, and the render says so.
    bool spectral = false;
    /// Samples scattering in participating media (glint.medium). The others see through
    /// such media as if they were not there, absorbing glass apart, and the render says so.
    bool scattering_media = false;
    /// Collects the light that media emit (glint.medium{ emission = ... }); the render says
    /// so where a medium emits and the integrator does not.
    bool emitting_media = false;
    /// Collects only the glow of media that fill a shape (light paths start there: the
    /// light tracer); the render says so where the camera's medium itself glows.
    bool glow_needs_shape = false;
    /// The debug views it can write, besides those every integrator's settings give.
    std::vector<DebugView> debug_views;

    bool has_debug_view(const std::string& name) const;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual RenderStats render(const Scene& scene, Film& film, Progress& progress) = 0;
    /// What this integrator can do; nothing beyond plain whole-image rendering by default.
    virtual IntegratorCapabilities capabilities() const { return {}; }
    /// For an MPI job (docs/cluster.md): an integrator that shares its own work among the
    /// ranks (sppm: each rank traces a share of every pass's photons, and the ranks exchange
    /// what they found) keeps `cluster` for render() and returns true; render() then gives
    /// every rank the film one process would. The default returns false: the job splits
    /// a tile integrator's samples instead, and refuses other integrators.
    virtual bool share_work(Cluster& cluster) {
        (void)cluster;
        return false;
    }
};

// Counts rays per thread without contention; summed once per tile.
struct RayCounter {
    uint64_t rays = 0;
};

// The film's image with the integrator's extra channels (sample counts, edge mask) added.
Image final_image(const Film& film, const RenderStats& stats);

/// Runs `check`, a validation of the render setting `key`; a glint::Error it throws comes
/// out prefixed with where `key` was set (settings.where_of: the scene's file and line, or
/// the flag), so that every integrator's message points at the line to fix.
template <typename Check>
void blame_setting(const RenderSettings& settings, const char* key, Check&& check) {
    try {
        check();
    } catch (const Error& e) {
        throw Error(settings.where_of(key) + ": " + e.what());
    }
}

/// For an integrator whose samples are not taken pixel by pixel (light paths, Markov
/// chains, passes over the whole film), so that no pixel can be sampled more: throws
/// glint::Error naming where `adaptive` was set, unless settings.adaptive is "none".
/// (Inline: the integrators' own libraries link before the registry's.)
inline void refuse_adaptive_sampling(const RenderSettings& settings, const char* integrator) {
    if (settings.adaptive == "none") return;
    throw Error(settings.where_of("adaptive") + ": integrator '" + integrator +
                "' has no adaptive sampling (adaptive '" + settings.adaptive + "')");
}

/// Makes an integrator from the common settings and the glint.render{...} table `params`
/// (a copy of settings.params), from which it reads and validates its own keys, each read
/// unconditionally: the registry learns which keys an integrator uses by creating it from
/// an empty table. Errors name the key's location (params.where_of(key)).
using IntegratorCreate = std::unique_ptr<Integrator> (*)(const RenderSettings& settings,
                                                         const Params& params);

/// Builds the integrator named in settings.integrator (registry.cpp maps names to create
/// functions); throws glint::Error naming where the name came from and listing the known
/// names otherwise, or naming a key of glint.render{...} that no integrator reads. Keys
/// that only other integrators read are not an error (a scene may keep settings for
/// several): when `warnings` is not null, one line naming them is appended to it.
std::unique_ptr<Integrator> make_integrator(const RenderSettings& settings,
                                            std::vector<std::string>* warnings = nullptr);

/// The names make_integrator() knows, in name order.
std::vector<std::string> integrator_names();

/// The capabilities of the integrator registered as `name`, as made with default settings.
IntegratorCapabilities integrator_capabilities(const std::string& name);

}  // namespace glint
