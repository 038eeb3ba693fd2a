#pragma once
// Image-based lighting: radiance arriving from every direction, read from a
// latitude-longitude (equirectangular) image and importance sampled by luminance.
//
// The map's frame, before any rotation: +y is up. Map coordinates (u, v) in [0, 1)^2 run
// from the image's top-left corner, u across the columns and v down the rows.
//   - v gives the polar angle from the zenith, theta = pi v: the top row is the zenith
//     (+y), the bottom row the nadir (-y), the middle row the horizon.
//   - u gives the azimuth about +y, phi = 2 pi u, turning from +z through -x, -z and +x:
//     u = 0 (the left edge) looks along +z, u = 1/4 along -x, u = 1/2 (the centre
//     column) along -z, u = 3/4 along +x. Seen from inside, as a camera looking along
//     -z sees it, the image is the right way round (not mirrored) and centred ahead.
//   So direction(u, v) = (-sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)).
// A rotation of the map about +y by `rotation` degrees (right-handed: 90 turns -z to -x)
// then an optional further rotation place it in the world.
#include <glint/core/distribution.h>
#include <glint/core/params.h>
#include <glint/light/light.h>

#include <memory>
#include <string>
#include <vector>

namespace glint {

class EnvironmentLight final : public Light {
public:
    /// `radiance`: the map in linear RGB (W sr^-1 m^-2), `width` x `height` pixels, row
    /// after row from the top, finite and non-negative. `to_world`: the rotation from the
    /// map's frame to the world (orthonormal, determinant +1).
    EnvironmentLight(std::vector<Spectrum> radiance, int width, int height, const Mat3& to_world);

    void preprocess(const Vec3& scene_center, float scene_radius) override;
    /// A direction drawn in proportion to luminance; the shadow-ray target lies beyond
    /// the scene's bounding sphere in that direction.
    std::optional<LightSample> sample_li(const Vec3& ref, const Vec2& u,
                                         float u_select) const override;
    /// Photons come from a point uniform on a disc of the scene's radius (pdf_pos
    /// 1 / (pi r^2)), outside the scene and facing it, travelling against a direction drawn
    /// like sample_li's (pdf_dir: sample_li's density of the direction towards the sky).
    std::optional<LightEmission> sample_le(const Vec2& u_position, const Vec2& u_direction,
                                           float u_select) const override;
    EmissionPdf pdf_le(const Ray& ray, const Vec3& n) const override;
    /// The radiance arriving from -w, whatever the point.
    Spectrum emitted(const Vec3&, const Vec3&, const Vec3& w) const override {
        return le_escaped(-w);
    }
    /// pi r^2 times the radiance integrated over the sphere (r: the scene's radius): the
    /// power that crosses the scene's bounding sphere.
    Spectrum power() const override;
    bool is_delta() const override { return false; }
    bool is_infinite() const override { return true; }
    Spectrum le_escaped(const Vec3& direction) const override;
    float pdf_li_escaped(const Vec3& direction) const override;

    /// Bilinear lookup at map coordinates (wrapping in u, clamped in v).
    Spectrum lookup(const Vec2& uv) const;
    /// Unit world direction of map coordinates, and back (see the mapping above).
    Vec3 direction_of(const Vec2& uv) const;
    Vec2 uv_of(const Vec3& world_direction) const;

private:
    const Spectrum& pixel(int x, int y) const { return m_pixels[y * m_width + x]; }
    // Map coordinates of a unit direction in the map's frame.
    static Vec2 uv_in_map(const Vec3& d);
    std::vector<float> sampling_weights() const;
    // A direction drawn in proportion to the sampling weights: a pixel from the 2D
    // distribution, then a point uniform in solid angle inside it (uniform in phi and in
    // cos(theta)), so the density is constant over each pixel and has no 1/sin(theta)
    // peak at the poles.
    struct DirectionSample {
        Vec2 uv;  // map coordinates, for lookup()
        Vec3 direction;
        float pdf = 0.0f;  // per unit solid angle
    };
    DirectionSample sample_direction(const Vec2& u) const;
    // Solid-angle density of sample_direction at map coordinates `uv`.
    float direction_pdf(const Vec2& uv) const;

    std::vector<Spectrum> m_pixels;
    int m_width;
    int m_height;
    Mat3 m_to_world;
    Mat3 m_to_map;
    Distribution2D m_distribution;
    Spectrum m_radiance_integral;  // radiance integrated over the sphere of directions
    Vec3 m_center{0.0f};
    float m_radius = 1.0f;
};

/// Reads and checks `glint.environment{...}` (parameters documented at the definition);
/// relative file names start at `directory`.
std::unique_ptr<Light> make_environment_light(const Params& params, const std::string& directory);

}  // namespace glint
