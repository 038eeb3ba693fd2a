#include <glint/scene/render_settings.h>

#include <algorithm>

namespace glint {

RenderSettings parse_render_settings(const Params* params) {
    RenderSettings s;
    if (!params) return s;
    const Params& p = *params;
    s.where = p.where();
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
    s.aovs = p.get_bool("aovs", false);
    s.outputs = p.get_strings("output");
    s.csg_shortcuts = p.get_bool("csg_shortcuts", true);
    s.mipmapping = p.get_bool("mipmapping", true);
    s.ambient = p.get_spectrum("ambient", s.ambient);
    s.shadow_samples = p.get_int("shadow_samples", s.shadow_samples);
    s.penumbra_shortcut = p.get_bool("penumbra_shortcut", s.penumbra_shortcut);
    s.caustics = p.get_bool("caustics", s.caustics);
    s.photons = p.get_int("photons", s.photons);
    s.caustic_photons = p.get_int("caustic_photons", s.caustic_photons);
    s.photon_radius = p.get_float("photon_radius", s.photon_radius);
    s.intermediate = p.get_int("intermediate", s.intermediate);
    s.photon_neighbours = p.get_int("photon_neighbours", s.photon_neighbours);
    s.gather_rays = p.get_int("gather_rays", s.gather_rays);
    s.projection_maps = p.get_bool("projection_maps", s.projection_maps);
    s.adaptive = p.get_string("adaptive", s.adaptive);
    s.edge_threshold = p.get_float("edge_threshold", s.edge_threshold);
    s.edge_radius = p.get_int("edge_radius", s.edge_radius);
    s.supersample = p.get_int("supersample", s.supersample);
    s.target_error = p.get_float("target_error", s.target_error);
    s.max_spp = p.get_int("max_spp", s.max_spp);
    s.debug = p.get_strings("debug");
    if (s.width < 1 || s.height < 1 || s.width > 65536 || s.height > 65536) {
        p.fail("'width' and 'height' must be between 1 and 65536");
    }
    if (s.spp < 1) p.fail("'spp' must be at least 1");
    if (s.max_depth < -1) p.fail("'max_depth' must be -1 (unlimited) or at least 0");
    if (p.get_int("seed", 0) < 0) p.fail("'seed' must not be negative");
    if (s.filter_radius < 0.0f) p.fail("'filter_radius' must not be negative");
    if (std::min({s.ambient.r, s.ambient.g, s.ambient.b}) < 0.0f) p.fail("'ambient' must not be negative");
    if (s.shadow_samples < 1 || s.shadow_samples > 64) p.fail("'shadow_samples' must be in [1, 64]");
    if (s.photons < 1 || s.caustic_photons < 0) p.fail("'photons' must be at least 1 and 'caustic_photons' not negative");
    if (s.photon_radius < 0.0f) p.fail("'photon_radius' must not be negative");
    if (s.intermediate < 0) p.fail("'intermediate' must not be negative (0 writes no intermediate images)");
    if (s.photon_neighbours < 1 || s.gather_rays < 0) p.fail("'photon_neighbours' must be at least 1 and 'gather_rays' not negative");
    if (s.edge_radius < 0 || s.edge_radius > 16) p.fail("'edge_radius' must be in [0, 16]");
    if (s.supersample < 1 || s.supersample > 32) p.fail("'supersample' must be in [1, 32]");
    if (!(s.target_error > 0.0f)) p.fail("'target_error' must be positive");
    if (s.max_spp < 0) p.fail("'max_spp' must not be negative");
    if (!(s.edge_threshold > 0.0f)) p.fail("'edge_threshold' must be positive");
    p.check_all_used();
    return s;
}

}  // namespace glint
