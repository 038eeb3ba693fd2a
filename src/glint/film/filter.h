#pragma once
// Pixel reconstruction filters, used by filter importance sampling (Ernst et al. 2006):
// the camera ray's position is drawn from the filter itself and the sample is credited
// to the one pixel it was drawn for. A sample therefore never touches a neighbour, which
// keeps the film lock-free and the image identical for any thread count.
#include <glint/core/distribution.h>
#include <glint/math/vector.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint {

struct FilterSample {
    Vec2 offset;   ///< from the pixel centre, in pixels; inside [-radius, radius]
    float weight;  ///< sign(f) * integral of |f|; negative in Mitchell's lobes
};

class Filter {
public:
    virtual ~Filter() = default;

    /// Unnormalised filter value at `offset` pixels from the pixel centre; 0 outside
    /// the radius.
    virtual float eval(Vec2 offset) const = 0;

    /// Half-width of the support, in pixels, per axis.
    Vec2 radius() const { return m_radius; }

    /// Draws an offset with density proportional to |f| and returns it with a weight
    /// such that sum(weight * L) / sum(weight) over one pixel's samples is the filtered
    /// pixel value. Deterministic in u (each component in [0, 1)).
    FilterSample sample(Vec2 u) const;

protected:
    explicit Filter(Vec2 radius);

    /// Separable filters f(x, y) = fx(x) * fy(y) call this from their constructor with
    /// the 1D factors (already zero outside the radius). Without it sample() is uniform
    /// over the support with weight 1, which is exact for the box.
    void tabulate_separable(const std::function<float(float)>& fx,
                            const std::function<float(float)>& fy);

private:
    // |f| of one axis, averaged over each bin, as a distribution over [-r, r], with the
    // sign of each bin kept aside so negative lobes get negative weights.
    struct Axis {
        Distribution1D distribution;
        std::vector<float> sign;
        float abs_integral;  // integral of |f| over [-r, r], in pixels
    };
    static Axis tabulate_axis(const std::function<float(float)>& f, float radius);

    Vec2 m_radius;
    std::optional<std::array<Axis, 2>> m_axes;
};

/// Uniform weight over [-radius, radius]^2 (radius in pixels, default half a pixel).
std::unique_ptr<Filter> make_box_filter(float radius = 0.5f);
/// Per axis exp(-x^2 / (2 sigma^2)) - exp(-r^2 / (2 sigma^2)), clamped at 0 so that the
/// filter reaches zero at its radius; sigma in pixels.
std::unique_ptr<Filter> make_gaussian_filter(float radius = 1.5f, float sigma = 0.5f);
/// Mitchell-Netravali cubic (B, C) stretched so its support [-2, 2] maps onto
/// [-radius, radius]; has negative lobes for the default B = C = 1/3.
std::unique_ptr<Filter> make_mitchell_filter(float radius = 2.0f, float b = 1.0f / 3,
                                             float c = 1.0f / 3);
/// `name` is "box", "gaussian" or "mitchell"; radius <= 0 selects that filter's
/// default. Throws glint::Error naming the valid filters for anything else.
std::unique_ptr<Filter> make_filter(const std::string& name, float radius);

}  // namespace glint
