#include <glint/integrator/transport/media.h>
#include <glint/scene/scene.h>

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

}  // namespace glint
