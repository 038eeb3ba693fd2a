#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/integrator/realtime/restir_di.h>
#include <glint/integrator/transport/transport.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/material/bsdf.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

// Neighbours (and the previous pass's pixel) are rejected when their depth differs by more
// than this fraction, or their normals by more than 25 degrees (Bitterli et al.'s tests).
constexpr float kDepthTolerance = 0.1f;
constexpr float kNormalCosine = 0.906f;

// A light point as next-event estimation sampled it, as a candidate that can move between
// pixels, and the density with which it was chosen in the candidates' measure (see
// restir_di.h). False when it carries nothing.
bool make_candidate(const LightPoint& point, const Vec3& ref, LightCandidate& out, float& pdf) {
    const LightSample& ls = *point.sample;
    const Light* light = point.choice.light;
    out.light = light;
    if (light->is_infinite()) {
        out.kind = LightCandidate::Kind::kDirection;
        out.point = ls.wi;
        pdf = point.choice.pmf * ls.pdf;
    } else if (light->is_delta_direction()) {
        out.kind = LightCandidate::Kind::kParallel;
        out.point = ls.wi;
        out.irradiance = ls.L;
        pdf = point.choice.pmf;
    } else if (ls.n.x != 0.0f || ls.n.y != 0.0f || ls.n.z != 0.0f) {
        out.kind = LightCandidate::Kind::kArea;
        out.point = ls.p;
        out.normal = ls.n;
        // Solid angle to area: dA = d^2 / |cos_light| dw.
        const Vec3 d = ls.p - ref;
        const float distance2 = glm::dot(d, d);
        const float cos_light = std::abs(glm::dot(ls.n, ls.wi));
        if (!(distance2 > 0.0f) || !(cos_light > 0.0f)) return false;
        pdf = point.choice.pmf * ls.pdf * cos_light / distance2;
    } else {
        out.kind = LightCandidate::Kind::kPoint;
        out.point = ls.p;
        pdf = point.choice.pmf;
    }
    return pdf > 0.0f && std::isfinite(pdf);
}

}  // namespace

RestirMode restir_mode_named(const std::string& name) {
    if (name == "unbiased") return RestirMode::kUnbiased;
    if (name == "biased") return RestirMode::kBiased;
    if (name == "off") return RestirMode::kOff;
    throw Error(
        fmt::format("unknown ReSTIR mode '{}' (expected 'unbiased', 'biased' or 'off')", name));
}

float RestirDi::target_of(const Spectrum& contribution) {
    const float y = contribution.luminance();
    return y > 0.0f && std::isfinite(y) ? y : 0.0f;
}

bool RestirDi::arrive(const ReuseSurface& surface, const LightCandidate& candidate,
                      Arrival& out) const {
    Vec3 wi;
    Spectrum L;
    switch (candidate.kind) {
        case LightCandidate::Kind::kDirection:
            wi = candidate.point;
            L = candidate.light->le_escaped(wi);
            out.target = surface.p + wi * m_far;
            break;
        case LightCandidate::Kind::kParallel:
            wi = candidate.point;
            L = candidate.irradiance;
            out.target = surface.p + wi * m_far;
            break;
        case LightCandidate::Kind::kArea:
        case LightCandidate::Kind::kPoint: {
            const Vec3 d = candidate.point - surface.p;
            const float distance2 = glm::dot(d, d);
            if (!(distance2 > 0.0f)) return false;
            wi = d / std::sqrt(distance2);
            if (candidate.kind == LightCandidate::Kind::kArea) {
                const float g = std::abs(glm::dot(candidate.normal, wi)) / distance2;
                L = candidate.light->emitted(candidate.point, candidate.normal, -wi) * g;
            } else {
                L = candidate.light->emitted(candidate.point, Vec3(0.0f), -wi) / distance2;
            }
            out.target = candidate.point;
            break;
        }
    }
    if (L.is_black()) return false;
    const Vec3 wi_local = surface.shading.to_local(wi);
    out.contribution =
        surface.bsdf->eval(surface.wo_local, wi_local) * (abs_cos_theta(wi_local)) * L;
    return !out.contribution.is_black();
}

