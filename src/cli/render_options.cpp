#include "render_options.h"

#include "flags.h"

#include <glint/core/strict_number.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>

namespace glint::cli {

RenderSettings settings_for(const SceneDesc& desc, const RenderOptions& options) {
    Params table = desc.render ? *desc.render : Params("render", "render settings");
    if (const auto spp = int_flag("--spp", options.spp, 1, INT_MAX))
        table.set("spp", static_cast<double>(*spp), "--spp");
    if (!options.resolution.empty()) {
        const Vec2i res = parse_resolution_flag(options.resolution);
        table.set("width", static_cast<double>(res.x), "--res");
        table.set("height", static_cast<double>(res.y), "--res");
    }
    if (!options.crop.empty()) table.set("crop", parse_crop(options.crop), "--crop");
    if (!options.integrator.empty()) table.set("integrator", options.integrator, "--integrator");
    if (!options.exposure.empty()) {
        const auto stops = parse_finite(options.exposure);
        if (!stops || std::abs(*stops) > 100.0)
            bad_flag("--exposure", options.exposure, "a number of stops from -100 to 100");
        table.set("exposure", *stops, "--exposure");
    }
    if (!options.tonemap.empty()) table.set("tonemap", options.tonemap, "--tonemap");
    if (options.aovs) table.set("aovs", true, "--aovs");
    if (options.spectral) table.set("spectral", true, "--spectral");
    if (options.denoise) table.set("denoise", true, "--denoise");
    if (!options.denoiser.empty()) table.set("denoiser", options.denoiser, "--denoise");
    if (!options.denoise_quality.empty())
        table.set("denoise_quality", options.denoise_quality, "--denoise-quality");
    if (options.no_mipmap) table.set("mipmapping", false, "--no-mipmap");
    if (const auto every = int_flag("--intermediate", options.intermediate, 0, INT_MAX))
        table.set("intermediate", static_cast<double>(*every), "--intermediate");
    if (!options.adaptive.empty()) table.set("adaptive", options.adaptive, "--adaptive");
    if (!options.debug.empty()) table.set("debug", options.debug, "--debug");
    if (const auto photons = int_flag("--photons", options.photons, 1, INT_MAX)) {
        table.set("photons", static_cast<double>(*photons), "--photons");
        table.set("caustic_photons", static_cast<double>(*photons), "--photons");
    }
    if (!options.outputs.empty()) table.set("output", options.outputs, "--output");
    RenderSettings settings = parse_render_settings(&table);
    // Not table values: the seed may exceed what a table's integer holds, threads is no
    // scene setting.
    if (const auto threads = int_flag("--threads", options.threads, 1, kMaxThreads))
        settings.threads = *threads;
    if (!options.seed.empty()) {
        const auto seed = parse_unsigned(options.seed, UINT64_MAX);
        if (!seed) bad_flag("--seed", options.seed, "an integer from 0 to 2^64 - 1");
        settings.seed = *seed;
    }
    if (settings.outputs.empty()) {
        settings.outputs = {std::filesystem::path(options.scene).stem().string() + ".exr"};
    }
    return settings;
}

std::optional<SampleRange> parse_samples_flag(const std::string& text) {
    if (text.empty()) return std::nullopt;
    const size_t colon = text.find(':');
    const char* expected = "A:B, sample indices 0 <= A < B <= 2^31 - 1";
    if (colon == std::string::npos) bad_flag("--samples", text, expected);
    const auto first = parse_unsigned(text.substr(0, colon), INT_MAX);
    const auto end = parse_unsigned(text.substr(colon + 1), INT_MAX);
    if (!first || !end || *first >= *end) bad_flag("--samples", text, expected);
    return SampleRange{static_cast<int>(*first), static_cast<int>(*end)};
}

}  // namespace glint::cli
