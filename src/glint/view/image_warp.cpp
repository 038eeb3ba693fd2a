#include <glint/camera/camera.h>
#include <glint/core/error.h>
#include <glint/view/image_warp.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace glint {
namespace {

// As reprojection.cpp: escaped rays become points this far along the ray.
constexpr float kFarAway = 1e6f;

struct Vertex {
    bool valid = false;
    Vec2 film;        // in the new view
    float depth = 0;  // distance from the new camera
    float source_depth = 0;
    Rgb colour;
};

float edge(const Vec2& a, const Vec2& b, const Vec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

class Rasteriser {
public:
    Rasteriser(int width, int height, const WarpSettings& settings)
        : m_width(width),
          m_height(height),
          m_settings(settings),
          m_depth(static_cast<std::size_t>(width) * height, std::numeric_limits<float>::infinity()),
          m_colour(m_depth.size(), settings.hole_colour),
          m_point(m_depth.size(), 0) {}

    void triangle(const Vertex& a, const Vertex& b, const Vertex& c) {
        if (!a.valid || !b.valid || !c.valid) return;
        const float near = std::min({a.source_depth, b.source_depth, c.source_depth});
        const float far = std::max({a.source_depth, b.source_depth, c.source_depth});
        if (far > near * (1.0f + m_settings.depth_discontinuity)) return;
        const float min_x = std::min({a.film.x, b.film.x, c.film.x});
        const float max_x = std::max({a.film.x, b.film.x, c.film.x});
        const float min_y = std::min({a.film.y, b.film.y, c.film.y});
        const float max_y = std::max({a.film.y, b.film.y, c.film.y});
        if (max_x - min_x > m_settings.max_triangle_pixels ||
            max_y - min_y > m_settings.max_triangle_pixels)
            return;
        const float area = edge(a.film, b.film, c.film);
        if (area == 0.0f) return;
        // Pixel centres (x + 1/2, y + 1/2) inside the triangle, its edges included.
        const int x0 = std::max(0, static_cast<int>(std::ceil(min_x - 0.5f)));
        const int x1 = std::min(m_width - 1, static_cast<int>(std::floor(max_x - 0.5f)));
        const int y0 = std::max(0, static_cast<int>(std::ceil(min_y - 0.5f)));
        const int y1 = std::min(m_height - 1, static_cast<int>(std::floor(max_y - 0.5f)));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const Vec2 p(x + 0.5f, y + 0.5f);
                const float wa = edge(b.film, c.film, p) / area;
                const float wb = edge(c.film, a.film, p) / area;
                const float wc = 1.0f - wa - wb;
                constexpr float kTolerance = -1e-5f;
                if (wa < kTolerance || wb < kTolerance || wc < kTolerance) continue;
                const float depth = wa * a.depth + wb * b.depth + wc * c.depth;
                const std::size_t i = static_cast<std::size_t>(y) * m_width + x;
                if (!(depth < m_depth[i])) continue;
                m_depth[i] = depth;
                m_colour[i] = a.colour * wa + b.colour * wb + c.colour * wc;
            }
        }
    }

    // A vertex on its own into the pixel it lands in, where no triangle is (the nearest
    // point wins): fills the pixels along an edge, whose depth, a blend of both sides, joins
    // no triangle.
    void point(const Vertex& v) {
        if (!v.valid) return;
        const int x = static_cast<int>(std::floor(v.film.x));
        const int y = static_cast<int>(std::floor(v.film.y));
        if (x < 0 || y < 0 || x >= m_width || y >= m_height) return;
        const std::size_t i = static_cast<std::size_t>(y) * m_width + x;
        const bool free = std::isinf(m_depth[i]) || (m_point[i] && v.depth < m_depth[i]);
        if (!free) return;
        m_depth[i] = v.depth;
        m_colour[i] = v.colour;
        m_point[i] = 1;
    }

    WarpResult result() const {
        WarpResult r;
        r.image = make_image(m_width, m_height, {"R", "G", "B"});
        r.hole.assign(m_depth.size(), 0);
        for (std::size_t i = 0; i < m_depth.size(); ++i) {
            r.hole[i] = std::isinf(m_depth[i]) ? 1 : 0;
            r.holes += r.hole[i];
            for (int c = 0; c < 3; ++c) r.image.pixels[3 * i + c] = m_colour[i][c];
        }
        return r;
    }

private:
    int m_width, m_height;
    const WarpSettings& m_settings;
    std::vector<float> m_depth;
    std::vector<Rgb> m_colour;
    std::vector<uint8_t> m_point;  // 1 where a point, not a triangle, drew the pixel
};

}  // namespace

WarpResult warp_image(const Image& source, const Camera& source_camera, const Camera& target_camera,
                      int width, int height, const WarpSettings& settings) {
    const int r = source.channel_index("R"), g = source.channel_index("G");
    const int b = source.channel_index("B"), z = source.channel_index("depth.Z");
    if (r < 0 || g < 0 || b < 0 || z < 0)
        throw Error("warping an image needs its R, G, B and depth.Z channels");
    std::vector<Vertex> vertices(static_cast<std::size_t>(source.width) * source.height);
    for (int y = 0; y < source.height; ++y) {
        for (int x = 0; x < source.width; ++x) {
            Vertex& v = vertices[static_cast<std::size_t>(y) * source.width + x];
            const float depth = source.at(x, y, z);
            if (std::isnan(depth) || depth < 0.0f) continue;
            const Ray ray = source_camera.generate_ray(Vec2(x + 0.5f, y + 0.5f), Vec2(0.5f));
            // Integrators write 0 (or infinity) where the ray escaped.
            const bool escaped = depth == 0.0f || std::isinf(depth);
            v.source_depth = escaped ? kFarAway : depth;
            const std::optional<FilmProjection> projected =
                target_camera.project(ray.origin + v.source_depth * ray.direction);
            if (!projected) continue;
            v.valid = true;
            v.film = projected->film;
            v.depth = projected->depth;
            v.colour = Rgb(source.at(x, y, r), source.at(x, y, g), source.at(x, y, b));
        }
    }
    Rasteriser raster(width, height, settings);
    auto vertex = [&](int x, int y) -> const Vertex& {
        return vertices[static_cast<std::size_t>(y) * source.width + x];
    };
    for (int y = 0; y + 1 < source.height; ++y) {
        for (int x = 0; x + 1 < source.width; ++x) {
            raster.triangle(vertex(x, y), vertex(x + 1, y), vertex(x, y + 1));
            raster.triangle(vertex(x + 1, y), vertex(x + 1, y + 1), vertex(x, y + 1));
        }
    }
    for (const Vertex& v : vertices) raster.point(v);
    return raster.result();
}

}  // namespace glint
