#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/medium/delta_tracking.h>
#include <glint/scene/scene.h>

#include <algorithm>
#include <cmath>

#include <optional>

namespace glint {
namespace {

// The probe's direction: fixed, so every render finds the same media, and far from the axes
// and diagonals along which boxes' edges and faces lie.
const Vec3 kProbeDirection = glm::normalize(Vec3(0.5377f, 0.8122f, 0.2262f));
// A probe gives up after this many surfaces that bound no media (a wall of glass panes).
constexpr int kMaxProbeSurfaces = 4096;

// The medium on the side of the first media-bounding surface a probe from p arrives at, or
// nullopt when the probe leaves the scene without meeting one.
std::optional<const Medium*> probe(const Scene& scene, const Vec3& p) {
    Ray ray{p, kProbeDirection, 0.0f, kInfinity, 0.0f};
    for (int surfaces = 0; surfaces < kMaxProbeSurfaces; ++surfaces) {
        SurfaceInteraction si;
        if (!scene.intersect_surface(ray, si)) return std::nullopt;
        const MediumInterface media = si.material->medium_interface();
        if (media.is_transition()) return media.arriving(glm::dot(ray.direction, si.ng) < 0.0f);
        ray = spawn_ray(si, ray.direction);
    }
    return std::nullopt;
}

}  // namespace

const Medium* medium_containing(const Scene& scene, const Vec3& p) {
    if (scene.media().empty()) return nullptr;
    if (const std::optional<const Medium*> enclosing = probe(scene, p)) return *enclosing;
    // Outside every closed medium: the camera's medium fills that space only if the camera
    // is out there too.
    const Ray eye = scene.camera().generate_ray(Vec2(0.5f), Vec2(0.5f));
    return probe(scene, eye.origin) ? nullptr : scene.camera_medium();
}

std::optional<WalkMedia> walk_media(const Scene& scene) {
    // Only media a walk can be in count: the camera's, and those the surfaces bound. A
    // medium the scene defines but places nowhere changes nothing, and costs nothing.
    const auto sampled = [](const Medium* m) { return m && (m->scatters() || m->emits()); };
    bool reachable = sampled(scene.camera_medium());
    for (const auto& material : scene.materials()) {
        const MediumInterface media = material->medium_interface();
        reachable = reachable || sampled(media.inside) || sampled(media.outside);
    }
    if (!reachable) return std::nullopt;
    WalkMedia result;
    result.camera = scene.camera_medium();
    // A light names no medium: the one round a point it emits from (light_tracer.cpp's rule).
    const auto& lights = scene.lights();
    for (const auto& light : lights) {
        const int index = light->index();
        if (index < 0) continue;
        if (static_cast<size_t>(index) >= result.light_start.size())
            result.light_start.resize(index + 1, nullptr);
        const std::optional<LightEmission> e = light->sample_le(Vec2(0.5f), Vec2(0.5f), 0.5f);
        if (e) result.light_start[index] = medium_containing(scene, e->ray.origin);
    }
    return result;
}

SegmentEnd through_medium(const Medium& medium, const Ray& ray, float t_hit, int hero, Rng& rng,
                          Spectrum& weight, Spectrum& r_u, float& t_scatter, float& sigma_t,
                          Spectrum* emission) {
    weight = Spectrum(1.0f);
    if (emission) *emission = Spectrum(0.0f);
    const bool collect = emission && medium.emits();
    if (!samples_distances(medium)) {
        weight = medium.transmittance(ray, std::isinf(t_hit) ? 1e30f : t_hit, rng);
        return weight.is_black() ? SegmentEnd::kAbsorbed : SegmentEnd::kReached;
    }
    SegmentEnd end = SegmentEnd::kReached;
    const Spectrum T_maj = sample_collisions(
        medium, ray, t_hit, hero, rng,
        [&](float t, const MediumPoint& point, const Spectrum& sigma_maj, const Spectrum& T) {
            const float sigma_hero = sigma_maj.value(hero), T_hero = T.value(hero);
            if (collect && !point.emission.is_black()) {
                // The source sigma_a Le at a tentative collision, over the density of the
                // collision, weighted over the channels that could have been the hero.
                const float pdf = sigma_hero * T_hero;
                const float r_e = (r_u * weight * sigma_maj * T / pdf).average();
                if (r_e > 0.0f)
                    *emission += weight * T * point.sigma_a * point.emission / (pdf * r_e);
            }
            const float p_absorb = point.sigma_a.value(hero) / sigma_hero;
            const float p_scatter = point.sigma_s.value(hero) / sigma_hero;
            const float u = rng.next_float();
            if (u < p_absorb) {
                end = SegmentEnd::kAbsorbed;
                return false;
            }
            if (u < p_absorb + p_scatter) {
                weight *= T * point.sigma_s / (T_hero * point.sigma_s.value(hero));
                end = weight.is_black() ? SegmentEnd::kAbsorbed : SegmentEnd::kScattered;
                t_scatter = t;
                sigma_t = (point.sigma_a + point.sigma_s).average();
                return false;
            }
            // A null collision: on, each channel weighted by its null share.
            const Spectrum sigma_n =
                (sigma_maj - point.sigma_a - point.sigma_s).clamped(0.0f, kInfinity);
            const float pdf = T_hero * sigma_n.value(hero);
            if (!(pdf > 0.0f)) {
                end = SegmentEnd::kAbsorbed;
                return false;
            }
            weight *= T * sigma_n / pdf;
            if (weight.is_black()) {
                end = SegmentEnd::kAbsorbed;
                return false;
            }
            return true;
        });
    if (end == SegmentEnd::kReached) {
        const float T_hero = T_maj.value(hero);
        if (!(T_hero > 0.0f)) return SegmentEnd::kAbsorbed;
        weight *= T_maj / T_hero;
    }
    r_u *= weight;
    return end;
}

}  // namespace glint
