#include <glint/film/film.h>

#include <glint/core/error.h>
#include <glint/core/memory.h>
#include <glint/core/parallel.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

Film::Film(int width, int height, bool with_aovs)
    : m_width(width), m_height(height), m_with_aovs(with_aovs) {
    if (width <= 0 || height <= 0) {
        throw Error(
            fmt::format("film size {}x{}; expected positive width and height", width, height));
    }
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    m_pixels.resize(count);
    if (with_aovs) m_aovs.resize(count);
}

uint64_t Film::memory_bytes(int width, int height, bool with_aovs, bool with_halves) {
    const uint64_t pixels = saturating_product(static_cast<uint64_t>(std::max(width, 0)),
                                               static_cast<uint64_t>(std::max(height, 0)));
    const uint64_t channels = with_aovs ? 10 : 3;
    const uint64_t accumulators = sizeof(Pixel) + (with_aovs ? sizeof(AovPixel) : 0);
    // With halves: two more accumulators, and the denoiser's two half images, its
    // variance and feature buffers and its output (about four more images).
    const uint64_t per_pixel = accumulators * (with_halves ? 3 : 1) + 3 * sizeof(double) +
                               (with_halves ? 6 : 2) * channels * sizeof(float);
    return saturating_product(pixels, per_pixel);
}

Film::Film(int width, int height, bool with_aovs, Vec2i origin) : Film(width, height, with_aovs) {
    m_origin = origin;
}

Film::Film(int width, int height, bool with_aovs, Vec2i origin, bool with_halves)
    : Film(width, height, with_aovs, origin) {
    m_with_halves = with_halves;
    if (with_halves) {
        m_half_pixels.resize(2 * m_pixels.size());
        if (with_aovs) m_half_aovs.resize(2 * m_pixels.size());
    }
}

Film Film::window(Vec2i origin, int width, int height) const {
    const Vec2i offset = origin - m_origin;
    if (offset.x < 0 || offset.y < 0 || width < 1 || height < 1 || offset.x + width > m_width ||
        offset.y + height > m_height) {
        throw Error(fmt::format("film: window {}x{} at ({}, {}) outside the {}x{} film at ({}, {})",
                                width, height, origin.x, origin.y, m_width, m_height, m_origin.x,
                                m_origin.y));
    }
    Film result(width, height, m_with_aovs, origin, m_with_halves);
    result.m_splat_scale = m_splat_scale;
    if (!m_splats.empty()) result.m_splats.assign(3 * result.m_pixels.size(), 0.0);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t from = static_cast<std::size_t>(y + offset.y) * m_width +
                                     static_cast<std::size_t>(x + offset.x);
            const std::size_t to =
                static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
            result.m_pixels[to] = m_pixels[from];
            if (m_with_aovs) result.m_aovs[to] = m_aovs[from];
            for (std::size_t h = 0; h < 2 && m_with_halves; ++h) {
                result.m_half_pixels[2 * to + h] = m_half_pixels[2 * from + h];
                if (m_with_aovs) result.m_half_aovs[2 * to + h] = m_half_aovs[2 * from + h];
            }
            if (!m_splats.empty()) {
                for (int c = 0; c < 3; ++c) result.m_splats[3 * to + c] = m_splats[3 * from + c];
            }
        }
    }
    return result;
}

void Film::add_sample(Vec2i pixel, const Spectrum& L, float weight, const AovSample* aov,
                      int sample_index) {
    pixel -= m_origin;
    // A stray index would silently corrupt a neighbour's accumulator; the test is one
    // well-predicted branch per sample.
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= m_width || pixel.y >= m_height) {
        throw Error(fmt::format("film: pixel ({}, {}) outside the {}x{} film", pixel.x, pixel.y,
                                m_width, m_height));
    }
    const std::size_t i = static_cast<std::size_t>(pixel.y) * static_cast<std::size_t>(m_width) +
                          static_cast<std::size_t>(pixel.x);
    const std::size_t half = 2 * i + static_cast<std::size_t>(sample_index & 1);
    Pixel& p = m_pixels[i];
    const Rgb rgb = to_rgb(L);
    // The product of two floats is exact in double.
    const double terms[3] = {static_cast<double>(weight) * rgb[0],
                             static_cast<double>(weight) * rgb[1],
                             static_cast<double>(weight) * rgb[2]};
    if (L.is_finite() && FixedSum::accepts(weight) && FixedSum::accepts(terms[0]) &&
        FixedSum::accepts(terms[1]) && FixedSum::accepts(terms[2])) {
        // Dropping the weight too, not only the radiance, keeps one NaN path from
        // darkening the pixel: the mean is over the samples that could be measured.
        p.weight_sum.add(weight);
        for (int c = 0; c < 3; ++c) p.rgb[c].add(terms[c]);
        if (m_with_halves) {
            Pixel& h = m_half_pixels[half];
            h.weight_sum.add(weight);
            for (int c = 0; c < 3; ++c) h.rgb[c].add(terms[c]);
        }
    } else {
        ++p.non_finite;
    }

    if (!m_with_aovs || aov == nullptr) return;
    accumulate_aov(m_aovs[i], weight, *aov);
    if (m_with_halves) accumulate_aov(m_half_aovs[half], weight, *aov);
}

