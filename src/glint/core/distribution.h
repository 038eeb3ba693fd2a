#pragma once
// A piecewise-constant 1D distribution over [0, 1) built from n non-negative bin values.
// Used for pixel filter importance sampling (one per axis) and for choosing lights in
// proportion to their power, so it offers both a continuous and a discrete view.
// Distribution2D builds on it for image-based lighting.
#include <glint/math/vector.h>

#include <cstddef>
#include <vector>

namespace glint {

class Distribution1D {
public:
    struct ContinuousSample {
        float x;            ///< position in [0, 1)
        float pdf;          ///< density with respect to x on [0, 1)
        std::size_t index;  ///< the bin x fell in
    };
    struct DiscreteSample {
        std::size_t index;  ///< chosen bin
        float pmf;          ///< probability of choosing it
        float u_remapped;   ///< u stretched back to [0, 1) within the bin, for reuse
    };

    /// `values` are the bin heights; they must be finite and non-negative (throws
    /// glint::Error otherwise) and there must be at least one. If all are zero the
    /// distribution falls back to uniform so that sampling stays well defined, while
    /// integral() still reports 0.
    explicit Distribution1D(std::vector<float> values);

    std::size_t size() const { return m_func.size(); }
    /// Bin height i as given to the constructor.
    float value(std::size_t i) const { return m_func[i]; }
    /// Integral of the step function over [0, 1): the mean bin height.
    float integral() const { return m_integral; }
    /// Probability of bin i under sample_discrete.
    float pmf(std::size_t i) const;
    /// Density at x in [0, 1) under sample_continuous (0 outside).
    float pdf(float x) const;

    /// Deterministic in u; u is clamped into [0, 1).
    ContinuousSample sample_continuous(float u) const;
    DiscreteSample sample_discrete(float u) const;

private:
    std::size_t find_bin(float u) const;

    std::vector<float> m_func;
    std::vector<float> m_cdf;  // size n + 1, m_cdf[0] = 0, m_cdf[n] = 1
    float m_sum = 0.0f;
    float m_integral = 0.0f;
    bool m_uniform_fallback = false;
};

/// A piecewise-constant 2D distribution over [0, 1)^2 built from a grid of non-negative
/// cell values: a marginal distribution over the rows (by each row's integral) and one
/// conditional distribution per row. Points are (x, y) with x along a row (the column
/// axis) and y across the rows, so for an image, cell (column i, row j) covers
/// [i / width, (i + 1) / width) x [j / height, (j + 1) / height).
class Distribution2D {
public:
    struct ContinuousSample {
        Vec2 point;  ///< (x, y) in [0, 1)^2
        float pdf;   ///< density with respect to area on [0, 1)^2
    };

    /// `values` holds height rows of width cells, row after row. Values must be finite and
    /// non-negative (throws glint::Error otherwise, as does a size that does not match).
    /// All-zero values fall back to a uniform distribution, as Distribution1D does.
    Distribution2D(const std::vector<float>& values, std::size_t width, std::size_t height);

    std::size_t width() const { return m_rows.front().size(); }
    std::size_t height() const { return m_rows.size(); }
    /// Integral of the step function over [0, 1)^2: the mean cell value.
    float integral() const { return m_marginal.integral(); }

    /// Deterministic in u; each coordinate is clamped into [0, 1). u.y picks the row,
    /// u.x the position along it.
    ContinuousSample sample_continuous(const Vec2& u) const;
    /// Density at a point of [0, 1)^2 under sample_continuous (0 outside).
    float pdf(const Vec2& point) const;

private:
    std::vector<Distribution1D> m_rows;  // conditional densities of x given the row
    Distribution1D m_marginal;           // row integrals
};

}  // namespace glint
