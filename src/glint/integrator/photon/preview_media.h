#pragma once
// The preview in participating media (issue 29): volumetric caustics in real time.
//
// The light a camera ray gathers on its way through a medium that scatters has two parts
// here, and the preview estimates each its own way:
//
//   light that reached the medium point straight from a light (single scattering): one
//   point per medium segment of the camera path, with a light sample and its shadow ray
//   (PreviewIntegrator::camera_sample_in_media);
//   light that reached it through mirrors and glass (the volumetric caustic, L S+ M): the
//   volume photons, caustic photons that scattered in a medium, gathered along the camera
//   ray by the beam radiance estimate (Jarosz et al. 2008): each photon within the radius r
//   of the ray adds its power times the phase function towards the camera, the
//   transmittance from the lens to it and the 2D kernel 1 / (pi r^2).
//
// The photons are kept in world space (they survive a camera move) and the radius shrinks
// from pass to pass as the surface caustics' does. Each pass they are seen from the camera
// anew: projected onto the film and binned by the tiles of pixels their footprint covers,
// each with its transmittance from the lens (a shadow ray through the media and interfaces,
// 0 when something blocks it). A pixel then reads only its tile's photons. Multiple
// scattering in media is left out (the preview is an approximation; volpath has it).
//
// A medium that emits glows along every segment of the camera path through it (the
// transmittance times sigma_a Le, in closed form: only homogeneous media emit); its light
// does not reach surfaces or other media (no light path starts in a medium).
#include <glint/core/ray.h>
#include <glint/core/spectrum.h>

#include <cstdint>
#include <vector>

namespace glint {

class Scene;
class Medium;

/// A caustic photon that scattered in a medium: where, from where (unit, back towards the
/// light), the power it carries (per emitted photon of its batch), the asymmetry of the
/// medium's phase function there and its batch.
struct VolumePhoton {
    Vec3 p{0.0f};
    Vec3 wi{0.0f};
    Spectrum power{0.0f};
    float g = 0.0f;
    int set = 0;
};

/// The volume photons of one pass as the camera sees them: binned by tiles of the film.
class VolumePhotonView {
public:
    /// Pixels per tile side. A photon's footprint is about 20 pixels wide at 640 x 480: tiles
    /// of 8 test a quarter fewer photons per pixel than tiles of 16 (the whole frame 1 %
    /// fewer instructions), for more bin entries; 4 gains 0.3 % more.
    static constexpr int kTile = 8;

    /// Sees `batches` (each an estimate on its own; in spectral mode only the photons of set
    /// `only_set` are read, else every set: pass -1) from the camera of `scene`, which sits
    /// in `camera_medium`, for the film window at `origin` of `size` pixels, with kernel
    /// radius sqrt(radius2). In spectral mode `wavelengths` are the photons' (the lens
    /// transmittance is taken at them); nullptr in RGB mode.
    void build(const Scene& scene, const Medium* camera_medium,
               const std::vector<std::vector<VolumePhoton>>& batches, int only_set, float radius2,
               Vec2i origin, Vec2i size, const WavelengthContext* wavelengths);

    /// The beam radiance estimate along the ray from `origin` (the lens) along `direction`
    /// (unit) up to t_end, the distance to the first surface that is not an interface: the
    /// photons of `pixel`'s tile within the radius of the ray.
    Spectrum estimate(Vec2i pixel, const Vec3& origin, const Vec3& direction, float t_end) const;

    /// Photons the camera sees this pass (transmittance above zero, on the film).
    size_t size() const { return m_photons.size(); }
    bool empty() const { return m_photons.empty(); }

private:
    // A photon as the camera sees it: its power times the transmittance from the lens and
    // the kernel's 1 / (pi r^2 batches).
    struct Seen {
        Vec3 p;
        Vec3 wi;
        Spectrum power;
        float g;
    };
    std::vector<Seen> m_photons;
    std::vector<uint32_t> m_bin_start;  // tile t's photons: m_bin_photons[start[t], start[t+1])
    std::vector<uint32_t> m_bin_photons;
    // Each bin entry's photon position, coordinate by coordinate (parallel to
    // m_bin_photons, padded by 3 so that four can always be loaded): a pixel tests four
    // photons against its ray at once, reading them in a row instead of through the index.
    std::vector<float> m_bin_x, m_bin_y, m_bin_z;
    Vec2i m_origin{0}, m_tiles{0};
    float m_radius2 = 0.0f;
};

}  // namespace glint
