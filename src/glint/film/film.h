#pragma once
// The film accumulates weighted radiance samples per pixel and resolves them into an
// Image. Pixel filtering happens before the film, by filter importance sampling (see
// filter.h): a sample carries its filter weight and belongs to exactly one pixel.
#include <glint/core/spectrum.h>
#include <glint/film/image.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <vector>

namespace glint {

/// Features of the first visible surface, for denoisers. Misses should pass zeros.
struct AovSample {
    Spectrum albedo;
    Vec3 normal;  ///< world-space shading normal
    float depth;  ///< distance along the camera ray, in scene units
};

class Film {
public:
    /// Throws glint::Error unless width and height are positive.
    Film(int width, int height, bool with_aovs);

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool has_aovs() const { return m_with_aovs; }

    /// Adds one sample to `pixel` ((0, 0) is the top-left pixel) with its filter weight
    /// (FilterSample::weight, possibly negative). Each pixel is only ever written by the
    /// thread that renders it (filter importance sampling keeps a sample inside its
    /// pixel), so there are no locks, and the result is bit-identical for any thread
    /// count as long as each pixel's samples arrive in the same order.
    /// A sample whose radiance or weight is not finite is dropped from the radiance
    /// mean and counted in non_finite_samples(); its finite AOVs still count.
    /// `aov` may be null; it is ignored when the film has no AOVs.
    /// Throws glint::Error for a pixel outside the film.
    void add_sample(Vec2i pixel, const Spectrum& L, float weight, const AovSample* aov);

    /// Weighted mean per pixel: channels R, G, B and, with AOVs, albedo.R albedo.G
    /// albedo.B normal.X normal.Y normal.Z depth.Z. AOVs are averaged with |weight|.
    /// Pixels with zero total weight resolve to 0.
    Image resolve() const;

    /// Samples dropped so far for non-finite radiance or weight, over all pixels.
    uint64_t non_finite_samples() const;
    /// Clears all accumulated samples.
    void clear();

private:
    struct Pixel {
        double weight_sum = 0.0;
        double rgb[3] = {0.0, 0.0, 0.0};
        uint32_t non_finite = 0;
    };
    struct AovPixel {
        double weight_sum = 0.0;
        double albedo[3] = {0.0, 0.0, 0.0};
        double normal[3] = {0.0, 0.0, 0.0};
        double depth = 0.0;
    };

    int m_width, m_height;
    bool m_with_aovs;
    std::vector<Pixel> m_pixels;
    std::vector<AovPixel> m_aovs;  // empty without AOVs
};

}  // namespace glint
