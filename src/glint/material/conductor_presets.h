#pragma once
// Complex refractive indices eta + i k of common metals, relative to air, per RGB channel.
//
// Where the numbers come from: the measured spectra pbrt-v4 ships for these metals
// (mmp/pbrt-v4, src/pbrt/util/spectrum.cpp, tables Au_eta/Au_k, Ag_*, Cu_*, Al_*, which
// follow Palik's "Handbook of Optical Constants of Solids"), linearly interpolated at
// 650 nm (R), 550 nm (G) and 450 nm (B). Point samples rather than averages weighted by
// the colour matching functions: close enough for RGB rendering, and easy to check. The
// resulting reflectance at normal incidence is gold (0.94, 0.85, 0.39), silver (0.97,
// 0.96, 0.92), copper (0.94, 0.63, 0.55), aluminium (0.91, 0.92, 0.92).
#include <glint/core/rgb.h>

#include <array>
#include <string_view>

namespace glint {

struct ConductorPreset {
    std::string_view name;
    Rgb eta;
    Rgb k;
};

inline constexpr std::array<ConductorPreset, 4> kConductorPresets = {{
    {"gold", {0.1678f, 0.3504f, 1.5085f}, {3.1378f, 2.7141f, 1.8788f}},
    {"silver", {0.1394f, 0.1248f, 0.1517f}, {4.1288f, 3.3396f, 2.4704f}},
    {"copper", {0.2166f, 0.9582f, 1.1658f}, {3.6377f, 2.5771f, 2.3939f}},
    {"aluminium", {1.4748f, 0.9586f, 0.6180f}, {7.7941f, 6.6870f, 5.4694f}},
}};

// The preset called `name`, or nullptr.
inline const ConductorPreset* find_conductor_preset(std::string_view name) {
    for (const ConductorPreset& preset : kConductorPresets) {
        if (preset.name == name) return &preset;
    }
    return nullptr;
}

}  // namespace glint
