#pragma once
// Integrators turn a Scene into an image on a Film.
#include <glint/core/arena.h>
#include <glint/core/sampler.h>
#include <glint/film/film.h>
#include <glint/film/filter.h>
#include <glint/integrator/progressive.h>
#include <glint/integrator/render_stats.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene.h>

#include <atomic>
#include <memory>

namespace glint {

class Progress;

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual RenderStats render(const Scene& scene, Film& film, Progress& progress) = 0;
    /// Whether render() fills a film's halves (Film::has_halves(), by each sample's index),
    /// which a denoiser needs. Integrators that splat light paths onto the film do not.
    virtual bool records_halves() const { return false; }
};

// Counts rays per thread without contention; summed once per tile.
struct RayCounter {
    uint64_t rays = 0;
};

// The film's image with the integrator's extra channels (sample counts, edge mask) added.
Image final_image(const Film& film, const RenderStats& stats);

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

}  // namespace glint
