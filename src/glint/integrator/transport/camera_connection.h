#pragma once
// Connecting a light path to the camera (Veach's t = 1 strategies): a point on the lens
// sampled from a vertex of the light path, a shadow ray, and the contribution splatted where
// the connection lands on the film. Light tracing and the bidirectional methods join light
// paths to the camera this way; they differ only in how they weight it (MIS, or not at all).
#include <glint/integrator/integrator.h>
#include <glint/scene/scene.h>

#include <optional>

namespace glint {

/// Light paths join a moving camera where it stands at their time; the densities of those
/// joins hold only while the camera turns and moves without scaling (Camera::motion_is_rigid).
/// Throws glint::Error naming `integrator` and the setting's place `where` otherwise.
void check_camera_motion_joinable(const Scene& scene, const std::string& integrator,
                                  const std::string& where);

/// A light path joined to the lens: the lens sample (film position, point, importance) and
/// the unweighted contribution it carries to the film.
struct CameraConnection {
    CameraWiSample lens;
    Spectrum L;
};

/// Each connection's shadow ray draws from `rng` in media without a closed form (the path's
/// own stream: see transmittance() in visibility.h for why not null there).
///
/// Connects a non-specular surface vertex of a light path to the lens with `u_lens`: `beta`
/// is the power the path carries to `si`, `bsdf` its BSDF (evaluated in importance mode,
/// from where the particle came, si.wo, to the lens). nullopt when the lens cannot see the
/// point or the shadow ray is blocked; the shadow ray is counted in `rays`. `medium` is the
/// medium the particle travelled through to `si` (null: vacuum); the shadow ray starts in
/// the medium on the lens's side of the surface and takes on the transmittance of its media.
std::optional<CameraConnection> connect_surface_to_camera(
    const Scene& scene, const SurfaceInteraction& si, const Bsdf& bsdf, const Spectrum& beta,
    const Vec2& u_lens, uint64_t& rays, const Medium* medium = nullptr, Rng* rng = nullptr);

/// Connects a scattering point `p` of a light path inside `medium` to the lens with
/// `u_lens`: `beta` is the power the path carries to p, arriving along `wi_arrival` (unit,
/// the direction it travelled), and the medium's Henyey–Greenstein phase function scatters
/// it towards the lens; `time` is the path's scene time. nullopt when the lens cannot see p or the
/// media and surfaces between let nothing through; the shadow ray is counted in `rays`.
std::optional<CameraConnection> connect_medium_point_to_camera(
    const Scene& scene, const Vec3& p, const Vec3& wi_arrival, float time, const Medium& medium,
    const Spectrum& beta, const Vec2& u_lens, uint64_t& rays, Rng* rng = nullptr);

/// Connects the starting point `p` of a light path in a glowing `medium` to the lens with
/// `u_lens`: `source` is what p emits per unit length towards any direction (sigma_a Le)
/// over the density p was chosen with. nullopt when the lens cannot see p or nothing gets
/// through; the shadow ray is counted in `rays`.
std::optional<CameraConnection> connect_glowing_point_to_camera(const Scene& scene, const Vec3& p,
                                                                float time, const Medium& medium,
                                                                const Spectrum& source,
                                                                const Vec2& u_lens, uint64_t& rays,
                                                                Rng* rng = nullptr);
/// Connects the starting point `p` of a light path on an emitting surface (normal `n`, the
/// side Light::sample_le chose) to the lens with `u_lens`. `pdf_origin` is the density the
/// path chose p with: the light's pmf times its area density. Only the chosen side can see
/// the lens without hitting the light itself; a two-sided light chooses each side half the
/// time, so the side facing the camera counts double. Points without a surface (point,
/// spot lights) and lights at infinity are for the caller to leave out: they are invisible
/// to the camera in every glint integrator. `time` is the path's scene time; `medium` the
/// medium around the light (null: vacuum).
std::optional<CameraConnection> connect_light_point_to_camera(
    const Scene& scene, const Light& light, const Vec3& p, const Vec3& n, float time,
    float pdf_origin, const Vec2& u_lens, uint64_t& rays, const Medium* medium = nullptr,
    Rng* rng = nullptr);

}  // namespace glint
