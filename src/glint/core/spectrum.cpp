#include <glint/core/secondary_wavelengths.h>
#include <glint/core/spectrum.h>

#include <cmath>

namespace glint {

namespace {
// The visible range spectral mode samples, nm (the CIE 1931 observer's tables).
constexpr float kLambdaMin = 360.0f;
constexpr float kLambdaMax = 830.0f;
// The importance density p(λ) ∝ 1 / cosh²(a (λ − λ_c)) over [kLambdaMin, kLambdaMax]: a
// bell around the eye's peak sensitivity whose width follows the luminous efficiency
// (the fit of Radziszewski et al. 2009, also pbrt-v4's choice), so few samples go where the
// observer barely sees. Its CDF is tanh, so it is sampled in closed form.
constexpr double kCentre = 538.0;
constexpr double kSharpness = 0.0072;

double visible_cdf_numerator(double nm) {
    return std::tanh(kSharpness * (nm - kCentre));
}

float visible_pdf(float nm) {
    static const double norm =
        kSharpness / (visible_cdf_numerator(kLambdaMax) - visible_cdf_numerator(kLambdaMin));
    const double c = std::cosh(kSharpness * (nm - kCentre));
    return static_cast<float>(norm / (c * c));
}

float sample_visible_wavelength(float u) {
    static const double t0 = visible_cdf_numerator(kLambdaMin);
    static const double t1 = visible_cdf_numerator(kLambdaMax);
    const double t = t0 + static_cast<double>(u) * (t1 - t0);
    const double nm = kCentre + std::atanh(t) / kSharpness;
    return std::clamp(static_cast<float>(nm), kLambdaMin, kLambdaMax);
}
}  // namespace

namespace {
thread_local bool t_secondary_terminated = false;
}  // namespace

void terminate_secondary_wavelengths() {
    t_secondary_terminated = true;
}
bool secondary_wavelengths_terminated() {
    return t_secondary_terminated;
}
SecondaryWavelengthsScope::SecondaryWavelengthsScope() : m_previous(t_secondary_terminated) {
    t_secondary_terminated = false;
}
SecondaryWavelengthsScope::~SecondaryWavelengthsScope() {
    t_secondary_terminated = m_previous;
}

SampledWavelengths SampledWavelengths::sample_visible(float u) {
    SampledWavelengths w;
    for (int i = 0; i < kCount; ++i) {
        float ui = u + static_cast<float>(i) / static_cast<float>(kCount);
        if (ui >= 1.0f) ui -= 1.0f;
        w.nm[i] = sample_visible_wavelength(ui);
        w.pdf[i] = visible_pdf(w.nm[i]);
    }
    return w;
}

namespace detail {

Spectrum uplift_at_wavelengths(const Rgb& rgb, RgbRole role, const WavelengthContext& c) {
    Spectrum s;
    const SpectralModel::Values v = c.model->uplift(rgb, role, c.lambda.nm);
    for (int i = 0; i < Spectrum::kValues; ++i) s.m_v[i] = v[i];
    return s;
}

// The film's colour is ∫ L(λ) o(λ) dλ with o the model's observer; each wavelength, drawn
// by pdf, gives the estimate L(λ_i) o(λ_i) / pdf(λ_i), and the path's four are averaged.
// After a dispersive event only the hero's estimate is valid and it stands alone (as
// pbrt-v4's TerminateSecondary): for the current path when it went through one, and for a
// value whose other wavelengths are exactly 0 (a light path's that did, met by another path,
// as vcm and sppm join them; an uplifted colour is never exactly 0 at some wavelengths only).
Rgb spectral_to_rgb(const std::array<float, Spectrum::kValues>& v, const WavelengthContext& c) {
    const bool hero_alone =
        secondary_wavelengths_terminated() || (v[1] == 0.0f && v[2] == 0.0f && v[3] == 0.0f);
    const int count = hero_alone ? 1 : Spectrum::kValues;
    Rgb sum;
    for (int i = 0; i < count; ++i) {
        if (v[i] == 0.0f || c.lambda.pdf[i] <= 0.0f) continue;
        sum += c.model->observer(c.lambda.nm[i]) * (v[i] / c.lambda.pdf[i]);
    }
    return sum / static_cast<float>(count);
}

}  // namespace detail

}  // namespace glint