void Film::accumulate_aov(AovPixel& a, float weight, const AovSample& aov) {
    const double w = std::abs(weight);
    const Rgb albedo = to_rgb(aov.albedo);
    const double terms[7] = {w * albedo[0],     w * albedo[1],     w * albedo[2], w * aov.normal[0],
                             w * aov.normal[1], w * aov.normal[2], w * aov.depth};
    if (!FixedSum::accepts(w)) return;
    for (double term : terms) {
        if (!FixedSum::accepts(term)) return;  // NaN fails too
    }
    a.weight_sum.add(w);
    for (int c = 0; c < 3; ++c) {
        a.albedo[c].add(terms[c]);
        a.normal[c].add(terms[3 + c]);
    }
    a.depth.add(terms[6]);
}

void Film::add_splats(std::span<const Splat> splats) {
    for (const Splat& splat : splats) {
        if (!splat.rgb.is_finite() || !std::isfinite(splat.film.x) ||
            !std::isfinite(splat.film.y)) {
            ++m_non_finite_splats;
            continue;
        }
        const float fx = std::floor(splat.film.x) - static_cast<float>(m_origin.x),
                    fy = std::floor(splat.film.y) - static_cast<float>(m_origin.y);
        // Compared as floats first: a position far outside would overflow an int.
        if (fx < 0.0f || fy < 0.0f || fx >= static_cast<float>(m_width) ||
            fy >= static_cast<float>(m_height)) {
            continue;
        }
        if (m_splats.empty()) m_splats.assign(3 * m_pixels.size(), 0.0);
        const std::size_t i = static_cast<std::size_t>(fy) * static_cast<std::size_t>(m_width) +
                              static_cast<std::size_t>(fx);
        const Rgb& rgb = splat.rgb;
        for (int c = 0; c < 3; ++c) m_splats[3 * i + c] += static_cast<double>(rgb[c]);
    }
}

Image Film::resolve() const {
    return resolve_pixels(m_pixels.data(), 1, m_with_aovs ? m_aovs.data() : nullptr, 1, true);
}

Image Film::resolve_half(int half) const {
    if (!m_with_halves || half < 0 || half > 1)
        throw Error(fmt::format("film: no half {} (the film keeps no halves)", half));
    const std::size_t h = static_cast<std::size_t>(half);
    return resolve_pixels(m_half_pixels.data() + h, 2,
                          m_with_aovs ? m_half_aovs.data() + h : nullptr, 2, false);
}

Image Film::resolve_pixels(const Pixel* pixels, std::size_t pixel_stride, const AovPixel* aovs,
                           std::size_t aov_stride, bool with_splats) const {
    std::vector<std::string> channels = {"R", "G", "B"};
    if (m_with_aovs) {
        channels.insert(channels.end(), {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y",
                                         "normal.Z", "depth.Z"});
    }
    Image image = make_image(m_width, m_height, std::move(channels));
    auto resolve_pixel = [&](int x, int y) {
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) +
                              static_cast<std::size_t>(x);
        const Pixel& p = pixels[i * pixel_stride];
        // Mitchell's negative lobes can cancel the positive weights exactly; such a pixel has
        // no defined mean and resolves to black rather than infinity.
        const double weight_sum = p.weight_sum.value();
        const double inv = weight_sum != 0.0 ? 1.0 / weight_sum : 0.0;
        for (int c = 0; c < 3; ++c) {
            double value = p.rgb[c].value() * inv;
            if (with_splats && !m_splats.empty()) value += m_splat_scale * m_splats[3 * i + c];
            image.at(x, y, c) = static_cast<float>(value);
        }
        if (!m_with_aovs) return;
        const AovPixel& a = aovs[i * aov_stride];
        const double aov_weight = a.weight_sum.value();
        const double ainv = aov_weight > 0.0 ? 1.0 / aov_weight : 0.0;
        for (int c = 0; c < 3; ++c) {
            image.at(x, y, 3 + c) = static_cast<float>(a.albedo[c].value() * ainv);
            image.at(x, y, 6 + c) = static_cast<float>(a.normal[c].value() * ainv);
        }
        image.at(x, y, 9) = static_cast<float>(a.depth.value() * ainv);
    };
    // Rows in parallel: each pixel's value is its own, so the bits do not depend on the
    // threads (the viewer resolves a film after every pass).
    parallel_for_rows(m_height, [&](int y) {
        for (int x = 0; x < m_width; ++x) resolve_pixel(x, y);
    });
    return image;
}

uint64_t Film::non_finite_samples() const {
    uint64_t total = 0;
    for (const Pixel& p : m_pixels) total += p.non_finite;
    return total + m_non_finite_splats;
}

namespace {
// Every element of `values` set to T{}, in parallel (a 640x480 film with AOVs holds 64 MB of
// accumulators, and the viewer clears it on every camera move).
template <typename T>
void clear_in_parallel(std::vector<T>& values) {
    parallel_for_indices(values.size(), [&](std::size_t i) { values[i] = T{}; });
}
}  // namespace

void Film::clear() {
    clear_in_parallel(m_pixels);
    clear_in_parallel(m_aovs);
    clear_in_parallel(m_half_pixels);
    clear_in_parallel(m_half_aovs);
    m_splats.clear();
    m_non_finite_splats = 0;
}

}  // namespace glint
