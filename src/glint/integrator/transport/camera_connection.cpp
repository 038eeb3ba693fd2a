#include <glint/core/error.h>
#include <glint/integrator/transport/camera_connection.h>
#include <glint/integrator/transport/media.h>
#include <glint/integrator/transport/visibility.h>
#include <glint/medium/henyey_greenstein.h>

#include <fmt/format.h>

namespace glint {
namespace {

// A lens point seen from `p` at scene time `time` (where the camera then stands), when the
// camera gives one that carries importance.
std::optional<CameraWiSample> sample_lens(const Scene& scene, const Vec3& p, const Vec2& u_lens,
                                          float time) {
    std::optional<CameraWiSample> lens = scene.camera().sample_wi_at(p, u_lens, time);
    if (!lens || lens->We.is_black() || !(lens->pdf > 0.0f)) return std::nullopt;
    return lens;
}

// A point p inside `medium` joined to the lens: `towards(wi)` is what leaves p towards the
// lens along wi, per unit solid angle (a point in a medium has no cosine); the shadow ray
// takes on the media and interfaces between.
template <typename Towards>
std::optional<CameraConnection> connect_point_in_medium(const Scene& scene, const Vec3& p,
                                                        float time, const Medium& medium,
                                                        const Vec2& u_lens, uint64_t& rays,
                                                        Rng* rng, Towards&& towards) {
    const std::optional<CameraWiSample> lens = sample_lens(scene, p, u_lens, time);
    if (!lens) return std::nullopt;
    const Spectrum leaving = towards(lens->wi);
    if (leaving.is_black()) return std::nullopt;
    ++rays;
    const Spectrum visible =
        transmittance(scene, Scene::ShadowRay{p, lens->p_lens - p, time}, &medium, rng);
    if (visible.is_black()) return std::nullopt;
    return CameraConnection{*lens, leaving * (1.0f / lens->pdf) * lens->We * visible};
}

}  // namespace

void check_camera_motion_joinable(const Scene& scene, const std::string& integrator,
                                  const std::string& where) {
    const Camera& camera = scene.camera();
    if (!camera.is_moving() || camera.motion_is_rigid()) return;
    throw Error(
        fmt::format("{}: integrator '{}' joins light paths to a moving camera, whose "
                    "motion keys may only turn and move it (these scale or shear it); "
                    "use path or sppm",
                    where, integrator));
}

std::optional<CameraConnection> connect_surface_to_camera(const Scene& scene,
                                                          const SurfaceInteraction& si,
                                                          const Bsdf& bsdf, const Spectrum& beta,
                                                          const Vec2& u_lens, uint64_t& rays,
                                                          const Medium* medium, Rng* rng) {
    const std::optional<CameraWiSample> lens = sample_lens(scene, si.p, u_lens, si.time);
    if (!lens) return std::nullopt;
    const Vec3 wi_local = si.to_local(lens->wi);
    // Importance mode: wo is where the particle came from, wi where it goes (the camera).
    const Spectrum f =
        bsdf.eval(si.to_local(si.wo), wi_local, TransportMode::kImportance, si.to_local(si.ng));
    if (f.is_black()) return std::nullopt;
    ++rays;
    const Spectrum visible =
        transmittance(scene, si, lens->p_lens, medium_beyond(si, lens->wi, medium), rng);
    if (visible.is_black()) return std::nullopt;
    return CameraConnection{*lens,
                            beta * f * (abs_cos_theta(wi_local) / lens->pdf) * lens->We * visible};
}

std::optional<CameraConnection> connect_light_point_to_camera(
    const Scene& scene, const Light& light, const Vec3& p, const Vec3& n, float time,
    float pdf_origin, const Vec2& u_lens, uint64_t& rays, const Medium* medium, Rng* rng) {
    const std::optional<CameraWiSample> lens = sample_lens(scene, p, u_lens, time);
    if (!lens) return std::nullopt;
    const float cosine = glm::dot(n, lens->wi);
    if (!(cosine > 0.0f)) return std::nullopt;
    const Spectrum Le = light.emitted(p, n, lens->wi);
    if (Le.is_black()) return std::nullopt;
    const float side_pdf = light.emitted(p, n, -n).is_black() ? 1.0f : 0.5f;
    ++rays;
    const Spectrum visible =
        transmittance(scene, Scene::ShadowRay{p, lens->p_lens - p, time}, medium, rng);
    if (visible.is_black()) return std::nullopt;
    // p was chosen with density pdf_origin per area and the lens point with lens->pdf per
    // solid angle at p: Le |cos| We / (pdf_origin side_pdf pdf).
    return CameraConnection{
        *lens, Le * lens->We * (cosine / (pdf_origin * side_pdf * lens->pdf)) * visible};
}

std::optional<CameraConnection> connect_medium_point_to_camera(
    const Scene& scene, const Vec3& p, const Vec3& wi_arrival, float time, const Medium& medium,
    const Spectrum& beta, const Vec2& u_lens, uint64_t& rays, Rng* rng) {
    // The phase function's arguments point away from p: where the light came from
    // (-wi_arrival) and where it goes (the lens).
    const HenyeyGreenstein phase(medium.phase_asymmetry());
    return connect_point_in_medium(
        scene, p, time, medium, u_lens, rays, rng,
        [&](const Vec3& to_lens) { return beta * phase.eval(-wi_arrival, to_lens); });
}

std::optional<CameraConnection> connect_glowing_point_to_camera(const Scene& scene, const Vec3& p,
                                                                float time, const Medium& medium,
                                                                const Spectrum& source,
                                                                const Vec2& u_lens, uint64_t& rays,
                                                                Rng* rng) {
    // Emission in a medium is the same in every direction.
    return connect_point_in_medium(scene, p, time, medium, u_lens, rays, rng,
                                   [&](const Vec3&) { return source; });
}

}  // namespace glint
