#include <glint/scene/render_settings.h>

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
    if (s.width < 1 || s.height < 1 || s.width > 65536 || s.height > 65536) {
        p.fail("'width' and 'height' must be between 1 and 65536");
    }
    if (s.spp < 1) p.fail("'spp' must be at least 1");
    if (s.max_depth < -1) p.fail("'max_depth' must be -1 (unlimited) or at least 0");
    if (p.get_int("seed", 0) < 0) p.fail("'seed' must not be negative");
    if (s.filter_radius < 0.0f) p.fail("'filter_radius' must not be negative");
    p.check_all_used();
    return s;
}

}  // namespace glint
