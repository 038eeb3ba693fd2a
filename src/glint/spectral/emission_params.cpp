#include <glint/spectral/emission_params.h>

#include <glint/spectral/blackbody.h>
#include <glint/spectral/cie.h>
#include <glint/spectral/illuminants.h>
#include <glint/spectral/spectrum_to_rgb.h>

#include <cmath>

#include <fmt/format.h>

namespace glint::spectral {
namespace {

constexpr double kMinKelvin = 100.0;
constexpr double kMaxKelvin = 100000.0;

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "'" : ", '") + n + "'";
    return out;
}

}  // namespace

EmissionShape::EmissionShape(double kelvin, TabulatedSpectrum spectrum)
    : m_kelvin(kelvin), m_table(std::move(spectrum)) {
    const double luminance =
        emission_to_rgb([this](double nm) { return unscaled(nm); }).luminance();
    m_scale = luminance > 0.0 ? 1.0 / luminance : 0.0;
    // A very red black body (below ~2000 K) lies outside the Rec.709 gamut: its blue is a
    // hair below 0, which RGB mode clips (the spectral mode keeps the spectrum itself).
    m_rgb = emission_to_rgb([this](double nm) { return eval(nm); }).clamped(0.0f, INFINITY);
}

EmissionShape EmissionShape::blackbody(double kelvin) {
    return EmissionShape(kelvin, TabulatedSpectrum());
}

EmissionShape EmissionShape::tabulated(TabulatedSpectrum spectrum) {
    return EmissionShape(0.0, std::move(spectrum));
}

double EmissionShape::unscaled(double nm) const {
    if (m_kelvin > 0.0) return blackbody_normalized(nm, m_kelvin);
    return m_table.eval(static_cast<float>(nm));
}

double EmissionShape::eval(double nm) const {
    return m_scale * unscaled(nm);
}

std::optional<EmissionShape> read_emission_shape(const Params& params) {
    const bool has_blackbody = params.has("blackbody"), has_spectrum = params.has("spectrum");
    if (has_blackbody && has_spectrum) params.fail("give 'blackbody' or 'spectrum', not both");
    if (has_blackbody) {
        const double kelvin = params.get_float("blackbody");
        if (!(kelvin >= kMinKelvin && kelvin <= kMaxKelvin))
            params.fail(fmt::format("'blackbody' is a temperature in kelvin in [{}, {}], got {}",
                                    kMinKelvin, kMaxKelvin, kelvin));
        return EmissionShape::blackbody(kelvin);
    }
    if (!has_spectrum) return std::nullopt;
    if (params.is_string("spectrum")) {
        const std::string name = params.get_string("spectrum");
        const TabulatedSpectrum* illuminant = named_illuminant(name);
        if (!illuminant)
            params.fail(
                fmt::format("unknown 'spectrum' '{}'; known illuminants: {} (or give a "
                            "table {{ {{nm, value}}, ... }})",
                            name, joined(illuminant_names())));
        return EmissionShape::tabulated(*illuminant);
    }
    std::vector<std::pair<float, float>> samples;
    for (const Vec2& pair : params.get_vec2_list("spectrum")) samples.emplace_back(pair.x, pair.y);
    if (auto problem = TabulatedSpectrum::check(samples))
        params.fail(fmt::format("'spectrum': {}", *problem));
    // A table that is 0 wherever the eye sees has no colour to scale to luminance 1.
    EmissionShape shape = EmissionShape::tabulated(TabulatedSpectrum(std::move(samples)));
    if (!(shape.rgb().luminance() > 0.0f))
        params.fail(fmt::format("'spectrum' emits nothing visible between {} and {} nm", kLambdaMin,
                                kLambdaMax));
    return shape;
}

Rgb read_emission_rgb(const Params& params, const char* name) {
    const std::optional<EmissionShape> shape = read_emission_shape(params);
    const Rgb colour = shape ? params.get_rgb(name, Rgb(1.0f)) : params.get_rgb(name);
    if (colour.min_value() < 0.0f) params.fail(fmt::format("'{}' must not be negative", name));
    return shape ? colour * shape->rgb() : colour;
}

namespace {

// An emission shape as the colour of a light reads it.
class ShapeSpectrum final : public EmissionSpectrum {
public:
    explicit ShapeSpectrum(EmissionShape shape) : m_shape(std::move(shape)) {}
    float eval(float nm) const override { return static_cast<float>(m_shape.eval(nm)); }

private:
    EmissionShape m_shape;
};

}  // namespace

SceneColor read_emission_color(const Params& params, const char* name) {
    const std::optional<EmissionShape> shape = read_emission_shape(params);
    if (!shape) return {read_emission_rgb(params, name), RgbRole::illuminant};
    const Rgb colour = params.get_rgb(name, Rgb(1.0f));
    if (colour.min_value() < 0.0f) params.fail(fmt::format("'{}' must not be negative", name));
    const Rgb shape_rgb = shape->rgb();
    return {colour, std::make_shared<const ShapeSpectrum>(*shape), shape_rgb};
}

}  // namespace glint::spectral
