#pragma once
// The film accumulates weighted radiance samples per pixel and resolves them into an
// Image. Pixel filtering happens before the film, by filter importance sampling (see
// filter.h): a sample carries its filter weight and belongs to exactly one pixel.
#include <glint/core/spectrum.h>
#include <glint/film/fixed_sum.h>
#include <glint/film/image.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <span>
#include <vector>

namespace glint {

/// Features of the first visible surface, for denoisers. Misses should pass zeros.
struct AovSample {
    Spectrum albedo;
    Vec3 normal;  ///< world-space shading normal
    float depth;  ///< distance along the camera ray, in scene units
};

/// A light path's contribution to the film (light tracing, bidirectional methods).
struct Splat {
    Splat() = default;
    /// Turns L into the film's colour now, while the path's wavelengths are active (spectral
    /// mode): splats are merged later, after the path has ended.
    Splat(Vec2 film_position, const Spectrum& L) : film(film_position), rgb(to_rgb(L)) {}

    Vec2 film;  ///< film position in pixels (origin top-left, y down, as Camera::generate_ray)
    Rgb rgb;    ///< its contribution, before the film's splat scale
};

class Film {
public:
    /// Throws glint::Error unless width and height are positive.
    Film(int width, int height, bool with_aovs);
    /// A film for the window [origin, origin + (width, height)) of a larger image (a crop
    /// window): add_sample() and add_splats() take positions in the larger image's pixels,
    /// resolve() gives the window's pixels only.
    Film(int width, int height, bool with_aovs, Vec2i origin);
    /// A film that also keeps two half accumulators, for a denoiser (film/denoise.h): a
    /// sample with an even index goes to half 0, an odd one to half 1, besides the full
    /// mean, which stays exactly what a film without halves holds. The two halves are
    /// independent estimates of the same pixel, so their difference measures its noise.
    Film(int width, int height, bool with_aovs, Vec2i origin, bool with_halves);

    /// Bytes a film of this size holds at most: its accumulators, splat sums, and the
    /// resolved Image (floats, 3 or 10 channels) with one more image's worth for encoding
    /// and verifying the output. For checking a render against the memory budget before
    /// anything is allocated; saturates rather than wraps.
    static uint64_t memory_bytes(int width, int height, bool with_aovs, bool with_halves = false);

    int width() const { return m_width; }
    int height() const { return m_height; }
    /// The image pixel of the film's top-left pixel: (0, 0) unless it is a crop window.
    Vec2i origin() const { return m_origin; }
    /// A film for the sub-window [origin, origin + (width, height)) of this one (in image
    /// pixels, inside this film's window), holding exactly the samples this film holds
    /// there. Throws glint::Error for a window outside this film.
    Film window(Vec2i origin, int width, int height) const;
    bool has_aovs() const { return m_with_aovs; }
    bool has_halves() const { return m_with_halves; }

    /// Adds one sample to `pixel` ((0, 0) is the top-left pixel) with its filter weight
    /// (FilterSample::weight, possibly negative). Each pixel is only ever written by the
    /// thread that renders it (filter importance sampling keeps a sample inside its
    /// pixel), so there are no locks, and the result is bit-identical for any thread
    /// count as long as each pixel's samples arrive in the same order.
    /// A sample whose radiance or weight is not finite is dropped from the radiance
    /// mean and counted in non_finite_samples(); its finite AOVs still count.
    /// `aov` may be null; it is ignored when the film has no AOVs.
    /// `sample_index` (the sample's index within its pixel) chooses the half of a film with
    /// halves by its parity; integrators that do not pass it cannot feed a denoiser
    /// (Integrator::records_halves()).
    /// Throws glint::Error for a pixel outside the film.
    void add_sample(Vec2i pixel, const Spectrum& L, float weight, const AovSample* aov,
                    int sample_index = 0);

    /// Adds splats to the pixel containing each film position; splats outside the film are
    /// ignored. Not thread-safe: integrators gather splats per fixed chunk of work and add
    /// the chunks in chunk order, so the image is the same bit for bit for any thread
    /// count. Splats whose position or L is not finite are dropped and counted in
    /// non_finite_samples().
    void add_splats(std::span<const Splat> splats);
    /// Factor on every pixel's sum of splats in resolve() (1 until set); a light tracer sets
    /// it to pixel count / number of light paths.
    void set_splat_scale(double scale) { m_splat_scale = scale; }

    /// Weighted mean per pixel of add_sample's radiance plus the splat scale times the sum
    /// of the pixel's splats (exactly the mean when nothing was splatted): channels R, G, B
    /// and, with AOVs, albedo.R albedo.G
    /// albedo.B normal.X normal.Y normal.Z depth.Z. AOVs are averaged with |weight|.
    /// Pixels with zero total weight resolve to 0.
    Image resolve() const;
    /// The weighted mean of half `half` (0: even sample indices, 1: odd), with the same
    /// channels as resolve() but no splats. Throws glint::Error unless the film has halves.
    Image resolve_half(int half) const;

    /// Samples (and splats) dropped so far for non-finite radiance or weight, over all
    /// pixels.
    uint64_t non_finite_samples() const;
    /// Clears all accumulated samples and splats (not the splat scale).
    void clear();

    /// The film's exact sums (film_sums.cpp documents the channels), for a partial render
    /// that `glint merge` or the MPI ranks add up: with the resolved mean's R, G, B for a
    /// viewer. Throws glint::Error for a film with splats or halves, which partial renders
    /// do not carry.
    Image sums_image() const;
    /// Adds the sums of `sums` (from sums_image() of a film of the same size, with or without
    /// AOVs as this one) to this film's: the film then holds both renders' samples, exactly
    /// as one film given all of them. Throws glint::Error naming what does not match.
    void add_sums_image(const Image& sums);

private:
    // Exact sums (fixed_sum.h): the same samples give the same bits in any order and
    // any split into sample ranges.
    struct Pixel {
        FixedSum weight_sum;
        FixedSum rgb[3];
        uint32_t non_finite = 0;
    };
    struct AovPixel {
        FixedSum weight_sum;
        FixedSum albedo[3];
        FixedSum normal[3];
        FixedSum depth;
    };

    static void accumulate_aov(AovPixel& a, float weight, const AovSample& aov);
    Image resolve_pixels(const Pixel* pixels, std::size_t pixel_stride, const AovPixel* aovs,
                         std::size_t aov_stride, bool with_splats) const;

    int m_width, m_height;
    bool m_with_aovs;
    bool m_with_halves = false;
    Vec2i m_origin{0, 0};
    std::vector<Pixel> m_pixels;
    std::vector<AovPixel> m_aovs;  // empty without AOVs
    // Halves: two radiance accumulators (and, with AOVs, two AOV accumulators) per pixel,
    // interleaved [pixel][half]; empty without halves.
    std::vector<Pixel> m_half_pixels;
    std::vector<AovPixel> m_half_aovs;
    // Sums of splats, three per pixel; empty until the first splat, so films without any
    // cost nothing and resolve exactly as before.
    std::vector<double> m_splats;
    double m_splat_scale = 1.0;
    uint64_t m_non_finite_splats = 0;
};

}  // namespace glint