void RestirDi::begin_pass(const Scene& scene, int width, int height, Vec2i origin,
                          bool keep_history) {
    const Bounds3& bounds = scene.stats().bounds;
    m_far = 2.0f * (bounds.is_empty() ? 1.0f : glm::length(bounds.extent())) + 1.0f;
    const bool same_film = width == m_width && height == m_height && origin == m_origin;
    if (!same_film) {
        m_width = width;
        m_height = height;
        m_origin = origin;
        const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
        for (int b = 0; b < 2; ++b) {
            m_surfaces[b].assign(pixels, ReuseSurface{});
            m_final[b].assign(pixels, LightReservoir{});
        }
        m_temporal.assign(pixels, LightReservoir{});
    }
    m_history = m_history && keep_history && same_film && m_settings.temporal;
    const float diagonal = std::sqrt(static_cast<float>(width) * static_cast<float>(width) +
                                     static_cast<float>(height) * static_cast<float>(height));
    const float radius =
        m_settings.radius > 0.0f ? m_settings.radius : std::clamp(diagonal / 64.0f, 3.0f, 30.0f);
    if (radius != m_radius || m_offsets.empty()) {
        m_radius = radius;
        // Every pixel offset within the radius but the pixel itself (at least its 8
        // neighbours, however small the radius), from which spatial reuse draws.
        const int reach = std::max(1, static_cast<int>(std::min(radius, 1024.0f)));
        const float limit = std::max(radius * radius, 2.0f);
        m_offsets.clear();
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx)
                if ((dx != 0 || dy != 0) && static_cast<float>(dx * dx + dy * dy) <= limit)
                    m_offsets.emplace_back(dx, dy);
    }
    m_previous_camera = std::move(m_camera);
    m_camera = scene.camera().clone();
}

void RestirDi::end_pass() {
    m_current ^= 1;
    m_history = true;
}

bool RestirDi::similar(const ReuseSurface& a, const ReuseSurface& b) const {
    return b.bsdf != nullptr &&
           std::abs(a.depth - b.depth) <= kDepthTolerance * std::max(a.depth, b.depth) &&
           glm::dot(a.shading.n(), b.shading.n()) >= kNormalCosine;
}

Scene::ShadowRay RestirDi::shadow_ray_to(const ReuseSurface& surface, const Vec3& target) {
    const Vec3 origin = offset_ray_origin(surface.p, surface.ng, target - surface.p);
    return Scene::ShadowRay{origin, target - origin, surface.time};
}

Spectrum RestirDi::transmittance_to(const Scene& scene, const ReuseSurface& surface,
                                    const Vec3& target, RayCounter& counter) const {
    ++counter.rays;
    return transmittance(scene, shadow_ray_to(surface, target));
}

RestirDi::LightReservoir RestirDi::combine(const Scene& scene, const LightReservoir* const* inputs,
                                           const ReuseSurface* const* surfaces, int count, Rng& rng,
                                           Spectrum& through, RayCounter& counter) const {
    LightReservoir combined;
    through = Spectrum(0.0f);
    int chosen = -1;
    Vec3 chosen_target(0.0f);
    for (int i = 0; i < count; ++i) {
        // The first input is the pixel's own: its target is already the one here.
        float target = inputs[i]->target;
        Arrival arrival;
        if (i > 0) {
            target = inputs[i]->has_sample() && arrive(*surfaces[0], inputs[i]->sample, arrival)
                         ? target_of(arrival.contribution)
                         : 0.0f;
        }
        if (combined.merge(*inputs[i], target, rng.next_float())) {
            chosen = i;
            chosen_target = i > 0 ? arrival.target : Vec3(0.0f);
        }
    }
    if (chosen < 0) return combined;  // W = 0: nothing to shade with
    // Whether the sample reaches this pixel's surface: known for its own sample.
    if (chosen == 0) {
        through = Spectrum(1.0f);
        if (scene.has_interfaces()) {
            Arrival arrival;
            if (arrive(*surfaces[0], combined.sample, arrival))
                through = transmittance_to(scene, *surfaces[0], arrival.target, counter);
        }
    } else {
        through = transmittance_to(scene, *surfaces[0], chosen_target, counter);
    }
    if (m_settings.mode == RestirMode::kBiased) {
        combined.finish_uniform();
    } else {
        // The balance heuristic over the candidates the inputs stand for, each input's target
        // and visibility evaluated at its own surface: p_s(y) V_s(y) / sum_i M_i p_i(y) V_i(y).
        float numerator = 0.0f, denominator = 0.0f;
        for (int i = 0; i < count; ++i) {
            float target = combined.target;
            if (i > 0) {
                Arrival arrival;
                target = arrive(*surfaces[i], combined.sample, arrival)
                             ? target_of(arrival.contribution)
                             : 0.0f;
                if (target > 0.0f && i != chosen &&
                    transmittance_to(scene, *surfaces[i], arrival.target, counter).is_black())
                    target = 0.0f;
            } else if (through.is_black()) {
                target = 0.0f;
            }
            denominator += inputs[i]->count * target;
            if (i == chosen) numerator = target;
        }
        combined.finish_weighted(denominator > 0.0f ? numerator / denominator : 0.0f);
    }
    // Keep the invariant: a reservoir's sample reaches its surface.
    if (through.is_black()) combined.W = 0.0f;
    return combined;
}

