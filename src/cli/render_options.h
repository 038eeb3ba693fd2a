#pragma once
// The render flags, shared by `glint render` and `glint view`, and the settings they make.
#include <glint/render/render_job.h>
#include <glint/scene/render_settings.h>
#include <glint/scene/scene_desc.h>

#include <optional>
#include <string>
#include <vector>

namespace glint::cli {

/// Numeric flags are taken as text and parsed strictly (flags.h).
struct RenderOptions {
    std::string scene;
    std::vector<std::string> outputs;
    std::string spp;
    std::string resolution;
    std::string threads;
    std::string seed;
    std::string crop;
    std::string integrator;
    std::string exposure;
    std::string tonemap;
    bool denoise = false;
    std::string denoiser;  // --denoise's value: "network" (the default) or "nlm"
    std::string denoise_quality;
    std::string adaptive;
    std::string photons;
    std::string samples;  // --samples A:B, a partial render
    bool no_mipmap = false;
    std::string intermediate;
    std::vector<std::string> debug;
    bool aovs = false;
    bool spectral = false;
    bool quiet = false;
    bool trusted_scene = false;
    std::string script_time_limit;
};

/// The scene's settings with the flags' values written into its glint.render{...} table,
/// each with the flag's name as its location, so that an error about a value names the
/// flag that gave it and anything else names the scene's line.
RenderSettings settings_for(const SceneDesc& desc, const RenderOptions& options);

/// --samples A:B as a sample range (checked against spp by the render); nothing when the
/// flag was not given.
std::optional<SampleRange> parse_samples_flag(const std::string& text);

}  // namespace glint::cli
