#include <glint/core/distribution.h>

#include <glint/core/error.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint {

namespace {

// Keeps u in [0, 1) (kOneMinusEpsilon) so that the last non-empty bin is the furthest a
// sample can reach, even when callers pass exactly 1.
float clamp_unit(float u) {
    // NaN compares false with everything, so it ends at 0 rather than poisoning indices.
    if (!(u > 0.0f)) return 0.0f;
    return std::min(u, kOneMinusEpsilon);
}

}  // namespace

Distribution1D::Distribution1D(std::vector<float> values) : m_func(std::move(values)) {
    if (m_func.empty()) throw Error("Distribution1D: needs at least one value");
    const std::size_t n = m_func.size();
    // Sum in double: light selection can have thousands of emitters of very different power.
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const float v = m_func[i];
        if (!std::isfinite(v) || v < 0.0f) {
            throw Error("Distribution1D: value " + std::to_string(i) + " is " + std::to_string(v) +
                        "; expected a finite value >= 0");
        }
        sum += v;
    }
    m_sum = static_cast<float>(sum);
    m_integral = static_cast<float>(sum / static_cast<double>(n));
    m_uniform_fallback = !(sum > 0.0);

    m_cdf.resize(n + 1);
    m_cdf[0] = 0.0f;
    double running = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        running += m_uniform_fallback ? 1.0 : static_cast<double>(m_func[i]);
        const double total = m_uniform_fallback ? static_cast<double>(n) : sum;
        m_cdf[i + 1] = static_cast<float>(running / total);
    }
    // Rounding must not leave the last entry short of 1, or u near 1 would find no bin.
    m_cdf[n] = 1.0f;
}

float Distribution1D::pmf(std::size_t i) const {
    if (i >= m_func.size()) return 0.0f;
    if (m_uniform_fallback) return 1.0f / static_cast<float>(m_func.size());
    return m_func[i] / m_sum;
}

float Distribution1D::pdf(float x) const {
    if (!(x >= 0.0f && x < 1.0f)) return 0.0f;
    const std::size_t n = m_func.size();
    const std::size_t i = std::min(static_cast<std::size_t>(x * static_cast<float>(n)), n - 1);
    if (m_uniform_fallback) return 1.0f;
    return m_func[i] / m_integral;
}

std::size_t Distribution1D::find_bin(float u) const {
    // upper_bound returns the first edge strictly above u, so the bin before it has
    // cdf[i] <= u < cdf[i + 1]: an empty bin (equal edges) can never be chosen.
    const auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), u);
    const std::ptrdiff_t i = (it - m_cdf.begin()) - 1;
    return static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(m_func.size()) - 1));
}

Distribution1D::ContinuousSample Distribution1D::sample_continuous(float u) const {
    u = clamp_unit(u);
    const std::size_t i = find_bin(u);
    const float width = m_cdf[i + 1] - m_cdf[i];
    const float du = width > 0.0f ? (u - m_cdf[i]) / width : 0.0f;
    const float n = static_cast<float>(m_func.size());
    const float x = std::min((static_cast<float>(i) + du) / n, kOneMinusEpsilon);
    const float density = m_uniform_fallback ? 1.0f : m_func[i] / m_integral;
    return {x, density, i};
}

Distribution1D::DiscreteSample Distribution1D::sample_discrete(float u) const {
    u = clamp_unit(u);
    const std::size_t i = find_bin(u);
    const float width = m_cdf[i + 1] - m_cdf[i];
    const float du = width > 0.0f ? std::min((u - m_cdf[i]) / width, kOneMinusEpsilon) : 0.0f;
    return {i, pmf(i), du};
}

namespace {

std::vector<Distribution1D> make_rows(const std::vector<float>& values, std::size_t width,
                                      std::size_t height) {
    if (width == 0 || height == 0 || values.size() != width * height) {
        throw Error("Distribution2D: " + std::to_string(values.size()) + " values for a " +
                    std::to_string(width) + " x " + std::to_string(height) + " grid");
    }
    std::vector<Distribution1D> rows;
    rows.reserve(height);
    for (std::size_t j = 0; j < height; ++j) {
        const auto row_start = values.begin() + static_cast<std::ptrdiff_t>(j * width);
        rows.emplace_back(
            std::vector<float>(row_start, row_start + static_cast<std::ptrdiff_t>(width)));
    }
    return rows;
}

std::vector<float> row_integrals(const std::vector<Distribution1D>& rows) {
    std::vector<float> integrals;
    integrals.reserve(rows.size());
    for (const Distribution1D& row : rows) integrals.push_back(row.integral());
    return integrals;
}

}  // namespace

Distribution2D::Distribution2D(const std::vector<float>& values, std::size_t width,
                               std::size_t height)
    : m_rows(make_rows(values, width, height)), m_marginal(row_integrals(m_rows)) {}

// The density factors as p(x, y) = p(y) p(x | y) = (row integral / integral) *
// (value / row integral) = value / integral, which pdf() evaluates the same way.
Distribution2D::ContinuousSample Distribution2D::sample_continuous(const Vec2& u) const {
    const Distribution1D::ContinuousSample row = m_marginal.sample_continuous(u.y);
    const Distribution1D::ContinuousSample along = m_rows[row.index].sample_continuous(u.x);
    return {Vec2(along.x, row.x), row.pdf * along.pdf};
}

float Distribution2D::pdf(const Vec2& point) const {
    if (!(point.y >= 0.0f && point.y < 1.0f)) return 0.0f;
    const std::size_t n = m_rows.size();
    const std::size_t j =
        std::min(static_cast<std::size_t>(point.y * static_cast<float>(n)), n - 1);
    return m_marginal.pdf(point.y) * m_rows[j].pdf(point.x);
}

}  // namespace glint