void RestirDi::generate(const Scene& scene, int x, int y, Sampler& sampler, RayCounter& counter) {
    const std::optional<Scene::ShadowRay> shadow = draw_candidates(scene, x, y, sampler);
    Spectrum visible(0.0f);
    if (shadow) {
        ++counter.rays;
        visible = transmittance(scene, *shadow);
    }
    reuse_history(scene, x, y, visible, sampler, counter);
}

std::optional<Scene::ShadowRay> RestirDi::draw_candidates(const Scene& scene, int x, int y,
                                                          Sampler& sampler) {
    const size_t i = index(x, y);
    const ReuseSurface& s = m_surfaces[m_current][i];
    LightReservoir& r = m_temporal[i];
    r = LightReservoir{};
    if (!s.bsdf) return std::nullopt;
    const Vec3 n = s.shading.n();
    Vec3 chosen_target(0.0f);
    for (int c = 0; c < m_settings.candidates; ++c) {
        // Next-event estimation's draws, then the reservoir's.
        const Vec2 u = sampler.get_2d();
        const float u_light = sampler.get_1d();
        const float u_select = sampler.get_1d();
        const float u_keep = sampler.get_1d();
        r.count += 1.0f;
        const LightPoint point = sample_light_point(scene, s.p, n, u, u_light, u_select);
        if (!point.sample || point.sample->L.is_black() || !(point.choice.pmf > 0.0f) ||
            !(point.sample->pdf > 0.0f))
            continue;
        LightCandidate candidate;
        float pdf = 0.0f;
        Arrival arrival;
        if (!make_candidate(point, s.p, candidate, pdf) || !arrive(s, candidate, arrival)) continue;
        const float target = target_of(arrival.contribution);
        if (r.update(candidate, target / pdf, target, u_keep)) chosen_target = arrival.target;
    }
    r.finish_uniform();
    // Visibility reuse: a sample that does not reach the surface is dropped (by
    // reuse_history) before it spreads; the candidates still count.
    if (!r.has_sample()) return std::nullopt;
    return shadow_ray_to(s, chosen_target);
}

