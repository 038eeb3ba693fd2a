#include <glint/scene/render_settings.h>

#include <glint/core/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

RenderSettings parse_render_settings(const Params* params) {
    RenderSettings s;
    if (params) s.params = *params;
    const Params& p = s.params;
    s.width = p.get_int("width", s.width);
    s.height = p.get_int("height", s.height);
    s.spp = p.get_int("spp", s.spp);
    s.seed = static_cast<uint64_t>(p.get_int("seed", 0));
    s.max_depth = p.get_int("max_depth", s.max_depth);
    s.integrator = p.get_string("integrator", s.integrator);
    s.sampler = p.get_string("sampler", s.sampler);
    s.filter = p.get_string("filter", s.filter);
    s.filter_radius = p.get_float("filter_radius", 0.0f);
    s.exposure = p.get_float("exposure", 0.0f);
    const std::string tonemap = p.get_string("tonemap", "clip");
    try {
        s.tonemap = parse_tonemap(tonemap);
    } catch (const Error& e) {
        p.fail_at("tonemap", e.what());
    }
    s.aovs = p.get_bool("aovs", false);
    s.spectral = p.get_bool("spectral", false);
    s.denoise = p.get_bool("denoise", false);
    s.denoiser = p.get_string("denoiser", s.denoiser);
    if (s.denoiser != "network" && s.denoiser != "nlm")
        p.fail_at("denoiser",
                  fmt::format("'denoiser' must be \"network\" or \"nlm\", got \"{}\"", s.denoiser));
    s.denoise_quality = p.get_string("denoise_quality", s.denoise_quality);
    if (s.denoise_quality != "fast" && s.denoise_quality != "balanced" &&
        s.denoise_quality != "high")
        p.fail_at(
            "denoise_quality",
            fmt::format("'denoise_quality' must be \"fast\", \"balanced\" or \"high\", got \"{}\"",
                        s.denoise_quality));
    s.denoise_clean_aux = p.get_bool("denoise_clean_aux", false);
    s.outputs = p.get_strings("output");
    s.csg_shortcuts = p.get_bool("csg_shortcuts", true);
    s.mipmapping = p.get_bool("mipmapping", true);
    s.light_sampler = p.get_string("light_sampler", s.light_sampler);
    if (s.light_sampler != "tree" && s.light_sampler != "power")
        p.fail_at("light_sampler",
                  fmt::format("'light_sampler' must be \"tree\" or \"power\", got \"{}\"",
                              s.light_sampler));
    s.adaptive = p.get_string("adaptive", s.adaptive);
    s.edge_threshold = p.get_float("edge_threshold", s.edge_threshold);
    s.edge_radius = p.get_int("edge_radius", s.edge_radius);
    s.supersample = p.get_int("supersample", s.supersample);
    s.target_error = p.get_float("target_error", s.target_error);
    s.max_spp = p.get_int("max_spp", s.max_spp);
    s.debug = p.get_strings("debug");
    if (s.width < 1 || s.height < 1 || s.width > 65536 || s.height > 65536) {
        p.fail_at(s.width < 1 || s.width > 65536 ? "width" : "height",
                  "'width' and 'height' must be between 1 and 65536");
    }
    if (s.spp < 1) p.fail_at("spp", "'spp' must be at least 1");
    if (s.max_depth < -1 || s.max_depth > kMaxPathDepth) {
        p.fail_at("max_depth",
                  fmt::format("'max_depth' must be -1 (until Russian roulette ends the path, at "
                              "most {0} bounces) or in [0, {0}], got {1}",
                              kMaxPathDepth, s.max_depth));
    }
    if (p.get_int("seed", 0) < 0) p.fail_at("seed", "'seed' must not be negative");
    // 2^100 is still a finite float scale (any radiance is then white or black already).
    if (!(std::abs(s.exposure) <= 100.0f))  // as the --exposure flag
        p.fail_at("exposure", "'exposure' must be in [-100, 100] stops");
    if (s.filter_radius < 0.0f) p.fail_at("filter_radius", "'filter_radius' must not be negative");
    if (s.edge_radius < 0 || s.edge_radius > 16)
        p.fail_at("edge_radius", "'edge_radius' must be in [0, 16]");
    if (s.supersample < 1 || s.supersample > 32)
        p.fail_at("supersample", "'supersample' must be in [1, 32]");
    if (!(s.target_error > 0.0f)) p.fail_at("target_error", "'target_error' must be positive");
    if (s.max_spp < 0) p.fail_at("max_spp", "'max_spp' must not be negative");
    if (!(s.edge_threshold > 0.0f))
        p.fail_at("edge_threshold", "'edge_threshold' must be positive");
    if (p.has("crop")) {
        const std::vector<double> c = p.get_numbers("crop");
        const std::string expected = fmt::format(
            "'crop' must be four whole numbers {{x0, y0, x1, y1}} with 0 <= x0 < x1 <= {} "
            "(width) and 0 <= y0 < y1 <= {} (height)",
            s.width, s.height);
        if (c.size() != 4) p.fail_at("crop", fmt::format("{}; got {} numbers", expected, c.size()));
        for (double v : c) {
            if (v != std::floor(v) || v < 0.0 || v > 65536.0) p.fail_at("crop", expected);
        }
        for (int k = 0; k < 4; ++k) s.crop[k] = static_cast<int>(c[k]);
        if (s.crop[0] >= s.crop[2] || s.crop[1] >= s.crop[3] || s.crop[2] > s.width ||
            s.crop[3] > s.height) {
            p.fail_at("crop", fmt::format("{}; got {{{}, {}, {}, {}}}", expected, s.crop[0],
                                          s.crop[1], s.crop[2], s.crop[3]));
        }
    }
    return s;
}

}  // namespace glint
