#include <glint/medium/homogeneous_medium.h>
#include <glint/medium/registry.h>

namespace glint {
namespace {

Rgb non_negative_rgb(const Params& params, const char* name, const Rgb& fallback) {
    const Rgb value = params.get_rgb(name, fallback);
    if (!(value.min_value() >= 0.0f) || !std::isfinite(value.max_value()))
        params.fail(fmt::format("'{}' must be finite and not negative", name));
    return value;
}

}  // namespace

// glint.medium{...}: a participating medium, for a shape's interior or exterior (the
// `interior`/`exterior` of glint.interface and glint.dielectric) or the camera's `medium`.
//   sigma_a   spectrum  0    absorption coefficient per scene unit (times scale)
//   sigma_s   spectrum  0    scattering coefficient per scene unit (times scale)
//   density   spectrum  -    extinction sigma_a + sigma_s per scene unit; with `albedo`,
//                            instead of sigma_a and sigma_s
//   albedo    spectrum  1    sigma_s / (sigma_a + sigma_s), in [0, 1], with `density`
//   scale     float     1    multiplies the coefficients (a unit change), > 0
//   g         float     0    Henyey-Greenstein asymmetry in (-1, 1): > 0 scatters forwards
//   emission  spectrum  0    radiance of the medium's emission (its source is sigma_a times it)
std::unique_ptr<Medium> make_medium(const Params& params) {
    const bool by_density = params.has("density") || params.has("albedo");
    if (by_density && (params.has("sigma_a") || params.has("sigma_s")))
        params.fail("give either 'sigma_a' and 'sigma_s', or 'density' and 'albedo', not both");
    Rgb sigma_a(0.0f), sigma_s(0.0f);
    if (by_density) {
        const Rgb density = non_negative_rgb(params, "density", Rgb(1.0f));
        const Rgb albedo = non_negative_rgb(params, "albedo", Rgb(1.0f));
        if (albedo.max_value() > 1.0f) params.fail("'albedo' must lie in [0, 1]");
        sigma_s = density * albedo;
        sigma_a = density - sigma_s;
    } else {
        sigma_a = non_negative_rgb(params, "sigma_a", Rgb(0.0f));
        sigma_s = non_negative_rgb(params, "sigma_s", Rgb(0.0f));
    }
    const float scale = params.get_float("scale", 1.0f);
    if (!(scale > 0.0f) || !std::isfinite(scale)) params.fail("'scale' must be a positive number");
    const float g = params.get_float("g", 0.0f);
    if (!(g > -1.0f && g < 1.0f)) params.fail("'g' must lie in (-1, 1)");
    const Rgb emission = non_negative_rgb(params, "emission", Rgb(0.0f));
    params.check_all_used();
    return std::make_unique<HomogeneousMedium>(uplift(sigma_a * scale, RgbRole::unbounded),
                                               uplift(sigma_s * scale, RgbRole::unbounded), g,
                                               uplift(emission, RgbRole::illuminant));
}

}  // namespace glint
