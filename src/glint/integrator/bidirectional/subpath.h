#pragma once
// Subpaths for the bidirectional methods (bdpt today; VCM and MLT later): a camera subpath
// and a light subpath as random walks that record, at every vertex, the densities with which
// each side's walk would have produced it. Multiple importance sampling over the ways of
// joining two subpaths (bdpt_mis.h) needs nothing else.
//
// Every random number comes from the Sampler passed in, in a documented order, so that a
// primary-sample-space sampler (MLT) can drive the same code.
//
// Densities (Veach 1997, ch. 10; the layout follows pbrt's BDPT): `pdf_fwd` is the density of
// a vertex as the walk that made it produced it, `pdf_rev` the density with which a walk
// from the other end would produce it; both per unit area at the vertex (with the cosine at
// the vertex), except at a vertex at infinity (an environment or directional light), where
// they are per unit solid angle of its direction. A vertex left through a delta lobe
// (mirror, smooth glass) has both set to 0 and `delta` true: no strategy can connect there.
//
// In participating media (a WalkMedia passed in) the walks sample distances by delta
// tracking on a hero channel, as volpath does, and scatter in media with the phase function.
// A medium vertex's densities are per unit volume: per solid angle over distance squared (no
// cosine: it has no normal) times the extinction there, the density of a collision per unit
// length. They leave out the transmittance (alike both ways along a segment, pbrt-v3's
// choice): the weights of a path's strategies still come from one set of numbers and sum to
// 1, and with the extinction in, a merge in a medium (per unit volume) weighs fairly against
// the joins.
#include <glint/core/arena.h>
#include <glint/core/rng.h>
#include <glint/core/sampler.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/transport/media.h>

#include <vector>

namespace glint {

/// One vertex of a camera or light subpath.
struct PathVertex {
    enum class Kind : uint8_t {
        kCamera,   ///< the lens point
        kLight,    ///< a light subpath's start, or a light sampled to end a camera subpath
        kSurface,  ///< a surface hit (it may emit: `light` is then its area light)
        kEscape,   ///< a camera subpath that left the scene, towards `w_sky`
        kMedium,   ///< a scattering point in a participating medium (`medium`)
    };
    Kind kind = Kind::kSurface;
    bool delta = false;     ///< the walk left this vertex through a delta lobe
    bool infinite = false;  ///< a direction at infinity (environment, directional light,
                            ///< escape), not a point: `p` is unused for densities
    Spectrum beta{0.0f};    ///< throughput from the subpath's start to here (for a camera
                            ///< subpath: importance; light subpath: power), this vertex's
                            ///< scattering excluded
    float pdf_fwd = 0.0f, pdf_rev = 0.0f;  ///< see the header comment
    Vec3 p{0.0f};                          ///< position (ray origin for lights and the lens)
    Vec3 ng{0.0f};     ///< geometric normal of a surface; the emitting side's normal of an
                       ///< area light's start; zero for points without a surface
    Vec3 w_sky{0.0f};  ///< infinite vertices: unit direction from the scene towards the light
    const Light* light = nullptr;    ///< the light of a light vertex or emitting surface (the
                                     ///< environment for an escape; null: constant background)
    const Bsdf* bsdf = nullptr;      ///< surfaces; null where the surface only emits
    SurfaceInteraction si;           ///< surfaces
    const Medium* medium = nullptr;  ///< the medium the walk reached this vertex through (a
                                     ///< medium vertex: the one it scatters in); null: vacuum
    Spectrum r_u{1.0f};    ///< in media, per channel: the density of the walk to here had that
                           ///< channel been the hero, over the hero's (volpath's r_u); 1 elsewhere
    float sigma_t = 0.0f;  ///< a medium vertex: the extinction there (mean over channels), the
                           ///< collision density per unit length its densities take on

