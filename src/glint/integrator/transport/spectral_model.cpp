#include <glint/integrator/transport/spectral_model.h>
#include <glint/spectral/cie.h>
#include <glint/spectral/illuminants.h>
#include <glint/spectral/rgb_uplift.h>

#include <array>
#include <bit>
#include <cmath>

namespace glint {

namespace {

using Values = SpectralModel::Values;

// D65 at luminance 1: the shape of an illuminant Rgb's spectrum (rgb_uplift.h).
float d65(float nm) {
    static const spectral::TabulatedSpectrum* const table = spectral::named_illuminant("D65");
    return table->eval(nm);
}

// What a colour stands for in a role, found once: scale · S(polynomial(λ)), times D65 for
// an illuminant (the roles of spectral::uplifted_rgb).
struct UpliftedColour {
    spectral::SigmoidPolynomial polynomial;
    float scale = 0.0f;
};

UpliftedColour find_uplift(const Rgb& rgb, RgbRole role) {
    if (role == RgbRole::reflectance) return {spectral::uplift_coefficients(rgb), 1.0f};
    // A scale times a spectrum in [0, 1] whose brightest channel is ½.
    const float scale = 2.0f * std::max(rgb.max_value(), 0.0f);
    if (!(scale > 0.0f)) return {};
    return {spectral::uplift_coefficients(rgb / scale), scale};
}

// Finding a colour's polynomial takes a table lookup and Gauss–Newton steps (about a
// microsecond); a path reads the same few colours (its materials' constants, its lights) at
// every bounce. A small direct-mapped cache per thread keeps them; a texture's many texels
// replace each other in it.
struct UpliftCache {
    static constexpr int kSize = 256;
    struct Entry {
        Rgb rgb{-1.0f};
        RgbRole role = RgbRole::reflectance;
        UpliftedColour colour;
    };
    std::array<Entry, kSize> entries;

    const UpliftedColour& get(const Rgb& rgb, RgbRole role) {
        uint32_t h = std::bit_cast<uint32_t>(rgb.r) * 0x9e3779b1u;
        h ^= std::bit_cast<uint32_t>(rgb.g) * 0x85ebca77u;
        h ^= std::bit_cast<uint32_t>(rgb.b) * 0xc2b2ae3du;
        h ^= static_cast<uint32_t>(role) * 0x27d4eb2fu;
        Entry& e = entries[(h ^ (h >> 15)) % kSize];
        if (!(e.rgb == rgb) || e.role != role) {
            e.rgb = rgb;
            e.role = role;
            e.colour = find_uplift(rgb, role);
        }
        return e.colour;
    }
};

Values uplift_values(const Rgb& rgb, RgbRole role, const Values& nm) {
    thread_local UpliftCache cache;
    const UpliftedColour& c = cache.get(rgb, role);
    Values v{};
    if (c.scale == 0.0f) return v;
    for (size_t i = 0; i < v.size(); ++i) {
        v[i] = c.scale * c.polynomial.eval(nm[i]);
        if (role == RgbRole::illuminant) v[i] *= d65(nm[i]);
    }
    return v;
}

Rgb observer_rec709(double nm) {
    return spectral::xyz_to_rec709(spectral::cie_xyz(nm));
}

// ∫ observer(λ) · white(λ) dλ per channel, for the white emitter (1, 1, 1): the film divides
// by it so that white light is exactly (1, 1, 1). Midpoint rule at 0.05 nm, finer than the
// tables' 5 nm steps between which everything is linear.
std::array<double, 3> white_response() {
    constexpr double step = 0.05;
    std::array<double, 3> sum{};
    for (double nm = 360.0 + 0.5 * step; nm < 830.0; nm += step) {
        const Rgb o = observer_rec709(nm);
        // The white emitter's spectrum is D65 itself (a constant ½ scaled by 2, times D65).
        const double w = d65(static_cast<float>(nm)) * step;
        for (int c = 0; c < 3; ++c) sum[c] += w * o[c];
    }
    return sum;
}

Rgb observer(float nm) {
    static const std::array<double, 3> white = white_response();
    const Rgb o = observer_rec709(nm);
    return {static_cast<float>(o.r / white[0]), static_cast<float>(o.g / white[1]),
            static_cast<float>(o.b / white[2])};
}

uint64_t mix(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// A uniform number in [0, 1) from `key`; a salt keeps this draw apart from every other use
// of the same key.
float key_to_unit(uint64_t key) {
    const uint64_t bits = mix(key ^ 0x5eec7a1c0ffee123ULL);
    return static_cast<float>(bits >> 40) * 0x1p-24f;
}

}  // namespace

const SpectralModel& spectral_model() {
    static const SpectralModel model{&uplift_values, &observer};
    return model;
}

WavelengthContext path_wavelengths(uint64_t key) {
    return {SampledWavelengths::sample_visible(key_to_unit(key)), &spectral_model()};
}

WavelengthContext wavelengths_at(float u) {
    return {SampledWavelengths::sample_visible(u), &spectral_model()};
}

WavelengthContext pass_wavelengths(uint64_t key, uint32_t index) {
    // Van der Corput: the bits of the index mirrored about the binary point.
    uint32_t bits = index;
    bits = (bits << 16) | (bits >> 16);
    bits = ((bits & 0x00ff00ffu) << 8) | ((bits & 0xff00ff00u) >> 8);
    bits = ((bits & 0x0f0f0f0fu) << 4) | ((bits & 0xf0f0f0f0u) >> 4);
    bits = ((bits & 0x33333333u) << 2) | ((bits & 0xccccccccu) >> 2);
    bits = ((bits & 0x55555555u) << 1) | ((bits & 0xaaaaaaaau) >> 1);
    const float radical_inverse = static_cast<float>(bits >> 8) * 0x1p-24f;
    float u = key_to_unit(key) + radical_inverse;
    if (u >= 1.0f) u -= 1.0f;
    return {SampledWavelengths::sample_visible(u), &spectral_model()};
}

}  // namespace glint
