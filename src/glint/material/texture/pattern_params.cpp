#include <glint/material/texture/pattern_params.h>

#include <fmt/format.h>

namespace glint {

Rgb read_colour(const Params& params, const std::string& name, const Rgb& fallback) {
    const Rgb colour = params.get_rgb(name, fallback);
    if (colour.min_value() < 0.0f) params.fail(fmt::format("'{}' must not be negative", name));
    return colour;
}

float read_positive(const Params& params, const std::string& name, float fallback) {
    const float value = params.get_float(name, fallback);
    if (!(value > 0.0f)) params.fail(fmt::format("'{}' must be greater than 0", name));
    return value;
}

float read_non_negative(const Params& params, const std::string& name, float fallback) {
    const float value = params.get_float(name, fallback);
    if (!(value >= 0.0f)) params.fail(fmt::format("'{}' must not be negative", name));
    return value;
}

FractalSettings read_fractal_settings(const Params& params, int default_octaves) {
    FractalSettings settings;
    settings.octaves = params.get_int("octaves", default_octaves);
    if (settings.octaves < 1 || settings.octaves > kMaxOctaves)
        params.fail(fmt::format("'octaves' must lie in [1, {}]", kMaxOctaves));
    settings.lacunarity = read_positive(params, "lacunarity", settings.lacunarity);
    settings.gain = read_non_negative(params, "gain", settings.gain);
    return settings;
}

}  // namespace glint