    bool is_surface() const { return kind == Kind::kSurface; }
    bool is_medium() const { return kind == Kind::kMedium; }
    /// Whether a strategy can join a subpath here (a surface with a BSDF not purely delta,
    /// or a point in a medium).
    bool connectible() const { return is_medium() || (bsdf && !bsdf->is_delta()); }
    /// Whether a camera subpath that reached this vertex sees a light here (s = 0).
    bool is_emitter() const { return kind == Kind::kEscape || (is_surface() && light); }
};

/// One path sample's state in media: the hero channel that samples distances, and the
/// stream that delta and ratio tracking draw from. Drawn from the sampler before the camera
/// subpath: the hero (1D), then the stream's seed (1D).
struct MediaWalk {
    const WalkMedia* media = nullptr;
    int hero = 0;
    Rng rng;
    /// The subpath this walk makes has a hero of its own, not shared with the subpaths it
    /// joins (vcm: a camera subpath merges with many light subpaths). Each subpath is then
    /// weighted over its own channels: a join divides by the product of the two means of
    /// r_u, not by the mean of the product; each factor is an unbiased estimate on its own.
    bool own_hero = false;
    /// Radiance that media emit along the camera subpath's segments, weighted as volpath
    /// weights it (generate_camera_subpath adds it up). Only the camera subpath samples it:
    /// no other strategy makes such a path, so it needs no MIS weight, and the integrators
    /// add it to the pixel as it is.
    Spectrum emitted{0.0f};
    /// Which segments of the camera subpath collect `emitted`: kEveryDepth, every segment
    /// with room under WalkLimits::max_vertices for one more vertex (bdpt, vcm); a depth
    /// d >= 0, only the segment after d scattering vertices (mlt's s = 0 state of depth d);
    /// kNoDepth, none.
    static constexpr int kEveryDepth = -1, kNoDepth = -2;
    int emission_depth = kEveryDepth;
};
/// The media walk for one path sample (draws as MediaWalk says); none without media.
std::optional<MediaWalk> start_media_walk(const WalkMedia* media, Sampler& sampler);

/// The value of the scattering at `v` (a connectible vertex) from where its walk came from
/// (`v.si.wo`: back along the arriving ray, for medium vertices too) towards `w` (unit,
/// leaving v): the BSDF times |cos| at a surface (in `mode`), the phase function in a medium.
Spectrum scattering_towards(const PathVertex& v, const Vec3& w, TransportMode mode);
/// The medium a ray leaving `v` along `w` travels through.
const Medium* medium_leaving(const PathVertex& v, const Vec3& w);

/// What bounds a subpath's walk.
struct WalkLimits {
    int max_vertices = 2;  ///< vertices in all, the start included
    bool roulette = true;  ///< Russian roulette as the path tracer's (from the third hit)
};

/// The camera subpath of `ray` (a camera ray, as Camera::sample_ray makes it) into `path`
/// (cleared first): the lens vertex, then one vertex per hit, and an escape vertex when the
/// walk leaves the scene. Draws per hit that scatters: the BSDF sample (2D, 1D), then
/// roulette (1D) where it applies; per scattering in a medium the phase sample (2D), then
/// roulette (1D).
void generate_camera_subpath(const Scene& scene, const Ray& ray, Sampler& sampler, Arena& arena,
                             RayCounter& counter, const WalkLimits& limits,
                             std::vector<PathVertex>& path, MediaWalk* media = nullptr);

/// A light subpath into `path` (cleared first): a light chosen by the light sampler, a ray
/// from it (Light::sample_le), then one vertex per hit, scattering in importance mode.
/// Draws: the light (1D), the ray's origin (2D) and direction (2D), the light's part (1D);
/// then per hit the BSDF sample (2D, 1D) and roulette (1D). Empty when the scene has no
/// light or the light emits nothing. Every ray of the subpath has scene time `time` (the
/// camera subpath's that it joins: one time per path, so joins see one scene).
void generate_light_subpath(const Scene& scene, float time, Sampler& sampler, Arena& arena,
                            RayCounter& counter, const WalkLimits& limits,
                            std::vector<PathVertex>& path, MediaWalk* media = nullptr);

/// Density (per unit area at `next`, or solid angle when `next` is at infinity) with which a
/// walk at `v`, having arrived from `prev`, continues to `next`. `v` is the lens (prev
/// unused, may be null), a surface with a BSDF or a medium vertex.
float continuation_pdf(const Scene& scene, const PathVertex* prev, const PathVertex& v,
                       const PathVertex& next);

/// Density with which the light at `v` (a light vertex, an emitting surface or an escape)
/// emits towards `next`: per unit area at `next` (for a light at infinity, that of the disc
/// its rays leave, projected on `next`'s surface).
float emission_pdf(const PathVertex& v, const PathVertex& next);

/// Density with which a light subpath starts at `v` (see emission_pdf) heading to `next`:
/// the light sampler's probability of v's light times the density of the point (per unit
/// area), or of the direction for a light at infinity (per unit solid angle).
float emission_origin_pdf(const Scene& scene, const PathVertex& v, const PathVertex& next);

/// A density `pdf_solid` (per unit solid angle at `from`) converted to one per unit area
/// at `to` (unchanged when `to` is at infinity; per unit volume at a medium vertex).
float solid_angle_to_area(float pdf_solid, const PathVertex& from, const PathVertex& to);

}  // namespace glint
