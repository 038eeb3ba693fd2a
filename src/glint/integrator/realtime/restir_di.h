#pragma once
// ReSTIR DI (Bitterli, Wyman, Pharr, Shirley, Lefohn and Jarosz 2020, "Spatiotemporal
// reservoir resampling for real-time ray tracing with dynamic direct lighting"): direct
// light at one surface point per pixel, with the light sample chosen by resampled
// importance sampling (RIS) and then reused from the same pixel's previous pass (temporal
// reuse, reprojected) and from nearby pixels (spatial reuse).
//
// The sample space is the set of points on the lights, in one measure shared by all
// pixels, so that a sample can move from one pixel to another: area on area lights, one
// point per point or spot light (counting measure), and solid angle for lights at infinity
// (the environment, directional lights). The target function at a surface point is the
// luminance of the unshadowed contribution f |cos| Le G, with G = |cos_light| / d^2 on area
// lights, 1 / d^2 for point lights and 1 for directions.
//
// Visibility reuse (both modes): after its candidates, each pixel traces a shadow ray to its
// reservoir's sample and empties the reservoir (W = 0, M kept) when it is blocked, so that
// occluded samples stop spreading; a reservoir's sample therefore always reaches its own
// surface, and a reservoir stands for the integrand with visibility, f V, whose support is
// where p V > 0. Two ways to weigh reused reservoirs (RestirMode):
// - unbiased: the chosen sample y's weight is the balance heuristic over the reservoirs that
//   were combined, p_s(y) V_s(y) / sum_i M_i p_i(y) V_i(y), each p_i V_i the target with
//   visibility at reservoir i's own surface (Bitterli et al. 2020, eq. 22 and the
//   visibility-aware weights of their unbiased variant): the weights sum to one over the
//   candidates that could have produced y, so the estimate is unbiased. It costs one shadow
//   ray per merged reservoir but the chosen one (whose visibility is known).
// - biased: 1 / M weights, no neighbour's target or visibility is evaluated (one shadow ray
//   per pixel for the final sample instead of one per neighbour). The bias: 1/M counts every
//   neighbour's candidates, also those of a neighbour that could not have produced the
//   sample, because from there it was blocked (visibility reuse emptied its reservoir) or
//   below its horizon. The estimate is then too small: darkening at occlusion boundaries
//   (contact shadows, shadow edges, a wall's foot) and at creases, where neighbours pass
//   the depth and normal tests but see the lights differently. Away from such boundaries it
//   equals the unbiased mode.
#include <glint/core/rng.h>
#include <glint/integrator/integrator.h>
#include <glint/integrator/realtime/reservoir.h>
#include <glint/math/frame.h>
#include <glint/scene/scene.h>

#include <optional>
#include <vector>

namespace glint {

class Bsdf;
class Camera;

enum class RestirMode { kOff, kUnbiased, kBiased };

struct RestirSettings {
    RestirMode mode = RestirMode::kOff;
    /// M: light samples per pixel per pass (RIS). 2 candidates and 2 neighbours gave the
    /// lowest error at equal time on examples/many-lights.lua (bench/README.md).
    int candidates = 2;
    int spatial = 2;       ///< neighbours merged per pixel (0: no spatial reuse)
    bool temporal = true;  ///< merge the previous pass's reservoir (reprojected)
    /// Spatial neighbours within this many pixels (drawn uniformly from the pixels within it,
    /// at most 1024); 0: a 64th of the film's diagonal, within [3, 30] (Bitterli et al. use
    /// 30 at 1920 x 1080).
    float radius = 0.0f;
    /// The previous pass counts at most this many times M. Bitterli et al. use 20 for single
    /// frames; the preview averages its passes, and passes that share much history average
    /// out less noise: 5 gave the lowest error after 16 passes on tests/integrator/realtime.
    float history_cap = 5.0f;
};

/// A light sample that can move between pixels: where it is on its light.
struct LightCandidate {
    enum class Kind : unsigned char { kArea, kPoint, kDirection, kParallel };
    const Light* light = nullptr;
    Vec3 point{0.0f};           ///< on the light; for kDirection and kParallel the unit direction
                                ///< towards the light
    Vec3 normal{0.0f};          ///< the light's normal at `point` (kArea)
    Spectrum irradiance{0.0f};  ///< a directional light's (kParallel), the same everywhere
    Kind kind = Kind::kPoint;
};

/// A surface point as reuse needs it: where it is, its BSDF and what rejection compares.
struct ReuseSurface {
    Vec3 p{0.0f};
    Vec3 ng{0.0f};
    Frame shading;
    Vec3 wo_local{0.0f};         ///< towards the camera's side, in the shading frame
    const Bsdf* bsdf = nullptr;  ///< null: the pixel has no surface to light
    float depth = 0.0f;          ///< distance along the camera's path to p
    float time = 0.0f;
    bool seen_directly = false;  ///< reached without mirrors or glass (temporal reuse needs it)
};

class RestirDi {
public:
    using LightReservoir = Reservoir<LightCandidate>;

    explicit RestirDi(const RestirSettings& settings) : m_settings(settings) {}

    /// Prepares the buffers of a pass over a `width` x `height` film whose first pixel is
    /// `origin` (in the full image); keeps the previous pass's surfaces and reservoirs for
    /// temporal reuse when `keep_history` and the film is the same.
    void begin_pass(const Scene& scene, int width, int height, Vec2i origin, bool keep_history);
    /// Ends the pass: its surfaces and final reservoirs become the history.
    void end_pass();
    /// Forgets the history (a light or an object changed).
    void drop_history() { m_history = false; }

