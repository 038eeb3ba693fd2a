#include <glint/core/error.h>
#include <glint/material/conductor_presets.h>
#include <glint/scene/import/file_bytes.h>
#include <glint/scene/import/pbrt/spectra.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace glint {
namespace {

// A Gaussian lobe with different widths below and above its centre (the fit's building block).
double lobe(double nm, double mu, double sigma_below, double sigma_above) {
    const double t = (nm - mu) / (nm < mu ? sigma_below : sigma_above);
    return std::exp(-0.5 * t * t);
}

// Planck's law, up to a constant factor (which the luminance normalisation removes).
double planck(double nm, double kelvin) {
    const double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
    const double m = nm * 1e-9;
    return 2.0 * h * c * c / (std::pow(m, 5) * (std::exp(h * c / (m * kb * kelvin)) - 1.0));
}

// XYZ of a spectrum over the visible range in 1 nm steps, scaled to Y = 1.
template <typename Spectrum>
Vec3 xyz_normalised(Spectrum&& s) {
    double x = 0, y = 0, z = 0;
    for (int nm = 360; nm <= 830; ++nm) {
        const double v = s(static_cast<double>(nm));
        const Vec3 cmf = cie_xyz_fit(nm);
        x += v * cmf.x;
        y += v * cmf.y;
        z += v * cmf.z;
    }
    if (!(y > 0)) throw Error("the spectrum has no luminance (it is zero over 360-830 nm)");
    return Vec3(x / y, 1.0, z / y);
}

// Piecewise-linear interpolation of (nm, value) pairs, constant beyond the ends.
double interpolate(const std::vector<double>& pairs, double nm) {
    const size_t n = pairs.size() / 2;
    if (nm <= pairs[0]) return pairs[1];
    for (size_t i = 1; i < n; ++i) {
        const double l0 = pairs[2 * i - 2], l1 = pairs[2 * i];
        if (nm <= l1) {
            const double t = l1 > l0 ? (nm - l0) / (l1 - l0) : 1.0;
            return pairs[2 * i - 1] + t * (pairs[2 * i + 1] - pairs[2 * i - 1]);
        }
    }
    return pairs[2 * n - 1];
}

void check_pairs(const std::vector<double>& pairs) {
    if (pairs.size() < 2 || pairs.size() % 2 != 0)
        throw Error("a spectrum needs pairs of wavelength (nm) and value");
    for (size_t i = 2; i < pairs.size(); i += 2)
        if (!(pairs[i] > pairs[i - 2]))
            throw Error(fmt::format("spectrum wavelengths must increase ({} follows {})", pairs[i],
                                    pairs[i - 2]));
}

// Sellmeier's equation n^2 = 1 + sum B_i l^2 / (l^2 - C_i), l in micrometres.
double sellmeier(double um, const double (&b)[3], const double (&c)[3]) {
    const double l2 = um * um;
    double n2 = 1.0;
    for (int i = 0; i < 3; ++i) n2 += b[i] * l2 / (l2 - c[i]);
    return std::sqrt(n2);
}

struct Glass {
    const char* name;
    double b[3];
    double c[3];  // micrometres squared
};

// Sellmeier coefficients from the SCHOTT optical glass data sheets (N-BK7, N-BAF10, N-FK51A,
// N-LASF9, F5), the glasses pbrt-v4's named spectra tabulate.
constexpr Glass kGlasses[] = {
    {"glass-BK7", {1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}},
    {"glass-BAF10",
     {1.5851495, 0.143559385, 1.08521269},
     {0.00926681282, 0.0424489805, 105.613573}},
    {"glass-FK51A",
     {0.971247817, 0.216901417, 0.904651666},
     {0.00472301995, 0.0153575612, 168.68133}},
    {"glass-LASF9",
     {2.00029547, 0.298926886, 1.80691843},
     {0.0121426017, 0.0538736236, 156.530829}},
    {"glass-F5", {1.3104463, 0.19603426, 0.96612977}, {0.00958633048, 0.0457627627, 115.011883}},
};

}  // namespace

Vec3 cie_xyz_fit(double nm) {
    const double x = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                     0.065 * lobe(nm, 501.1, 20.4, 26.2);
    const double y = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
    const double z = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
    return Vec3(x, y, z);
}

Vec3 rec709_from_xyz(const Vec3& v) {
    return Vec3(3.2404542f * v.x - 1.5371385f * v.y - 0.4985314f * v.z,
                -0.9692660f * v.x + 1.8760108f * v.y + 0.0415560f * v.z,
                0.0556434f * v.x - 0.2040259f * v.y + 1.0572252f * v.z);
}

Vec3 blackbody_rgb(double kelvin) {
    if (!(kelvin > 0))
        throw Error(fmt::format("blackbody temperature {} K is not positive", kelvin));
    return rec709_from_xyz(xyz_normalised([&](double nm) { return planck(nm, kelvin); }));
}

Vec3 illuminant_rgb(const std::vector<double>& pairs) {
    check_pairs(pairs);
    return rec709_from_xyz(xyz_normalised([&](double nm) { return interpolate(pairs, nm); }));
}

Vec3 sampled_rgb(const std::vector<double>& pairs) {
    check_pairs(pairs);
    return Vec3(interpolate(pairs, 650.0), interpolate(pairs, 550.0), interpolate(pairs, 450.0));
}

std::optional<NamedSpectrum> named_spectrum(const std::string& name) {
    static const std::pair<const char*, const char*> kMetals[] = {
        {"Au", "gold"}, {"Ag", "silver"}, {"Cu", "copper"}, {"Al", "aluminium"}};
    for (const auto& [symbol, preset] : kMetals) {
        const std::string stem = fmt::format("metal-{}-", symbol);
        if (name == stem + "eta" || name == stem + "k") {
            const ConductorPreset* p = find_conductor_preset(preset);
            const Rgb& s = name == stem + "eta" ? p->eta : p->k;
            return NamedSpectrum{NamedSpectrum::Kind::Index, Vec3(s.r, s.g, s.b)};
        }
    }
    for (const Glass& g : kGlasses) {
        if (name == g.name)
            return NamedSpectrum{NamedSpectrum::Kind::Index,
                                 Vec3(sellmeier(0.65, g.b, g.c), sellmeier(0.55, g.b, g.c),
                                      sellmeier(0.45, g.b, g.c))};
    }
    // D65 is the white of Rec.709: luminance 1 is (1, 1, 1). Illuminant A is by definition a
    // blackbody at 2856 K.
    if (name == "stdillum-D65") return NamedSpectrum{NamedSpectrum::Kind::Illuminant, Vec3(1.0f)};
    if (name == "stdillum-A")
        return NamedSpectrum{NamedSpectrum::Kind::Illuminant, blackbody_rgb(2856.0)};
    return std::nullopt;
}

std::vector<double> read_spectrum_file(const std::string& path) {
    const std::string text = read_file_bytes(path, "spectrum");
    std::vector<double> values;
    size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
            ++i;
        } else {
            char* end = nullptr;
            const double v = std::strtod(text.c_str() + i, &end);
            if (end == text.c_str() + i || !std::isfinite(v))
                throw Error(fmt::format("{}: byte {}: not a number", path, i));
            values.push_back(v);
            i = static_cast<size_t>(end - text.c_str());
        }
    }
    try {
        check_pairs(values);
    } catch (const Error& e) {
        throw Error(fmt::format("{}: {}", path, e.what()));
    }
    return values;
}

}  // namespace glint