void RestirDi::reuse_history(const Scene& scene, int x, int y, const Spectrum& visible,
                             Sampler& sampler, RayCounter& counter) {
    const size_t i = index(x, y);
    const ReuseSurface& s = m_surfaces[m_current][i];
    LightReservoir& out = m_temporal[i];
    if (!s.bsdf) return;
    LightReservoir r = out;
    if (r.has_sample() && visible.is_black()) r.W = 0.0f;
    if (m_history && s.seen_directly) {
        const int previous = m_current ^ 1;
        const std::optional<FilmProjection> projected =
            m_previous_camera ? m_previous_camera->project(s.p) : std::nullopt;
        if (projected) {
            const int px = static_cast<int>(std::floor(projected->film.x)) - m_origin.x;
            const int py = static_cast<int>(std::floor(projected->film.y)) - m_origin.y;
            if (px >= 0 && py >= 0 && px < m_width && py < m_height) {
                const size_t j = index(px, py);
                const ReuseSurface& ps = m_surfaces[previous][j];
                // The depth the previous pass would have seen this point at.
                ReuseSurface expected = s;
                expected.depth = projected->depth;
                if (ps.seen_directly && similar(expected, ps)) {
                    LightReservoir history = m_final[previous][j];
                    history.count =
                        std::min(history.count, m_settings.history_cap *
                                                    static_cast<float>(m_settings.candidates));
                    const LightReservoir* inputs[2] = {&r, &history};
                    const ReuseSurface* surfaces[2] = {&s, &ps};
                    Rng rng(hash_combine(static_cast<uint64_t>(sampler.get_1d() * 0x1p32f), i));
                    Spectrum through;
                    r = combine(scene, inputs, surfaces, 2, rng, through, counter);
                }
            }
        }
    }
    out = r;
}

void RestirDi::draw_neighbours(int x, int y, uint64_t key, SpatialDraw& draw) const {
    draw.rng = Rng(key);
    draw.count = 0;
    if (m_settings.spatial <= 0) return;
    for (int k = 0; k < std::min(m_settings.spatial, kMaxNeighbours); ++k) {
        // One of the offsets, uniformly (the high half of a 32 x 32-bit product).
        const uint64_t pick = (static_cast<uint64_t>(draw.rng.next_u32()) * m_offsets.size()) >> 32;
        const int nx = x + m_offsets[pick].x;
        const int ny = y + m_offsets[pick].y;
        if (nx < 0 || ny < 0 || nx >= m_width || ny >= m_height) continue;
        const size_t j = index(nx, ny);
        // A surface spans two cache lines, and the test of similarity reads both.
        const char* surface = reinterpret_cast<const char*>(&m_surfaces[m_current][j]);
        __builtin_prefetch(surface);
        __builtin_prefetch(surface + sizeof(ReuseSurface) - 1);
        __builtin_prefetch(&m_temporal[j]);
        draw.neighbours[draw.count++] = j;
    }
}

Spectrum RestirDi::shade(const Scene& scene, int x, int y, uint64_t key, RayCounter& counter) {
    SpatialDraw draw;
    draw_neighbours(x, y, key, draw);
    return shade(scene, x, y, draw, counter);
}

Spectrum RestirDi::shade(const Scene& scene, int x, int y, SpatialDraw& draw, RayCounter& counter) {
    const size_t i = index(x, y);
    const ReuseSurface& s = m_surfaces[m_current][i];
    LightReservoir& final = m_final[m_current][i];
    final = m_temporal[i];
    if (!s.bsdf) return Spectrum(0.0f);
    if (m_settings.spatial > 0) {
        Rng& rng = draw.rng;
        const LightReservoir* inputs[1 + kMaxNeighbours];
        const ReuseSurface* surfaces[1 + kMaxNeighbours];
        inputs[0] = &m_temporal[i];
        surfaces[0] = &s;
        int count = 1;
        for (int k = 0; k < draw.count; ++k) {
            const size_t j = draw.neighbours[k];
            const ReuseSurface& ns = m_surfaces[m_current][j];
            if (!similar(s, ns)) continue;
            inputs[count] = &m_temporal[j];
            surfaces[count] = &ns;
            ++count;
        }
        if (count > 1) {
            Spectrum through;
            final = combine(scene, inputs, surfaces, count, rng, through, counter);
            if (!final.has_sample()) return Spectrum(0.0f);
            Arrival arrival;
            if (!arrive(s, final.sample, arrival)) return Spectrum(0.0f);
            return arrival.contribution * through * final.W;
        }
    }
    // The pixel's own sample, which visibility reuse (or the temporal merge) has checked.
    if (!final.has_sample()) return Spectrum(0.0f);
    Arrival arrival;
    if (!arrive(s, final.sample, arrival)) return Spectrum(0.0f);
    const Spectrum through = scene.has_interfaces()
                                 ? transmittance_to(scene, s, arrival.target, counter)
                                 : Spectrum(1.0f);
    return arrival.contribution * through * final.W;
}

}  // namespace glint
