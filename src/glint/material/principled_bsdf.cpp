#include <glint/material/principled_bsdf.h>
#include <glint/math/warp.h>

#include <array>

namespace glint {
namespace {

constexpr int kSheenIntervals = 32;  // nodes at cos theta = j / 32

float pow5(float x) {
    const float x2 = x * x;
    return x2 * x2 * x;
}

// Burley's sheen factor (1 - cos theta_d)^5, theta_d the angle between wi (or wo: the half
// vector bisects them) and the half vector, for directions in the upper hemisphere.
float sheen_factor(const Vec3& i, const Vec3& wm) {
    return pow5(1.0f - std::clamp(glm::dot(i, wm), 0.0f, 1.0f));
}

// E_sheen(mu) by the midpoint rule over the hemisphere in (theta, phi): the lobe is smooth
// and wide, so 128 x 128 cells resolve it to about 1e-5.
float integrate_sheen_albedo(float mu) {
    const int ntheta = 128, nphi = 128;
    const Vec3 o(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, std::max(mu, 1e-4f));
    const double dtheta = 0.5 * M_PI / ntheta, dphi = 2.0 * M_PI / nphi;
    double sum = 0.0;
    for (int a = 0; a < ntheta; ++a) {
        const double theta = (a + 0.5) * dtheta;
        const double z = std::cos(theta), r = std::sin(theta);
        for (int b = 0; b < nphi; ++b) {
            const double phi = (b + 0.5) * dphi;
            const Vec3 i(static_cast<float>(r * std::cos(phi)),
                         static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
            sum += sheen_factor(i, glm::normalize(o + i)) * z * r;
        }
    }
    return static_cast<float>(sum * dtheta * dphi);
}

// Schlick's approximation of a conductor's Fresnel reflectance from its colour at normal
// incidence (glTF 2.0, Appendix B: the metal's F0 is the base colour).
Spectrum fresnel_schlick(const Spectrum& f0, float cos_theta) {
    const float weight = pow5(1.0f - std::clamp(cos_theta, 0.0f, 1.0f));
    return f0 + (Spectrum(1.0f) - f0) * weight;
}

}  // namespace

float sheen_albedo(float cos_theta) {
    // Read-only after its thread-safe first initialisation.
    static const std::array<float, kSheenIntervals + 1> table = [] {
        std::array<float, kSheenIntervals + 1> values{};
        for (int j = 0; j <= kSheenIntervals; ++j)
            values[j] = integrate_sheen_albedo(static_cast<float>(j) / kSheenIntervals);
        return values;
    }();
    const float x = std::clamp(cos_theta, 0.0f, 1.0f) * kSheenIntervals;
    const int j = std::min(static_cast<int>(x), kSheenIntervals - 1);
    const float s = x - j;
    return (1.0f - s) * table[j] + s * table[j + 1];
}

PrincipledBsdf::PrincipledBsdf(const PrincipledParams& params,
                               const CoatAlbedoTable& specular_albedo,
                               const CoatAlbedoTable& coat_albedo)
    : Bsdf(flags_for(params), params.ior),
      m_p(params),
      m_base(std::max(params.alpha, kMinAlpha)),
      m_coat(std::max(params.clearcoat_alpha, kMinAlpha)),
      m_glass(params.ior, m_base),
      m_specular_albedo(&specular_albedo),
      m_coat_albedo(&coat_albedo),
      m_specular_eta(specular_albedo.eta()),
      m_diffuse_scale(kInvPi / (1.0f - specular_albedo.average_albedo(m_base.alpha_x()))) {
    // Burley's sheen tint: the base colour's hue at full brightness. Normalised by its
    // largest channel rather than its luminance, so that no channel exceeds 1.
    const float brightest = params.base_color.max_value();
    const Spectrum hue = brightest > 0.0f ? params.base_color / brightest : Spectrum(1.0f);
    m_sheen_color =
        (Spectrum(1.0f) * (1.0f - params.sheen_tint) + hue * params.sheen_tint) * params.sheen;
}

uint32_t PrincipledBsdf::flags_for(const PrincipledParams& p) {
    uint32_t flags = kBsdfReflection | kBsdfGlossy;
    const float dielectric = 1.0f - p.metallic;
    if (dielectric * p.transmission > 0.0f) flags |= kBsdfTransmission;
    const bool diffuse_or_sheen = p.base_color.max_value() > 0.0f || p.sheen > 0.0f;
    if (dielectric * (1.0f - p.transmission) > 0.0f && diffuse_or_sheen) flags |= kBsdfDiffuse;
    return flags;
}

float PrincipledBsdf::ggx_reflection(const GgxDistribution& distribution, const Vec3& o,
                                     const Vec3& i) {
    const Vec3 wm = glm::normalize(o + i);
    return distribution.d(wm) * distribution.g2(o, i) / (4.0f * o.z * i.z);
}

float PrincipledBsdf::ggx_reflection_pdf(const GgxDistribution& distribution, const Vec3& o,
                                         const Vec3& i) {
    const Vec3 wm = glm::normalize(o + i);
    // d(wi) / d(wm) = 4 wo.wm for reflection about wm.
    return distribution.visible_normal_pdf(o, wm) / (4.0f * glm::dot(o, wm));
}

float PrincipledBsdf::coat_transmittance(const Vec3& w) const {
    if (m_p.clearcoat == 0.0f) return 1.0f;
    return 1.0f - m_p.clearcoat * m_coat_albedo->albedo(std::abs(w.z), m_coat.alpha_x());
}

Spectrum PrincipledBsdf::sheen_transmittance(const Vec3& w) const {
    if (m_p.sheen == 0.0f) return Spectrum(1.0f);
    return Spectrum(1.0f) - m_sheen_color * sheen_albedo(std::abs(w.z));
}

float PrincipledBsdf::specular_albedo(const Vec3& w) const {
    return m_specular_albedo->albedo(std::abs(w.z), m_base.alpha_x());
}

// The glass is asked for its f without the 1/eta^2 of radiance transport, which this BSDF's
// own wrappers apply: in importance mode with the default geometric normal (the shading
// normal) the wrappers apply no factor at all (bsdf.h, shading_correction).
Spectrum PrincipledBsdf::eval_unscaled(const Vec3& wo, const Vec3& wi) const {
    if (wo.z == 0.0f || wi.z == 0.0f) return Spectrum(0.0f);
    const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
    const float dielectric = 1.0f - m_p.metallic;
    const float glass = dielectric * m_p.transmission;
    const float opaque = dielectric * (1.0f - m_p.transmission);
    const float coat_through = coat_transmittance(o) * coat_transmittance(i);
    if (!same_hemisphere(wo, wi)) {
        if (glass == 0.0f) return Spectrum(0.0f);
        // The glass lobe is grey (its Fresnel term is a scalar): any of its values.
        const float f = m_glass.eval(wo, wi, TransportMode::kImportance).max_value();
        return m_p.base_color * (coat_through * glass * f);
    }
    const Vec3 wm = glm::normalize(o + i);
    const float cos_om = glm::dot(o, wm);
    Spectrum under(0.0f);
    if (m_p.metallic > 0.0f || opaque > 0.0f) {
        const float ggx = ggx_reflection(m_base, o, i);
        if (m_p.metallic > 0.0f)
            under += fresnel_schlick(m_p.base_color, cos_om) * (m_p.metallic * ggx);
        if (opaque > 0.0f) {
            const float specular = fresnel_dielectric(cos_om, m_specular_eta) * ggx;
            const float through = (1.0f - specular_albedo(o)) * (1.0f - specular_albedo(i));
            const Spectrum diffuse = m_p.base_color * (m_diffuse_scale * through);
            Spectrum layer =
                sheen_transmittance(o) * sheen_transmittance(i) * (Spectrum(specular) + diffuse);
            if (m_p.sheen > 0.0f) layer += m_sheen_color * sheen_factor(i, wm);
            under += layer * opaque;
        }
    }
    if (glass > 0.0f) under += m_glass.eval(wo, wi, TransportMode::kImportance) * glass;
    Spectrum f = under * coat_through;
    if (m_p.clearcoat > 0.0f) {
        f += Spectrum(m_p.clearcoat * fresnel_dielectric(cos_om, 1.5f) *
                      ggx_reflection(m_coat, o, i));
    }
    return f;
}

// The weights estimate each strategy's share of the albedo at wo; a lobe that is present
// must keep a weight above zero wherever its f can be (the metal's Schlick estimate is 0 at
// normal incidence for a black base, but its tilted facets still reflect).
void PrincipledBsdf::strategy_weights(const Vec3& wo, float weights[kStrategies]) const {
    const Vec3 o = mirror_to_upper(wo);
    const float dielectric = 1.0f - m_p.metallic;
    const float opaque = dielectric * (1.0f - m_p.transmission);
    const float coat_through = coat_transmittance(o);
    float specular = 0.0f, cosine = 0.0f;
    if (m_p.metallic > 0.0f)
        specular += m_p.metallic * std::max(fresnel_schlick(m_p.base_color, o.z).average(), 0.05f);
    if (opaque > 0.0f) {
        const float sheen_through = sheen_transmittance(o).average();
        const float e = specular_albedo(o);
        specular += opaque * sheen_through * e;
        cosine = opaque * (sheen_through * (1.0f - e) * m_p.base_color.average() +
                           m_sheen_color.average() * sheen_albedo(o.z));
    }
    weights[kCoat] = 1.0f - coat_through;  // c E_coat(o)
    weights[kSpecular] = coat_through * specular;
    weights[kGlass] = coat_through * dielectric * m_p.transmission;
    weights[kCosine] = coat_through * cosine;
}

float PrincipledBsdf::pdf_unscaled(const Vec3& wo, const Vec3& wi) const {
    if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
    float w[kStrategies];
    strategy_weights(wo, w);
    const float total = w[kCoat] + w[kSpecular] + w[kGlass] + w[kCosine];
    if (!(total > 0.0f)) return 0.0f;
    if (!same_hemisphere(wo, wi)) {
        return w[kGlass] > 0.0f ? w[kGlass] * m_glass.pdf(wo, wi) / total : 0.0f;
    }
    const Vec3 o = mirror_to_upper(wo), i = mirror_to_upper(wi);
    float p = 0.0f;
    if (w[kCoat] > 0.0f) p += w[kCoat] * ggx_reflection_pdf(m_coat, o, i);
    if (w[kSpecular] > 0.0f) p += w[kSpecular] * ggx_reflection_pdf(m_base, o, i);
    if (w[kGlass] > 0.0f) p += w[kGlass] * m_glass.pdf(wo, wi);
    if (w[kCosine] > 0.0f) p += w[kCosine] * i.z * kInvPi;
    return p / total;
}

bool PrincipledBsdf::sample_unscaled(const Vec3& wo, const Vec2& u, float u_lobe,
                                     BsdfSample& out) const {
    if (wo.z == 0.0f) return false;
    float w[kStrategies];
    strategy_weights(wo, w);
    const float total = w[kCoat] + w[kSpecular] + w[kGlass] + w[kCosine];
    if (!(total > 0.0f)) return false;
    // Choose a strategy, and stretch u_lobe's part of [0, 1) inside it back to [0, 1) for the
    // glass, which chooses between its reflection and refraction with it.
    float x = u_lobe * total;
    int strategy = 0;
    while (strategy < kStrategies - 1 && (w[strategy] == 0.0f || x >= w[strategy])) {
        x -= w[strategy];
        ++strategy;
    }
    if (w[strategy] == 0.0f) return false;  // rounding ran past the last present strategy
    const float u_rest = std::clamp(x / w[strategy], 0.0f, 0x1.fffffep-1f);

    const Vec3 o = mirror_to_upper(wo);
    Vec3 wi;
    switch (strategy) {
        case kCoat:
        case kSpecular: {
            const GgxDistribution& distribution = strategy == kCoat ? m_coat : m_base;
            wi = reflect(o, distribution.sample_visible_normal(o, u));
            if (wi.z <= 0.0f) return false;  // reflected into the surface: masked
            if (wo.z < 0.0f) wi.z = -wi.z;
            break;
        }
        case kGlass: {
            BsdfSample glass;
            if (!m_glass.sample(wo, u, u_rest, glass, TransportMode::kImportance)) return false;
            wi = glass.wi;
            break;
        }
        default:
            wi = warp::square_to_cosine_hemisphere(u);
            if (wo.z < 0.0f) wi.z = -wi.z;
            break;
    }
    const float p = pdf_unscaled(wo, wi);
    if (!(p > 0.0f)) return false;
    const bool transmitted = !same_hemisphere(wo, wi);
    uint32_t flags = transmitted ? kBsdfTransmission : kBsdfReflection;
    flags |= strategy == kCosine ? kBsdfDiffuse : kBsdfGlossy;
    const float eta = transmitted ? (wo.z > 0.0f ? m_p.ior : 1.0f / m_p.ior) : 1.0f;
    out = BsdfSample{eval_unscaled(wo, wi), wi, p, flags, eta};
    return true;
}

}  // namespace glint
