#include <glint/film/filter.h>

#include <glint/core/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// 64 bins per pixel of support is well below a pixel's sampling resolution, and each bin
// is averaged over several points so the step function keeps the filter's integral.
constexpr float kBinsPerPixel = 64.0f;
constexpr int kMaxBins = 4096;
constexpr int kPointsPerBin = 8;

void check_radius(const char* filter, float radius) {
    if (!(std::isfinite(radius) && radius > 0.0f)) {
        throw Error(fmt::format("{} filter: radius is {}; expected a finite value > 0 pixels",
                                filter, radius));
    }
}

class BoxFilter final : public Filter {
public:
    explicit BoxFilter(float radius) : Filter(Vec2(radius)) {}

    float eval(Vec2 offset) const override {
        const Vec2 r = radius();
        return std::abs(offset.x) <= r.x && std::abs(offset.y) <= r.y ? 1.0f : 0.0f;
    }
};

class GaussianFilter final : public Filter {
public:
    GaussianFilter(float radius, float sigma)
        : Filter(Vec2(radius)), m_sigma(sigma), m_floor(gaussian(radius, sigma)) {
        const auto axis = [this](float x) { return eval_1d(x); };
        tabulate_separable(axis, axis);
    }

    float eval(Vec2 offset) const override { return eval_1d(offset.x) * eval_1d(offset.y); }

private:
    static float gaussian(float x, float sigma) {
        return std::exp(-(x * x) / (2.0f * sigma * sigma));
    }
    float eval_1d(float x) const {
        if (std::abs(x) > radius().x) return 0.0f;
        return std::max(0.0f, gaussian(x, m_sigma) - m_floor);
    }

    float m_sigma;
    float m_floor;  // value at the radius, subtracted so the filter is continuous there
};

class MitchellFilter final : public Filter {
public:
    MitchellFilter(float radius, float b, float c) : Filter(Vec2(radius)), m_b(b), m_c(c) {
        const auto axis = [this](float x) { return eval_1d(x); };
        tabulate_separable(axis, axis);
    }

    float eval(Vec2 offset) const override { return eval_1d(offset.x) * eval_1d(offset.y); }

private:
    // The cubic is defined on [-2, 2]; the piecewise polynomial is Mitchell and Netravali
    // (1988), eq. 8, written here in Horner form.
    float eval_1d(float x) const {
        const float t = std::abs(2.0f * x / radius().x);
        const float b = m_b, c = m_c;
        float v = 0.0f;
        if (t < 1.0f) {
            v = ((12.0f - 9.0f * b - 6.0f * c) * t + (-18.0f + 12.0f * b + 6.0f * c)) * t * t +
                (6.0f - 2.0f * b);
        } else if (t < 2.0f) {
            v = (((-b - 6.0f * c) * t + (6.0f * b + 30.0f * c)) * t + (-12.0f * b - 48.0f * c)) *
                    t +
                (8.0f * b + 24.0f * c);
        }
        return v / 6.0f;
    }

    float m_b, m_c;
};

}  // namespace

Filter::Filter(Vec2 radius) : m_radius(radius) {}

Filter::Axis Filter::tabulate_axis(const std::function<float(float)>& f, float radius) {
    const int bins =
        std::clamp(static_cast<int>(std::ceil(2.0f * radius * kBinsPerPixel)), 2, kMaxBins);
    const double width = 2.0 * radius / bins;
    std::vector<float> magnitude(bins);
    std::vector<float> sign(bins);
    double abs_integral = 0.0;
    for (int i = 0; i < bins; ++i) {
        // Midpoint rule inside the bin: the signed mean decides the lobe's sign, and its
        // magnitude is what the sampler draws from.
        double mean = 0.0;
        for (int k = 0; k < kPointsPerBin; ++k) {
            const double x = -radius + (i + (k + 0.5) / kPointsPerBin) * width;
            mean += f(static_cast<float>(x));
        }
        mean /= kPointsPerBin;
        magnitude[i] = static_cast<float>(std::abs(mean));
        sign[i] = mean < 0.0 ? -1.0f : 1.0f;
        abs_integral += std::abs(mean) * width;
    }
    return {Distribution1D(std::move(magnitude)), std::move(sign),
            static_cast<float>(abs_integral)};
}

void Filter::tabulate_separable(const std::function<float(float)>& fx,
                                const std::function<float(float)>& fy) {
    m_axes = std::array<Axis, 2>{tabulate_axis(fx, m_radius.x), tabulate_axis(fy, m_radius.y)};
}

FilterSample Filter::sample(Vec2 u) const {
    if (!m_axes) return {(2.0f * u - Vec2(1.0f)) * m_radius, 1.0f};
    // Each axis is sampled from its own |f|, so the joint density is |fx| |fy| / (Ix Iy)
    // and f / pdf collapses to the signs times the integrals: a constant magnitude.
    Vec2 offset;
    float weight = 1.0f;
    for (int a = 0; a < 2; ++a) {
        const Axis& axis = (*m_axes)[a];
        const Distribution1D::ContinuousSample s = axis.distribution.sample_continuous(u[a]);
        offset[a] = (2.0f * s.x - 1.0f) * m_radius[a];
        weight *= axis.sign[s.index] * axis.abs_integral;
    }
    return {offset, weight};
}

std::unique_ptr<Filter> make_box_filter(float radius) {
    check_radius("box", radius);
    return std::make_unique<BoxFilter>(radius);
}

std::unique_ptr<Filter> make_gaussian_filter(float radius, float sigma) {
    check_radius("gaussian", radius);
    if (!(std::isfinite(sigma) && sigma > 0.0f)) {
        throw Error(
            fmt::format("gaussian filter: sigma is {}; expected a finite value > 0 pixels", sigma));
    }
    return std::make_unique<GaussianFilter>(radius, sigma);
}

std::unique_ptr<Filter> make_mitchell_filter(float radius, float b, float c) {
    check_radius("mitchell", radius);
    if (!(std::isfinite(b) && std::isfinite(c))) {
        throw Error(fmt::format("mitchell filter: B = {}, C = {}; expected finite values", b, c));
    }
    return std::make_unique<MitchellFilter>(radius, b, c);
}

std::unique_ptr<Filter> make_filter(const std::string& name, float radius) {
    // NaN and infinity fall through to the factories, which reject them by name.
    const bool use_default = radius <= 0.0f;
    if (name == "box") return use_default ? make_box_filter() : make_box_filter(radius);
    if (name == "gaussian") {
        return use_default ? make_gaussian_filter() : make_gaussian_filter(radius);
    }
    if (name == "mitchell") {
        return use_default ? make_mitchell_filter() : make_mitchell_filter(radius);
    }
    throw Error(
        fmt::format("unknown pixel filter '{}'; expected one of: box, gaussian, mitchell", name));
}

}  // namespace glint