    /// The surface of film pixel (x, y) in this pass, which the caller fills in.
    ReuseSurface& surface(int x, int y) { return m_surfaces[m_current][index(x, y)]; }
    /// The previous pass's surfaces stay valid until end_pass(): BSDFs the caller makes for
    /// this pass's surfaces must live as long (two arenas, used in turn).
    int buffer() const { return m_current; }

    /// First stage, per pixel once its surface is set: M candidates from the scene's light
    /// sampler, then the reprojected previous reservoir (and, when biased, visibility
    /// reuse). Draws from `sampler` (its order: per candidate a 2D value and two 1D values as
    /// next-event estimation draws them, then a 1D value deciding).
    void generate(const Scene& scene, int x, int y, Sampler& sampler, RayCounter& counter);
    /// generate() in two parts, so that a caller can trace the shadow rays of several pixels
    /// together (the preview traces a block's as one packet): draw_candidates() takes the
    /// draws of the M candidates and returns the shadow ray of visibility reuse (none when
    /// the candidates left nothing to check); reuse_history() takes what that ray let
    /// through (ignored when there was none) and merges the previous pass's reservoir. The
    /// two together draw, trace and give what generate() does, bit for bit.
    std::optional<Scene::ShadowRay> draw_candidates(const Scene& scene, int x, int y,
                                                    Sampler& sampler);
    void reuse_history(const Scene& scene, int x, int y, const Spectrum& visible, Sampler& sampler,
                       RayCounter& counter);
    /// Second stage, per pixel after every pixel's first stage: spatial reuse, then the
    /// direct light reflected towards wo from the final sample, with its shadow ray.
    /// `key` seeds the neighbours' choice (the same for any thread count).
    Spectrum shade(const Scene& scene, int x, int y, uint64_t key, RayCounter& counter);

    /// Spatial reuse merges at most this many neighbours (settings are validated against it).
    static constexpr int kMaxNeighbours = 16;
    /// A pixel's spatial neighbours, drawn ahead of its shading: they lie rows apart, mostly
    /// outside the nearer caches, and drawing them starts their loads.
    struct SpatialDraw {
        Rng rng;  ///< drawn the neighbours; shade() draws on from it
        int count = 0;
        size_t neighbours[kMaxNeighbours];
    };
    /// The neighbours shade(x, y, key) would merge (their loads started).
    void draw_neighbours(int x, int y, uint64_t key, SpatialDraw& draw) const;
    /// shade(x, y, key) with its neighbours drawn by draw_neighbours(x, y, key): call that a
    /// few pixels ahead.
    Spectrum shade(const Scene& scene, int x, int y, SpatialDraw& draw, RayCounter& counter);

    /// The target function's value and the point to trace to, for `candidate` at `surface`:
    /// the unshadowed contribution f |cos| Le G (public for the tests).
    struct Arrival {
        Spectrum contribution{0.0f};
        Vec3 target{0.0f};
    };
    bool arrive(const ReuseSurface& surface, const LightCandidate& candidate, Arrival& out) const;
    static float target_of(const Spectrum& contribution);

    const RestirSettings& settings() const { return m_settings; }

private:
    size_t index(int x, int y) const {
        return static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x);
    }
    bool similar(const ReuseSurface& a, const ReuseSurface& b) const;
    // Combines `inputs` (the first is the pixel's own, whose sample is known to reach it)
    // into one reservoir for `surfaces[0]`, and sets `through` to what the path from
    // surfaces[0] to the chosen sample lets through (tracing a shadow ray only when the
    // sample came from another input). An input's sample always reaches that input's surface
    // (visibility reuse), so a sample that does not reach surfaces[0] leaves the result
    // empty (W = 0), and the result's sample reaches surfaces[0] too.
    LightReservoir combine(const Scene& scene, const LightReservoir* const* inputs,
                           const ReuseSurface* const* surfaces, int count, Rng& rng,
                           Spectrum& through, RayCounter& counter) const;
    // What the shadow ray from `surface` to `target` lets through (0 or 1 without media
    // interfaces).
    Spectrum transmittance_to(const Scene& scene, const ReuseSurface& surface, const Vec3& target,
                              RayCounter& counter) const;
    static Scene::ShadowRay shadow_ray_to(const ReuseSurface& surface, const Vec3& target);

    RestirSettings m_settings;
    int m_width = 0, m_height = 0;
    Vec2i m_origin{0};
    float m_far = 1.0f;            // beyond the scene, for the targets of lights at infinity
    float m_radius = 0.0f;         // of spatial reuse, in pixels
    std::vector<Vec2i> m_offsets;  // the pixel offsets within m_radius but (0, 0)
    int m_current = 0;
    bool m_history = false;
    // This pass's camera and the previous pass's (copies: the viewer replaces the scene's
    // camera when it moves), onto which temporal reuse projects (Camera::project).
    std::unique_ptr<Camera> m_camera, m_previous_camera;
    std::vector<ReuseSurface> m_surfaces[2];
    std::vector<LightReservoir> m_temporal;  // after the first stage
    std::vector<LightReservoir> m_final[2];  // after spatial reuse; [previous] is the history
};

RestirMode restir_mode_named(const std::string& name);

}  // namespace glint
