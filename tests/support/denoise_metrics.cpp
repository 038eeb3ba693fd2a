#include <glint/core/progress.h>
#include <glint/film/film.h>
#include <glint/integrator/integrator.h>
#include <glint/math/vector.h>
#include <glint/scene/build.h>
#include <glint/scene/lua/lua_loader.h>
#include <support/denoise_metrics.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

namespace glint::test {

Halves render_halves(const std::string& code, int threads) {
    const SceneDesc desc =
        load_scene_string(code, "denoise_test.lua", GLINT_SOURCE_DIR "/examples");
    const RenderSettings settings = parse_render_settings(desc.render ? &*desc.render : nullptr);
    const auto scene = build_scene(desc, settings);
    auto integrator = make_integrator(settings);
    Film film(settings.output_width(), settings.output_height(), true, settings.output_origin(),
              true);
    Progress progress("test", 1, true);
    if (threads > 0) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        integrator->render(*scene, film, progress);
    } else {
        integrator->render(*scene, film, progress);
    }
    return {film.resolve(), film.resolve_half(0), film.resolve_half(1)};
}

float luminance(const Image& image, int x, int y) {
    return 0.2126f * image.at(x, y, 0) + 0.7152f * image.at(x, y, 1) + 0.0722f * image.at(x, y, 2);
}

double error_against(const Image& test, const Halves& ref, const std::vector<uint8_t>* mask) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < test.height; ++y) {
        for (int x = 0; x < test.width; ++x) {
            if (mask && !(*mask)[static_cast<size_t>(y) * test.width + x]) continue;
            ++count;
            for (int c = 0; c < 3; ++c) {
                const double r = ref.full.at(x, y, c), t = test.at(x, y, c);
                const double d = ref.a.at(x, y, c) - ref.b.at(x, y, c);
                sum += ((t - r) * (t - r) - 0.25 * d * d) / (r * r + 1e-2);
            }
        }
    }
    return sum / (3.0 * std::max(count, 1));
}

EdgeBands edge_bands(const Image& ref) {
    const int w = ref.width, h = ref.height;
    const int al = ref.channel_index("albedo.R"), no = ref.channel_index("normal.X"),
              de = ref.channel_index("depth.Z");
    EdgeBands bands{std::vector<uint8_t>(static_cast<size_t>(w) * h, 0),
                    std::vector<uint8_t>(static_cast<size_t>(w) * h, 0)};
    auto vec = [&](int x, int y, int c) {
        return Vec3(ref.at(x, y, c), ref.at(x, y, c + 1), ref.at(x, y, c + 2));
    };
    for (int y = 0; y + 1 < h; ++y) {
        for (int x = 0; x + 1 < w; ++x) {
            for (const Vec2i q : {Vec2i(x + 1, y), Vec2i(x, y + 1)}) {
                const float zp = ref.at(x, y, de), zq = ref.at(q.x, q.y, de);
                const bool geometry = glm::length(vec(x, y, no) - vec(q.x, q.y, no)) > 0.52f ||
                                      std::abs(zp - zq) > 0.1f * std::max(zp, zq);
                const bool texture = glm::length(vec(x, y, al) - vec(q.x, q.y, al)) > 0.15f;
                const size_t i = static_cast<size_t>(y) * w + x,
                             j = static_cast<size_t>(q.y) * w + q.x;
                if (geometry)
                    bands.geometry[i] = bands.geometry[j] = 1;
                else if (texture)
                    bands.texture[i] = bands.texture[j] = 1;
            }
        }
    }
    // A texture edge next to a geometry edge is a geometry edge.
    for (size_t i = 0; i < bands.texture.size(); ++i)
        if (bands.geometry[i]) bands.texture[i] = 0;
    return bands;
}

double edge_contrast(const Image& image, const std::vector<uint8_t>& band) {
    double sum = 0.0;
    int count = 0;
    for (int y = 1; y + 1 < image.height; ++y) {
        for (int x = 1; x + 1 < image.width; ++x) {
            if (!band[static_cast<size_t>(y) * image.width + x]) continue;
            const float l = luminance(image, x, y);
            float step = 0.0f;
            for (const Vec2i q :
                 {Vec2i(x + 1, y), Vec2i(x - 1, y), Vec2i(x, y + 1), Vec2i(x, y - 1)})
                step = std::max(step, std::abs(l - luminance(image, q.x, q.y)));
            sum += step;
            ++count;
        }
    }
    return count > 0 ? sum / count : 0.0;
}

int band_size(const std::vector<uint8_t>& band) {
    int n = 0;
    for (uint8_t b : band) n += b;
    return n;
}

}  // namespace glint::test
